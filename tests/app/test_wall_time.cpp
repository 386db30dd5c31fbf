// summary.json's wall_time splits an explicit run's own work (Timings): the passes over all dofs,
// the commits, the stable-step estimate and the energy balance, each apart from the assembly and
// the sliders' settling, so that the parts add up to no more than the run's wall time and `other`
// is what is left (start-up, the stepper's bookkeeping).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "app/RunCase.hpp"
#include "case/CaseSpec.hpp"

using namespace chute;

TEST(WallTime, TheSummarySplitsTheExplicitStepsOwnWork) {
  const std::string caseFile = std::string(CHUTE_SOURCE_DIR) + "/cases/c9_slider.toml";
  const CaseSpec spec = readCase(caseFile, {"solver.t_end=0.02"});
  const std::string out = ::testing::TempDir() + "wall_time_" + std::to_string(::getpid());
  const RunResult r = runCase(spec, RunOptions::writingTo(out));
  ASSERT_EQ(r.status, RunStatus::Completed);
  const Timings& t = r.timings;
  EXPECT_GT(t.passes, 0.0);
  EXPECT_GT(t.commits, 0.0);
  EXPECT_GT(t.stableStep, 0.0);
  EXPECT_GT(t.balance, 0.0);
  EXPECT_GT(t.assembly, 0.0);
  const double parts = t.assembly + t.search + t.factorisation + t.solve + t.output + t.passes +
                       t.commits + t.stableStep + t.balance;
  // Nothing is counted twice: the parts are disjoint spans of the stepping thread's time.
  EXPECT_LE(parts, r.wallTime);
  std::printf(
      "wall %.4f s: assembly %.4f, search %.4f, passes %.4f, commits %.4f, stable step "
      "%.4f, balance %.4f, output %.4f, other %.4f\n",
      r.wallTime, t.assembly, t.search, t.passes, t.commits, t.stableStep, t.balance, t.output,
      r.wallTime - parts);

  std::ifstream f(out + "/summary.json");
  const auto j = nlohmann::json::parse(f);
  const auto& w = j.at("wall_time");
  for (const char* key :
       {"total", "assembly", "search", "factorisation", "solve", "output", "passes", "commits",
        "stable_step", "balance", "other", "output_background"})
    EXPECT_TRUE(w.contains(key)) << key;
  double sum = 0.0;
  for (const char* key : {"assembly", "search", "factorisation", "solve", "output", "passes",
                          "commits", "stable_step", "balance", "other"})
    sum += w.at(key).get<double>();
  EXPECT_NEAR(sum, w.at("total").get<double>(), 1e-9 * w.at("total").get<double>() + 1e-12);
  std::filesystem::remove_all(out);
}
