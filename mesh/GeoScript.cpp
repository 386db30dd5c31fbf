#include "GeoScript.hpp"

#include <gmsh.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "GmshSession.hpp"
#include "MeshError.hpp"
#include "MshReader.hpp"
#include "io/InputFile.hpp"

namespace chute::mesh {

namespace {

// The address space this process has mapped now (VmSize of /proc/self/status), 0 if unknown.
rlim_t mappedBytes() {
  std::FILE* f = std::fopen("/proc/self/status", "r");
  if (!f) return 0;
  char line[256];
  unsigned long long kiB = 0;
  while (std::fgets(line, sizeof line, f))
    if (std::sscanf(line, "VmSize: %llu kB", &kiB) == 1) break;
  std::fclose(f);
  return static_cast<rlim_t>(kiB) * 1024;
}

// The child: gmsh runs the script and writes the mesh; a failure is one line written to `report`
// (at most 1000 bytes: the pipe never fills) and the exit status 2. Never returns.
[[noreturn]] void runChild(const std::string& geo, const std::string& tmp, double memoryMiB,
                           int report) {
  setpgid(0, 0);  // its own process group: commands the script starts die with it
  // The limit is on what the script adds to the address space chute already has mapped (its
  // libraries; in a sanitizer build, the shadow memory reserved at start, terabytes that an
  // absolute limit would not even cover).
  const rlim_t bytes = mappedBytes() + static_cast<rlim_t>(memoryMiB * 1024.0 * 1024.0);
  const struct rlimit rl { bytes, bytes };
  setrlimit(RLIMIT_AS, &rl);
  int status = 0;
  std::string message;
  try {
    GmshScope scope;
    callGmsh(geo, [&] {
      gmsh::open(geo);
      gmsh::model::mesh::generate(gmsh::model::getDimension());
      // After the script: it cannot choose a format chute does not read.
      gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
      gmsh::option::setNumber("Mesh.Binary", 0);
      gmsh::write(tmp);
    });
  } catch (const std::exception& e) {
    message = e.what();
    status = 2;
  } catch (...) {
    message = geo + ": gmsh failed";
    status = 2;
  }
  message = message.substr(0, std::min(message.find('\n'), std::size_t{1000}));
  if (!message.empty() && ::write(report, message.data(), message.size()) < 0) status = 3;
  _exit(status);  // no atexit handlers of the parent's state in the child
}

}  // namespace

GmshMesh meshGeoScript(const std::string& geo, const std::string& out,
                       const GeoScriptLimits& limits) {
  if (const auto problem = io::inputFileProblem(geo, 64ull << 20))
    throw MeshError(geo + ": " + *problem);
  if (std::filesystem::path(out).extension() != ".msh")
    throw MeshError(out + ": --out must name a .msh file");
  const std::string tmp = out + ".part" + std::to_string(getpid()) + ".msh";
  int report[2];
  if (pipe(report) != 0) throw MeshError(geo + ": cannot start gmsh (pipe failed)");
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) {
    close(report[0]);
    close(report[1]);
    throw MeshError(geo + ": cannot start gmsh (fork failed)");
  }
  if (pid == 0) {
    close(report[0]);
    runChild(geo, tmp, limits.memoryMiB, report[1]);
  }
  close(report[1]);
  setpgid(pid, pid);

  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(limits.seconds);
  int status = 0;
  bool timedOut = false;
  for (;;) {
    const pid_t r = waitpid(pid, &status, WNOHANG);
    if (r == pid) break;
    if (r < 0 && errno != EINTR) break;
    if (std::chrono::steady_clock::now() > deadline) {
      kill(-pid, SIGKILL);
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      timedOut = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  kill(-pid, SIGKILL);  // whatever the script left running
  std::string childMessage(1000, '\0');
  const ssize_t got = timedOut ? 0 : ::read(report[0], childMessage.data(), childMessage.size());
  childMessage.resize(got > 0 ? static_cast<std::size_t>(got) : 0);
  close(report[0]);
  auto discard = [&] {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
  };
  if (timedOut) {
    discard();
    throw MeshError(geo + ": the gmsh script did not finish within " +
                    std::to_string(static_cast<long>(limits.seconds)) + " s (--timeout)");
  }
  if (WIFSIGNALED(status)) {
    discard();
    throw MeshError(geo + ": gmsh died of signal " + std::to_string(WTERMSIG(status)) +
                    (WTERMSIG(status) == SIGSEGV || WTERMSIG(status) == SIGABRT
                         ? " (or ran out of its memory limit, --max-memory)"
                         : ""));
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    discard();
    throw MeshError(childMessage.empty() ? geo + ": the gmsh script failed" : childMessage);
  }
  GmshMesh mesh;
  try {
    mesh = readMsh(tmp);
  } catch (const MeshError& e) {
    discard();
    throw MeshError(geo + ": the mesh gmsh wrote cannot be read: " + e.what());
  }
  std::error_code ec;
  std::filesystem::rename(tmp, out, ec);
  if (ec) {
    discard();
    throw MeshError(out + ": cannot write: " + ec.message());
  }
  return mesh;
}

}  // namespace chute::mesh
