// The output a run leaves is never torn or mixed, whatever happens to the disk or who else writes:
// a failed write (a full disk, /dev/full here) ends the run with status 5 and one line saying
// how far the output is whole; a second run into a directory in use is refused; a restart with
// other solver settings is refused, not silently run with the checkpoint's; a forged or damaged
// checkpoint is refused before anything in the output directory changes.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "VtuSeries.hpp"
#include "support/RunChute.hpp"
#include "support/TempDir.hpp"

namespace fs = std::filesystem;

namespace {
const std::string kChute = CHUTE_BINARY;

using chute::testing::bytes;
using chute::testing::lines;
using chute::testing::Outcome;

Outcome runChute(const std::string& args, const std::string& prefix = "") {
  return chute::testing::runChute(kChute, args, prefix);
}

const std::string kBead = CHUTE_SOURCE_DIR "/cases/bead_5.toml";
}  // namespace

namespace {

// What a run that ended with a failed write (status 5) must leave, read from the files
// themselves: one stderr line saying what is whole; probes.csv of whole rows, as many as the
// message says, the last at the time it says; a .pvd that parses and lists only frames that are
// whole (each reads back with VTK's reader) and no frame file it does not list; no summary.json.
// Returns a description for the test's printout.
std::string checkWholeAfterAFailedWrite(const fs::path& dir, const std::string& name,
                                        const Outcome& o) {
  EXPECT_EQ(o.status, 5) << o.err;
  EXPECT_EQ(lines(o.err), 1) << o.err;
  EXPECT_EQ(o.err.rfind("chute: run: ", 0), 0u) << o.err;
  EXPECT_FALSE(fs::exists(dir / "summary.json")) << "no summary claims a result";
  std::string seen;
  // probes.csv: whole rows only, as the message says.
  if (fs::exists(dir / "probes.csv")) {
    const std::string csv = bytes(dir / "probes.csv");
    EXPECT_TRUE(csv.empty() || csv.back() == '\n') << "a row cut mid-number was left";
    std::istringstream in(csv);
    std::string line;
    std::getline(in, line);
    const size_t columns = static_cast<size_t>(std::count(line.begin(), line.end(), ',')) + 1;
    long rows = 0;
    double last = 0.0;
    while (std::getline(in, line)) {
      ++rows;
      EXPECT_EQ(static_cast<size_t>(std::count(line.begin(), line.end(), ',')) + 1, columns)
          << "row " << rows;
      last = std::stod(line.substr(0, line.find(',')));
    }
    const auto at = o.err.find("probes.csv is whole up to t = ");
    if (rows > 0) {
      EXPECT_NE(at, std::string::npos) << o.err;
      if (at != std::string::npos) {
        double t = 0.0;
        long n = 0;
        std::sscanf(o.err.c_str() + at, "probes.csv is whole up to t = %lf (%ld row", &t, &n);
        EXPECT_EQ(n, rows) << o.err;
        EXPECT_NEAR(t, last, 1e-8 * (1.0 + std::abs(last))) << o.err;
      }
    }
    seen += std::to_string(rows) + " whole rows";
  }
  // The series: every listed frame whole, no frame file unlisted.
  const fs::path pvd = dir / (name + ".pvd");
  if (fs::exists(pvd)) {
    std::vector<chute::PvdEntry> frames;
    EXPECT_NO_THROW(frames = chute::readPvd(pvd.string())) << "a torn .pvd";
    std::set<std::string> listed;
    for (const auto& f : frames) {
      listed.insert(f.file);
      vtkNew<vtkXMLUnstructuredGridReader> reader;
      reader->SetFileName((dir / f.file).string().c_str());
      reader->Update();
      EXPECT_EQ(reader->GetErrorCode(), 0UL) << f.file << " is listed but not whole";
      EXPECT_GT(reader->GetOutput()->GetNumberOfPoints(), 0) << f.file;
    }
    for (const auto& e : fs::directory_iterator(dir)) {
      if (e.path().extension() == ".vtu") {
        EXPECT_TRUE(listed.count(e.path().filename().string()))
            << e.path().filename() << " left on disk but not in the .pvd";
      }
    }
    const auto at = o.err.find(name + ".pvd lists ");
    if (!frames.empty() && at != std::string::npos) {
      long n = 0;
      std::sscanf(o.err.c_str() + at + name.size() + 11, "%ld", &n);
      EXPECT_EQ(n, static_cast<long>(frames.size())) << o.err;
    }
    seen += ", " + std::to_string(frames.size()) + " whole frames";
  }
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_NE(e.path().extension(), ".tmp") << e.path() << ": a temporary file left behind";
  return seen;
}

// `chute run` under a file size limit (bash's ulimit -f, KiB): a write past it fails with EFBIG,
// as on a full disk, whichever file it is.
Outcome runWithFileLimit(int kib, const std::string& args) {
  return runChute("run " + args + " --quiet", "ulimit -f " + std::to_string(kib) + "; ");
}

}  // namespace

// A full disk whatever the file: probes.csv, a .vtu frame, the .pvd, the checkpoint, the summary.
// Each limit makes that write the first to fail (sizes measured: a bead_5 row ~150 bytes, an
// airbag frame 30-50 KiB and checkpoint 34 KiB, a summary ~1.8 KiB).
TEST(OutputIntegrity, AFullDiskEndsTheRunWithStatus5AndSaysWhatIsWhole) {
  const std::string airbag = CHUTE_SOURCE_DIR "/cases/airbag.toml";
  struct Trial {
    const char* what;
    int kib;
    std::string args, name, failing;
  };
  const std::vector<Trial> trials = {
      {"probes.csv", 16, kBead, "bead_5", "probes.csv"},
      // Frames still queued for the background writer when the row fails: the message names
      // the frames the .pvd holds once they are written, not those listed at the failure.
      {"probes.csv, frames queued", 16,
       kBead + " --set output.vtu.write=true --set output.vtu.every=4", "bead_5", "probes.csv"},
      {"a .vtu frame", 40, airbag + " --set output.vtu.write=true", "airbag", "airbag_000001.vtu"},
      {"the .pvd", 8,
       kBead + " --set output.vtu.write=true --set output.vtu.every=1 --set output.interval=0.5",
       "bead_5", "bead_5.pvd"},
      {"the checkpoint", 20, airbag + " --set output.vtu.write=false --checkpoint-every 2",
       "airbag", "checkpoint.cbor"},
      {"summary.json", 1, CHUTE_SOURCE_DIR "/cases/bead_1.toml --set solver.t_end=0.01", "bead_1",
       "summary.json"}};
  for (const auto& t : trials) {
    const fs::path dir = chute::testing::freshTempDir("chute_test_integrity_full_", t.name);
    const auto o = runWithFileLimit(t.kib, t.args + " --out " + dir.string());
    std::printf("full disk at %s: status %d, stderr: %s", t.what, o.status, o.err.c_str());
    EXPECT_NE(o.err.find(t.failing), std::string::npos) << t.what << ": " << o.err;
    EXPECT_NE(o.err.find("disk full"), std::string::npos) << t.what;
    const std::string whole = checkWholeAfterAFailedWrite(dir, t.name, o);
    std::printf("  left: %s\n", whole.c_str());
    if (t.failing == "checkpoint.cbor") {
      EXPECT_FALSE(fs::exists(dir / "checkpoint.cbor")) << "a checkpoint that is not whole";
    }
  }
}

// A real full disk (ENOSPC), where the machine lets the test mount a small tmpfs (root): the run
// fills it with frames and rows, and whatever write fails first, the output is whole.
TEST(OutputIntegrity, ARealFullDiskLeavesWholeOutput) {
  const fs::path dir = chute::testing::freshTempDir("chute_test_integrity_", "tmpfs", true);
  if (std::system(("mount -t tmpfs -o size=160k tmpfs " + dir.string() + " 2>/dev/null").c_str()) !=
      0)
    GTEST_SKIP() << "cannot mount a tmpfs here (not root): the file size limit test covers it";
  const auto o = runChute("run " + kBead + " --quiet --set output.vtu.write=true " +
                          "--set output.vtu.every=4 --out " + (dir / "out").string());
  std::printf("tmpfs of 160 KiB: status %d, stderr: %s", o.status, o.err.c_str());
  EXPECT_NE(o.err.find("no space left on device"), std::string::npos) << o.err;
  std::printf("  left: %s\n", checkWholeAfterAFailedWrite(dir / "out", "bead_5", o).c_str());
  std::system(("umount " + dir.string()).c_str());
}

// The output directory removed while the run writes into it: status 5 and one line saying so
// (an unlinked probes.csv takes writes without an error: the run looks for it once a second).
TEST(OutputIntegrity, RemovingTheOutputDirectoryEndsTheRunWithStatus5) {
  const fs::path dir = chute::testing::freshTempDir("chute_test_integrity_", "removed");
  const fs::path err = dir.parent_path() / "chute_test_integrity_removed.err";
  const std::string bg = kChute + " run " + kBead + " --quiet --out " + dir.string() +
                         " --set solver.t_end=400 > /dev/null 2> " + err.string() + "; echo $? > " +
                         err.string() + ".status";
  fs::remove(err.string() + ".status");
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", bg.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  for (int i = 0; i < 1500 && !fs::exists(dir / "probes.csv"); ++i) ::usleep(20000);
  ::usleep(200000);
  fs::remove_all(dir);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  const std::string text = bytes(err);
  const int code = std::stoi(bytes(err.string() + ".status"));
  std::printf("directory removed: status %d, stderr: %s", code, text.c_str());
  EXPECT_EQ(code, 5);
  EXPECT_EQ(lines(text), 1);
  EXPECT_NE(text.find("removed"), std::string::npos) << text;
}

// A link planted where the run writes (probes.csv, a frame, the .pvd, the summary, the
// checkpoint) is replaced, never written through: its target is untouched.
TEST(OutputIntegrity, FilesAreCreatedNotWrittenThroughPlantedLinks) {
  const fs::path dir = chute::testing::freshTempDir("chute_test_integrity_", "links", true);
  const fs::path victim = dir.parent_path() / "chute_test_integrity_victim.txt";
  std::ofstream(victim) << "precious\n";
  for (const char* name :
       {"probes.csv", "bead_5.pvd", "bead_5_000000.vtu", "summary.json", "checkpoint.cbor",
        "checkpoint.cbor.tmp", "bead_5.pvd.tmp", "summary.json.tmp"})
    fs::create_symlink(victim, dir / name);
  const auto o = runChute("run " + kBead + " --quiet --set output.vtu.write=true " +
                          "--set solver.t_end=0.1 --checkpoint-every 10 --out " + dir.string());
  std::printf("planted links: status %d, stderr: %s", o.status, o.err.c_str());
  EXPECT_EQ(o.status, 0);
  EXPECT_EQ(bytes(victim), "precious\n") << "a link's target was written through";
  for (const char* name : {"probes.csv", "bead_5.pvd", "summary.json", "checkpoint.cbor"})
    EXPECT_FALSE(fs::is_symlink(dir / name)) << name;
  // The lock itself: a link there refuses the run (exit 2) rather than open its target.
  const fs::path dir2 = chute::testing::freshTempDir("chute_test_integrity_", "lock_link", true);
  fs::create_symlink(victim, dir2 / ".chute-run.lock");
  const auto l =
      runChute("run " + kBead + " --quiet --set solver.t_end=0.05 --out " + dir2.string());
  std::printf("planted lock link: status %d, stderr: %s", l.status, l.err.c_str());
  EXPECT_EQ(l.status, 2);
  EXPECT_EQ(bytes(victim), "precious\n");
}

TEST(OutputIntegrity, ASecondRunIntoADirectoryInUseIsRefused) {
  const fs::path dir = chute::testing::freshTempDir("chute_test_integrity_", "lock");
  // A long run holds the directory while a second one tries it.
  const std::string bg =
      kChute + " run " + kBead + " --quiet --out " + dir.string() +
      " --set solver.t_end=4000 --set output.max_rows=10000000 > /dev/null 2>&1 & echo $! > " +
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
  // The outer document {format: 4, payload: <deep>, checksum: FNV-1a(deep)}, CBOR by hand.
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : deep) h = (h ^ c) * 1099511628211ull;
  std::string forged = "\xa3";
  forged +=
      "\x66"
      "format"
      "\x04";  // this build's format, so that the payload is read
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
