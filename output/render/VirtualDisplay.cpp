#include "render/VirtualDisplay.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

namespace chute::render {

namespace {
// The Xvfb this process started, for the signal handlers below (a lock-free atomic is safe to
// read in a handler).
std::atomic<pid_t> gServer{-1};
static_assert(std::atomic<pid_t>::is_always_lock_free);

// SIGINT / SIGTERM / SIGHUP while rendering: the server is our child and would outlive us (a
// SIGTERM sent to chute alone, by `timeout` or a batch system, does not reach it). Stop it, then
// die of the signal as before. Only kill(), signal() and raise(): async-signal-safe.
void stopServerAndDie(int sig) {
  const pid_t pid = gServer.load();
  if (pid > 0) ::kill(pid, SIGTERM);
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

// Handlers only where the program has none of its own (`chute run` installs its own).
void stopServerOnSignals() {
  for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler != SIG_DFL) continue;
    struct sigaction sa {};
    sa.sa_handler = stopServerAndDie;
    ::sigemptyset(&sa.sa_mask);
    ::sigaction(sig, &sa, nullptr);
  }
}
}  // namespace

// Starts Xvfb on display `wanted`; its number once it is ready ("" if it could not start: the
// number taken, no Xvfb). The server's pid in pid_.
std::string VirtualDisplay::startServer(int wanted) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error("cannot start Xvfb: pipe failed");
  const pid_t parent = ::getpid();
  char display[16];  // ":N" (snprintf: gcc 12 warns falsely on ":" + std::to_string)
  std::snprintf(display, sizeof display, ":%d", wanted);
  pid_ = ::fork();
  if (pid_ < 0) throw std::runtime_error("cannot start Xvfb: fork failed");
  if (pid_ == 0) {
    // The server ends with chute whatever ends chute: a crash, an abort, SIGKILL (no handler
    // runs then). A parent already gone before this line leaves no one to signal it: stop.
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != parent) ::_exit(0);
    ::dup2(fds[1], 3);  // dup2 clears close-on-exec on the copy
    const int devnull = ::open("/dev/null", O_RDWR);
    if (devnull >= 0) ::dup2(devnull, 1), ::dup2(devnull, 2);
    ::execlp("Xvfb", "Xvfb", display, "-displayfd", "3", "-screen", "0", "3840x2160x24",
             "-nolisten", "tcp", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(fds[1]);
  gServer.store(pid_);
  stopServerOnSignals();
  std::string number;
  pollfd p{fds[0], POLLIN, 0};
  char buf[32];
  while (number.find('\n') == std::string::npos) {
    if (::poll(&p, 1, 20000) <= 0) break;  // Xvfb starts in well under a second
    const ssize_t n = ::read(fds[0], buf, sizeof buf);
    if (n <= 0) break;
    number.append(buf, static_cast<size_t>(n));
  }
  ::close(fds[0]);
  while (!number.empty() && (number.back() == '\n' || number.back() == ' ')) number.pop_back();
  if (number.empty()) {
    ::kill(pid_, SIGTERM);
    ::waitpid(pid_, nullptr, 0);
    gServer.store(-1);
    pid_ = -1;
  }
  return number;
}

VirtualDisplay::VirtualDisplay() {
  if (const char* d = std::getenv("DISPLAY"); d && *d) {
    display_ = d;
    return;
  }
  // A display number of our own, away from the low numbers: Xvfb's -displayfd alone takes the
  // lowest free one, and a server that is just exiting removes the socket of its number after
  // giving up its lock, so a server started then on the same number lost its socket and clients
  // failed with "bad X server connection" (seen in CI, with other renders starting and stopping
  // servers). A number taken makes Xvfb exit at once: the next is tried.
  std::string number;
  for (int attempt = 0; attempt < 8 && number.empty(); ++attempt) {
    const int wanted = 100 + static_cast<int>((::getpid() * 7919L + attempt * 131L) % 800);
    number = startServer(wanted);
  }
  if (number.empty()) {
    throw std::runtime_error(
        "no DISPLAY and Xvfb could not be started (install the Debian package xvfb)");
  }
  display_ = ":" + number;
  ::setenv("DISPLAY", display_.c_str(), 1);
}

VirtualDisplay::~VirtualDisplay() {
  if (pid_ <= 0) return;
  gServer.store(-1);
  ::kill(pid_, SIGTERM);
  ::waitpid(pid_, nullptr, 0);
  ::unsetenv("DISPLAY");
}

}  // namespace chute::render
