// An output interval shorter than solver.dt caps the implicit steps (steps land on output
// times); the run says so (RunResult::notes, summary.json solver.dt_capped_by_output) instead of
// shrinking dt silently. An interval of at least dt leaves the steps alone and says nothing.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <string>

#include "app/RunCase.hpp"
#include "case/CaseSpec.hpp"

using namespace chute;

namespace {

std::string writeCase(double dt, double interval) {
  // One file per process: ctest runs the two tests of this program at once.
  const std::string path =
      ::testing::TempDir() + "output_step_cap_" + std::to_string(getpid()) + ".toml";
  std::ofstream f(path);
  f << "name = \"output_step_cap\"\n"
    << "[nodes]\nanchor = [0.0, 0.0, 0.0]\nmass = [1.0, 0.0, 0.0]\n"
    << "[materials.rod]\nkind = \"truss\"\nE = 1.0e6\narea = 1.0\n"
    << "[[cables]]\nname = \"rod\"\nmaterial = \"rod\"\npath = [\"anchor\", \"mass\"]\n"
    << "[[point_masses]]\nnode = \"mass\"\nmass = 1.0\n"
    << "[boundary]\nfixed = [\"anchor\"]\n"
    << "[loads]\ngravity = [0.0, 0.0, -10.0]\n"
    << "[solver]\ndt = " << dt << "\nt_end = 0.1\n"
    << "[output]\ninterval = " << interval << "\n"
    << "[[output.probes]]\nname = \"mass\"\nkind = \"node_position\"\n";
  return path;
}

}  // namespace

TEST(OutputStepCap, AnIntervalBelowDtCapsTheStepAndSaysSo) {
  const RunResult r = runCase(readCase(writeCase(0.01, 0.004)), RunOptions{});
  ASSERT_EQ(r.status, RunStatus::Completed);
  EXPECT_EQ(r.steps, 25);  // 0.1 / 0.004: every step is the interval
  EXPECT_DOUBLE_EQ(r.outputStepCap, 0.004);
  ASSERT_EQ(r.notes.size(), 1u);
  EXPECT_NE(r.notes[0].find("output.interval = 0.004 is shorter than solver.dt = 0.01"),
            std::string::npos)
      << r.notes[0];
  std::printf("steps %ld, note: %s\n", r.steps, r.notes[0].c_str());
}

TEST(OutputStepCap, AnIntervalOfAtLeastDtSaysNothing) {
  const RunResult r = runCase(readCase(writeCase(0.01, 0.02)), RunOptions{});
  ASSERT_EQ(r.status, RunStatus::Completed);
  EXPECT_EQ(r.steps, 10);
  EXPECT_TRUE(std::isnan(r.outputStepCap));
  EXPECT_TRUE(r.notes.empty());
}
