// The output a run leaves is never torn or mixed, whatever happens to the disk or who else writes:
// a failed write (a full disk, /dev/full here) ends the run with status 5 and one line saying
// how far the output is whole; a second run into a directory in use is refused; a restart with
// other solver settings is refused, not silently run with the checkpoint's; a forged or damaged
// checkpoint is refused before anything in the output directory changes.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/TempDir.hpp"

namespace fs = std::filesystem;

namespace {
const std::string kChute = CHUTE_BINARY;

struct Outcome {
  int status = -1;
  std::string err;
};

Outcome runChute(const std::string& args) {
  // One file per test process: ctest runs these tests in parallel.
  const fs::path err = fs::temp_directory_path() /
                       ("chute_output_integrity_stderr_" + std::to_string(::getpid()) + ".txt");
  const std::string cmd = kChute + " " + args + " > /dev/null 2> " + err.string();
  const int raw = std::system(cmd.c_str());
  Outcome o;
  o.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  std::ifstream in(err);
  std::stringstream s;
  s << in.rdbuf();
  o.err = s.str();
  return o;
}

int lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

std::string bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

const std::string kBead = CHUTE_SOURCE_DIR "/cases/bead_5.toml";
}  // namespace

TEST(OutputIntegrity, AFullDiskEndsTheRunWithStatus5AndSaysWhatIsWhole) {
  // probes.csv is a link to /dev/full: every write fails with ENOSPC, as on a full disk.
  const fs::path dir = chute::testing::freshTempDir("chute_test_integrity_", "full");
  fs::create_directories(dir);
  fs::create_symlink("/dev/full", dir / "probes.csv");
  const auto o = runChute("run " + kBead + " --quiet --out " + dir.string());
  std::printf("full disk: status %d, stderr: %s", o.status, o.err.c_str());
  EXPECT_EQ(o.status, 5);
  EXPECT_EQ(lines(o.err), 1);
  EXPECT_NE(o.err.find("disk full"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "summary.json")) << "no summary claims a result";
}

TEST(OutputIntegrity, ASecondRunIntoADirectoryInUseIsRefused) {
  const fs::path dir = chute::testing::freshTempDir("chute_test_integrity_", "lock");
  // A long run holds the directory while a second one tries it.
  const std::string bg = kChute + " run " + kBead + " --quiet --out " + dir.string() +
                         " --set solver.t_end=4000 > /dev/null 2>&1 & echo $! > " +
                         (dir.parent_path() / "lock_pid").string();
  ASSERT_EQ(std::system(bg.c_str()), 0);
  for (int i = 0; i < 1500 && !fs::exists(dir / "probes.csv"); ++i) ::usleep(20000);
  const auto o = runChute("run " + kBead + " --quiet --out " + dir.string());
  std::system(("kill $(cat " + (dir.parent_path() / "lock_pid").string() + ")").c_str());
  std::printf("second run: status %d, stderr: %s", o.status, o.err.c_str());
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(lines(o.err), 1);
  EXPECT_NE(o.err.find("another chute run"), std::string::npos);
}

TEST(OutputIntegrity, ARestartWithOtherSolverSettingsOrABadCheckpointChangesNothing) {
  const fs::path dir = chute::testing::freshTempDir("chute_test_integrity_", "restart");
  ASSERT_EQ(runChute("run " + kBead + " --quiet --out " + dir.string() + " --checkpoint-every 300")
                .status,
            0);
  const std::string probes = bytes(dir / "probes.csv");
  const std::string ckpt = (dir / "checkpoint.cbor").string();
  const auto other = runChute("run " + kBead + " --quiet --out " + dir.string() + " --restart " +
                              ckpt + " --set solver.dt=1e-3");
  std::printf("restart with another dt: status %d, stderr: %s", other.status, other.err.c_str());
  EXPECT_EQ(other.status, 2);
  EXPECT_EQ(lines(other.err), 1);
  EXPECT_NE(other.err.find("solver.dt"), std::string::npos);
  EXPECT_EQ(bytes(dir / "probes.csv"), probes) << "the refused restart cut the output";

  // Every single-byte change of the checkpoint file is refused (the checksum), output untouched.
  const std::string good = bytes(ckpt);
  int refused = 0, tried = 0;
  for (size_t at = 7; at < good.size(); at += good.size() / 23) {
    std::string bad = good;
    bad[at] = static_cast<char>(bad[at] ^ 0x10);
    std::ofstream(ckpt, std::ios::binary) << bad;
    const auto o =
        runChute("run " + kBead + " --quiet --out " + dir.string() + " --restart " + ckpt);
    ++tried;
    refused += o.status == 2 && lines(o.err) == 1;
    EXPECT_EQ(bytes(dir / "probes.csv"), probes) << "byte " << at;
  }
  std::printf(
      "checkpoint with one byte changed: %d of %d refused with one line, output unchanged\n",
      refused, tried);
  EXPECT_EQ(refused, tried);
}

// A checkpoint nested hundreds of thousands of levels deep (the outer document, or a payload
// whose checksum is right) is refused with one line before the recursive CBOR reader would
// overflow the stack on it.
TEST(OutputIntegrity, ADeeplyNestedCheckpointIsRefusedNotACrash) {
  const fs::path dir = chute::testing::freshTempDir("chute_test_integrity_", "nested");
  ASSERT_EQ(runChute("run " + kBead + " --quiet --out " + dir.string() + " --checkpoint-every 300")
                .status,
            0);
  const std::string probes = bytes(dir / "probes.csv");
  const std::string ckpt = (dir / "nested.cbor").string();
  const std::string deep = std::string(400000, '\x81') + '\x00';  // [[[...[0]...]]]
  // The outer document {format: 2, payload: <deep>, checksum: FNV-1a(deep)}, CBOR by hand.
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : deep) h = (h ^ c) * 1099511628211ull;
  std::string forged = "\xa3";
  forged +=
      "\x66"
      "format"
      "\x02";
  forged +=
      "\x67"
      "payload"
      "\x5a";  // byte string, 4-byte length
  for (int s = 24; s >= 0; s -= 8) forged += static_cast<char>((deep.size() >> s) & 0xff);
  forged += deep;
  forged +=
      "\x68"
      "checksum"
      "\x1b";
  for (int s = 56; s >= 0; s -= 8) forged += static_cast<char>((h >> s) & 0xff);
  for (const auto& [what, content] :
       {std::pair<std::string, std::string>{"outer document", deep}, {"payload", forged}}) {
    std::ofstream(ckpt, std::ios::binary) << content;
    const auto o =
        runChute("run " + kBead + " --quiet --out " + dir.string() + " --restart " + ckpt);
    std::printf("%s nested 400000 deep: status %d, stderr: %s", what.c_str(), o.status,
                o.err.c_str());
    EXPECT_EQ(o.status, 2) << what;
    EXPECT_EQ(lines(o.err), 1) << what;
    EXPECT_NE(o.err.find("nested more than"), std::string::npos) << what;
    EXPECT_EQ(bytes(dir / "probes.csv"), probes) << what;
  }
}
