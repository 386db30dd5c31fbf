#pragma once
// The `chute` executable run as a user runs it (bash, arguments as typed): its exit status and
// what it wrote on stderr. For tests of the command line's promises (one line, exit codes).
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace chute::testing {

struct Outcome {
  int status = -1;
  std::string err;
};

// `prefix` goes before the command inside the shell (e.g. "ulimit -f 64; ").
inline Outcome runChute(const std::string& chute, const std::string& args,
                        const std::string& prefix = "") {
  // One file per test process: ctest runs tests in parallel.
  const std::filesystem::path err = std::filesystem::temp_directory_path() /
                                    ("chute_test_stderr_" + std::to_string(::getpid()) + ".txt");
  const std::string cmd = prefix + chute + " " + args + " > /dev/null 2> " + err.string();
  std::string quoted;  // cmd inside bash -c '...'
  for (char c : cmd) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  const int raw = std::system(("bash -c '" + quoted + "'").c_str());
  Outcome o;
  o.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  std::ifstream in(err);
  std::stringstream s;
  s << in.rdbuf();
  o.err = s.str();
  return o;
}

inline int lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

inline std::string bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace chute::testing
