// Stability stress suite (issue 8, item 5), short versions; the long ones are in bench/stress.py
// (bench/results/stress.csv). Each run must complete (step rejections are allowed: they are
// recovered by halving the step and counted), and its energy must stay bounded: the largest
// |E(t) - E(0)| relative to the largest kinetic energy of the run (rho_inf = 1 everywhere, so
// the integrator itself dissipates nothing). A table of the figures is printed.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "app/Simulation.hpp"
#include "case/CaseSpec.hpp"

using namespace chute;

namespace {
std::string casePath(const std::string& name) {
  return std::string(CHUTE_SOURCE_DIR) + "/cases/" + name + ".toml";
}

struct StressRun {
  std::string name;
  RunResult r;
  long handovers() const { return std::accumulate(r.handovers.begin(), r.handovers.end(), 0L); }
  double relativeDrift() const { return r.energyMaxDrift / r.kineticMax; }
};

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

StressRun run(const std::string& name, const std::string& file,
              const std::vector<std::string>& overrides = {}) {
  return {name, runCase(readCase(casePath(file), overrides), RunOptions{})};
}

void printTable(const std::vector<StressRun>& runs) {
  std::printf("\n%-34s %-10s %6s %6s %8s %9s %10s %10s %8s\n", "stress case", "status", "steps",
              "hand", "rejected", "retries", "max drift", "rel drift", "Newton/st");
  for (const auto& s : runs)
    std::printf("%-34s %-10s %6ld %6ld %8ld %9ld %10.3e %10.3e %8.2f\n", s.name.c_str(),
                s.r.status.c_str(), s.r.steps, s.handovers(), s.r.rejectedSteps, s.r.eventRetries,
                s.r.energyMaxDrift, s.relativeDrift(), s.r.newtonPerStep());
}

void expectBounded(const StressRun& s, double relativeDrift) {
  SCOPED_TRACE(s.name);
  EXPECT_EQ(s.r.status, "completed") << s.r.reason;
  EXPECT_TRUE(std::isfinite(s.r.energyMaxDrift));
  EXPECT_GT(s.r.kineticMax, 0.0);
  EXPECT_LE(s.relativeDrift(), relativeDrift);
}
}  // namespace

TEST(Stress, SliderSwingsAlongAFiftyElementRopeAcrossItsNodes) {
  // (a) 4 s here (> 80 node passages); bench/stress.py runs 40 s (> 1000 passages).
  const auto s = run("swing50 (4 s)", "stress_swing50");
  printTable({s});
  expectBounded(s, 1e-3);
  EXPECT_GE(s.handovers(), 80);
}

TEST(Stress, SliderStartingExactlyOnANode) {
  // (b) the bead starts on rope node 1: active element 1 (from the path) or 0 (the element
  // ending at that node); both must leave the node cleanly.
  const auto a = run("on_node (active 1)", "stress_on_node");
  CaseSpec other = readCase(casePath("stress_on_node"));
  other.model.groups[0].initialActive = {0};
  const StressRun b{"on_node (active 0)", runCase(other, RunOptions{})};
  printTable({a, b});
  expectBounded(a, 1e-3);
  expectBounded(b, 1e-3);
  // The same motion either way (the two elements describe the same configuration at the node).
  double worst = 0.0;
  for (size_t k = 0; k < std::min(a.r.rows.size(), b.r.rows.size()); ++k)
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(a.r.rows[k][c] - b.r.rows[k][c]));
  // Known defect (bench/README.md): starting on the element that *ends* at the node, the short
  // part sits on the regularised apex, where it pulls in no direction, so the initial
  // acceleration misses that part's tension; the bead is handed over at the first step, but the
  // first step's error stays (millimetres here). Printed, not asserted, until that is fixed.
  std::printf("on_node: largest bead position difference between the two starts %.3e m\n", worst);
}

TEST(Stress, StiffnessFromOneThousandToOneTrillionTimesTheLoad) {
  // (c) bead_5 with E A / W = 1e3 ... 1e12 (prestrain W / E A, the rope's tension at release).
  std::vector<StressRun> runs;
  for (int e = 3; e <= 12; e += 3) {
    const double E = std::pow(10.0, e + 4);  // A = 1e-3 ft^2, W = 10 lbf
    runs.push_back(
        run("bead_5 EA/W = 1e" + std::to_string(e), "bead_5",
            {"materials.rope.E=" + num(E), "sliding_groups.0.prestrain=" + num(std::pow(10.0, -e)),
             "solver.rho_inf=1"}));
  }
  printTable(runs);
  for (const auto& s : runs) {
    expectBounded(s, 1e-2);
    EXPECT_LE(s.r.reference->relative(), 5e-3);
  }
}

TEST(Stress, TimeStepFromTenMicrosecondsToATenthOfASecond) {
  // (d) bead_5 with dt = 1e-5 ... 1e-1 s, at most 2000 steps each (bench: down to 1e-6).
  std::vector<StressRun> runs;
  for (int e = -5; e <= -1; ++e) {
    const double dt = std::pow(10.0, e);
    const double tEnd = std::min(4.0, 2000 * dt);
    runs.push_back(run("bead_5 dt = 1e" + std::to_string(e), "bead_5",
                       {"solver.dt=" + num(dt), "solver.t_end=" + num(tEnd),
                        "output.interval=" + num(dt), "solver.rho_inf=1"}));
  }
  printTable(runs);
  for (const auto& s : runs) expectBounded(s, 2e-2);
}

TEST(Stress, CableCyclingSlackAndTaut) {
  // (e) a payload bouncing on a line that goes slack and snatches taut again.
  const auto s = run("snatch (3 s)", "stress_snatch");
  printTable({s});
  expectBounded(s, 2e-2);
  const int col = static_cast<int>(std::find(s.r.columns.begin(), s.r.columns.end(), "tension.N") -
                                   s.r.columns.begin());
  int tautPhases = 0;
  bool taut = false;
  for (const auto& row : s.r.rows) {
    if (row[col] > 0.0 && !taut) ++tautPhases;
    taut = row[col] > 0.0;
  }
  std::printf("snatch: %d slack -> taut cycles\n", tautPhases);
  EXPECT_GE(tautPhases, 3);
}

TEST(Stress, MasslessRopeNodes) {
  // (f) bead_5's massless rope in 20 elements, 10 s at rho_inf = 1.
  const auto s = run("bead_5, 20 massless el. (10 s)", "bead_5",
                     {"sliding_groups.0.elements=20", "solver.t_end=10", "solver.rho_inf=1"});
  printTable({s});
  expectBounded(s, 1e-3);
  EXPECT_GE(s.handovers(), 40);
}

TEST(Stress, TwentyEightLinesThroughOneRing) {
  // (g) 28 sliding groups sharing one slider point; the ring drops into its lines.
  const auto s = run("ring28 (2 s)", "stress_ring28");
  printTable({s});
  expectBounded(s, 2e-2);
  EXPECT_EQ(s.r.handovers.size(), 28u);
}
