// Checkpoint/restart, signals and divergence (issue 9): a restarted run reproduces the
// uninterrupted one bit for bit and never writes an output time twice; SIGTERM leaves a
// checkpoint and valid output; a run that cannot go on stops cleanly with its last good state.
#include <fmt/core.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <thread>

#include "VtuSeries.hpp"
#include "app/RunCase.hpp"
#include "case/CaseSpec.hpp"
#include "support/TempDir.hpp"

namespace fs = std::filesystem;
using namespace chute;

namespace {

const std::string kChute = CHUTE_BINARY;

fs::path freshDir(const std::string& name) {
  return chute::testing::freshTempDir("chute_test_restart_", name);
}

std::string readFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

nlohmann::json readJson(const fs::path& p) {
  return nlohmann::json::parse(readFile(p));
}

// Probe times of a probes.csv (first column).
std::vector<double> csvTimes(const fs::path& p) {
  std::ifstream in(p);
  std::string line;
  std::getline(in, line);
  std::vector<double> t;
  while (std::getline(in, line))
    if (!line.empty()) t.push_back(std::stod(line.substr(0, line.find(','))));
  return t;
}

CaseSpec bead5WithVtu() {
  CaseSpec spec = readCase(CHUTE_SOURCE_DIR "/cases/bead_5.toml");
  spec.output.vtu.write = true;
  spec.output.vtu.everySteps = 40;
  spec.output.vtu.interval = 0.0;
  return spec;
}

}  // namespace

TEST(Restart, ReproducesTheUninterruptedRunBitForBitWithoutRepeatedOutputTimes) {
  const CaseSpec spec = bead5WithVtu();
  const fs::path whole = freshDir("whole"), split = freshDir("split");
  const RunResult a = runCase(spec, RunOptions::writingTo(whole.string()));
  ASSERT_EQ(a.status, RunStatus::Completed);

  // The same run with a checkpoint every 300 steps: the file left holds the state at step 600
  // (the later ones overwrite the earlier). Restart from it into the same directory: the probes
  // and the .pvd after that time are discarded and written again.
  RunOptions withCheckpoints = RunOptions::writingTo(split.string());
  withCheckpoints.checkpointEvery = 300;
  const RunResult b = runCase(spec, withCheckpoints);
  ASSERT_EQ(b.status, RunStatus::Completed);
  EXPECT_EQ(b.checkpoints, a.steps / 300);
  RunOptions restart = RunOptions::writingTo(split.string());
  restart.restartFile = (split / "checkpoint.cbor").string();
  const RunResult c = runCase(spec, restart);
  ASSERT_EQ(c.status, RunStatus::Completed);

  const std::string pa = readFile(whole / "probes.csv"), pc = readFile(split / "probes.csv");
  std::printf("restart: %ld steps uninterrupted, %ld after restart; probes.csv %zu bytes, %s\n",
              a.steps, c.steps, pa.size(), pa == pc ? "identical" : "DIFFERENT");
  EXPECT_EQ(pa, pc) << "probes.csv differs after restart";
  EXPECT_EQ(a.steps, c.steps);
  EXPECT_EQ(a.newtonIterations, c.newtonIterations);
  EXPECT_EQ(a.eventRetries, c.eventRetries);
  EXPECT_EQ(a.handovers, c.handovers);
  EXPECT_EQ(a.energyMaxDrift, c.energyMaxDrift);

  // The .pvd: same times as the uninterrupted run, none twice; the last frame's file identical.
  const auto sa = readPvd((whole / "bead_5.pvd").string());
  const auto sc = readPvd((split / "bead_5.pvd").string());
  ASSERT_EQ(sa.size(), sc.size());
  std::set<double> seen;
  for (size_t i = 0; i < sc.size(); ++i) {
    EXPECT_EQ(sa[i].t, sc[i].t);
    EXPECT_TRUE(seen.insert(sc[i].t).second) << "time " << sc[i].t << " written twice";
    EXPECT_TRUE(fs::exists(split / sc[i].file));
  }
  EXPECT_EQ(readFile(whole / sa.back().file), readFile(split / sc.back().file));
  std::printf("restart: %zu VTU frames, no time twice, last frame identical\n", sc.size());
  // The summary counts the whole run.
  const auto j = readJson(split / "summary.json");
  EXPECT_EQ(j["steps"].get<long>(), a.steps);
  EXPECT_EQ(j["output"]["probe_rows"].get<long>(), a.probeRows);
}

TEST(Restart, RefusesACheckpointOfAnotherModel) {
  const fs::path dir = freshDir("other");
  RunOptions o = RunOptions::writingTo(dir.string());
  o.checkpointEvery = 50;
  CaseSpec spec = readCase(CHUTE_SOURCE_DIR "/cases/bead_1.toml");
  ASSERT_EQ(runCase(spec, o).status, RunStatus::Completed);
  RunOptions r = RunOptions::writingTo(freshDir("other_restart").string());
  r.restartFile = (dir / "checkpoint.cbor").string();
  spec.model.X[0].x() += 1e-9;  // a different model with the same name
  EXPECT_THROW(runCase(spec, r), std::runtime_error);
  r.restartFile = (dir / "probes.csv").string();  // not a checkpoint at all
  EXPECT_THROW(runCase(readCase(CHUTE_SOURCE_DIR "/cases/bead_1.toml"), r), std::runtime_error);
}

TEST(Signals, SigtermWritesACheckpointAndLeavesValidOutputThenTheRunContinues) {
  const fs::path dir = freshDir("sigterm");
  // A long run (bead_5 for 5000 s of simulated time) stopped by SIGTERM once it has output.
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen("/dev/null", "w", stderr);
    execl(kChute.c_str(), kChute.c_str(), "run", CHUTE_SOURCE_DIR "/cases/bead_5.toml", "--out",
          dir.c_str(), "--quiet", "--set", "solver.t_end=5000", "--set", "output.vtu.write=true",
          "--set", "output.vtu.every=200", "--set", "output.max_rows=10000000", "--set",
          "output.vtu.max_frames=100000", static_cast<char*>(nullptr));
    _exit(127);
  }
  const auto t0 = std::chrono::steady_clock::now();
  while (!fs::exists(dir / "bead_5_000002.vtu") &&
         std::chrono::steady_clock::now() - t0 < std::chrono::seconds(60))
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_EQ(kill(pid, SIGTERM), 0);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by a signal instead of stopping cleanly";
  EXPECT_EQ(WEXITSTATUS(status), 4);
  ASSERT_TRUE(fs::exists(dir / "checkpoint.cbor"));
  const auto j = readJson(dir / "summary.json");
  EXPECT_EQ(j["status"], "interrupted");
  const double tStop = j["final_time"].get<double>();
  EXPECT_GT(tStop, 0.0);
  EXPECT_LT(tStop, 5000.0);
  const auto times = csvTimes(dir / "probes.csv");
  ASSERT_FALSE(times.empty());
  EXPECT_EQ(times.back(), tStop) << "the last good state is the last probe row";
  const auto frames = readPvd((dir / "bead_5.pvd").string());
  ASSERT_GE(frames.size(), 3u);
  EXPECT_EQ(frames.back().t, tStop);
  for (const auto& f : frames) EXPECT_TRUE(fs::exists(dir / f.file));
  std::printf("SIGTERM: stopped at t = %.6g with exit 4, %zu probe rows, %zu VTU frames\n", tStop,
              times.size(), frames.size());

  // Continue from the checkpoint to a nearby end: exit 0, times strictly increasing.
  const std::string cmd = kChute + " run " CHUTE_SOURCE_DIR "/cases/bead_5.toml --quiet --out " +
                          dir.string() + " --restart " + (dir / "checkpoint.cbor").string() +
                          " --set output.vtu.write=true --set output.vtu.every=200" +
                          " --set solver.t_end=" + fmt::format("{:.17g}", tStop + 1.0);
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const auto after = csvTimes(dir / "probes.csv");
  for (size_t i = 1; i < after.size(); ++i) ASSERT_LT(after[i - 1], after[i]) << "row " << i;
  // The stop time may be any instant (an event step ends where a slider meets a node): the end
  // time is passed with all its digits.
  EXPECT_NEAR(after.back(), tStop + 1.0, 1e-12);
  const auto framesAfter = readPvd((dir / "bead_5.pvd").string());
  for (size_t i = 1; i < framesAfter.size(); ++i) ASSERT_LT(framesAfter[i - 1].t, framesAfter[i].t);
}

TEST(Divergence, StopsCleanlyWithTheLastGoodStateAndTheReason) {
  // Two Newton iterations are too few for bead_5's slider hand-overs: steps are rejected, dt
  // is halved down to dt_min, and the run stops with exit status 3 and the last good state.
  const fs::path dir = freshDir("diverge");
  const std::string cmd =
      kChute + " run " CHUTE_SOURCE_DIR "/cases/bead_5.toml --quiet --out " + dir.string() +
      " --set solver.newton_max_iterations=2 --set solver.dt_min=1e-4" +
      " --set output.vtu.write=true --set output.vtu.every=10 2> " + (dir.string() + ".err");
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 3);
  const std::string err = readFile(dir.string() + ".err");
  EXPECT_NE(err.find("dt_min"), std::string::npos) << err;
  const auto j = readJson(dir / "summary.json");
  EXPECT_EQ(j["status"], "diverged");
  EXPECT_NE(j["reason"].get<std::string>().find("step rejected"), std::string::npos);
  EXPECT_GT(j["rejected_steps"].get<long>(), 0);
  const double tLast = j["final_time"].get<double>();
  const auto times = csvTimes(dir / "probes.csv");
  ASSERT_FALSE(times.empty());
  EXPECT_EQ(times.back(), tLast);
  const auto frames = readPvd((dir / "bead_5.pvd").string());
  ASSERT_FALSE(frames.empty());
  EXPECT_EQ(frames.back().t, tLast);
  std::printf("divergence: exit 3 at t = %.6g after %ld rejected steps; reason: %s\n", tLast,
              j["rejected_steps"].get<long>(), j["reason"].get<std::string>().c_str());
}
