// Stability stress suite (issue 8, item 5), short versions; the long ones are in bench/stress.py
// (bench/results/stress.csv). Each run must complete (step rejections are allowed: they are
// recovered by halving the step and counted), and its energy must stay bounded: the largest
// |E(t) - E(0)| relative to the largest kinetic energy of the run (rho_inf = 1 everywhere, so
// the integrator itself dissipates nothing). A table of the figures is printed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "app/RunCase.hpp"
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
                std::string(runStatusName(s.r.status)).c_str(), s.r.steps, s.handovers(),
                s.r.rejectedSteps, s.r.eventRetries, s.r.energyMaxDrift, s.relativeDrift(),
                s.r.newtonPerStep());
}

void expectBounded(const StressRun& s, double relativeDrift) {
  SCOPED_TRACE(s.name);
  EXPECT_EQ(s.r.status, RunStatus::Completed) << s.r.reason;
  EXPECT_TRUE(std::isfinite(s.r.energyMaxDrift));
  EXPECT_GT(s.r.kineticMax, 0.0);
  EXPECT_LE(s.relativeDrift(), relativeDrift);
}
}  // namespace

TEST(Stress, DrivenSliderCrossesTheNodesOfAFiftyElementRope) {
  // (a) a slider with prescribed motion, x = 5 + 4.5 sin(2 pi t), 1.5 m below the anchors of a
  // massless 50-element rope, 4 periods (> 250 node passages; bench/stress.py: 40 periods).
  const CaseSpec spec = readCase(casePath("stress_driven_slider"));
  const StressRun s{"driven slider (4 s)", runCase(spec, RunOptions{})};
  printTable({s});
  SCOPED_TRACE(s.name);
  ASSERT_EQ(s.r.status, RunStatus::Completed) << s.r.reason;
  EXPECT_EQ(s.r.rejectedSteps, 0);
  EXPECT_GE(s.handovers(), 250);
  // Closed form: two straight lines at one strain, so s = L lL / (lL + lR).
  const auto& g = spec.model.groups[0];
  const double L = std::accumulate(g.refLength.begin(), g.refLength.end(), 0.0);
  auto column = [&](const std::string& c) {
    return static_cast<int>(std::find(s.r.columns.begin(), s.r.columns.end(), c) -
                            s.r.columns.begin());
  };
  const int sc = column("slider.s"), ec = column("energy.strain");
  double worst = 0.0, periodic = 0.0, strainMax = 0.0;
  for (size_t k = 0; k < s.r.rows.size(); ++k) {
    const double t = s.r.times[k], x = 5.0 + 4.5 * std::sin(2.0 * M_PI * t);
    const double lL = std::hypot(x, 1.5), lR = std::hypot(10.0 - x, 1.5);
    worst = std::max(worst, std::abs(s.r.rows[k][sc] - L * lL / (lL + lR)));
    strainMax = std::max(strainMax, s.r.rows[k][ec]);
    for (size_t j = k + 1; j < s.r.rows.size(); ++j)  // the same phase a whole period later
      if (std::abs(s.r.times[j] - t - 1.0) < 1e-9)
        periodic = std::max(periodic, std::abs(s.r.rows[j][ec] - s.r.rows[k][ec]));
  }
  std::printf(
      "driven slider: %ld node passages, material coordinate off the closed form by "
      "%.3e m at most, strain energy one period later off by %.3e of its peak\n",
      s.handovers(), worst, periodic / strainMax);
  EXPECT_LE(worst, 1e-6);
  EXPECT_LE(periodic / strainMax, 1e-8);
}

TEST(Stress, SliderSwingsAlongAFiftyElementRopeAcrossItsNodes) {
  // (a2) the free-swinging bead: 4 s here (> 80 node passages); bench/stress.py runs 40 s (> 1000
  // passages).
  const auto s = run("swing50 (4 s)", "stress_swing50");
  // The same with each crossing made inside its step (solver.slider_events = false).
  const auto inStep =
      run("swing50, in-step (4 s)", "stress_swing50", {"solver.slider_events=false"});
  printTable({s, inStep});
  expectBounded(s, 1e-3);
  expectBounded(inStep, 1e-3);
  EXPECT_GE(s.handovers(), 80);
  EXPECT_EQ(inStep.handovers(), s.handovers());
  EXPECT_EQ(inStep.r.eventRetries, 0);
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

TEST(Stress, CableWithMassiveNodesSnatchingTaut) {
  // (e') the same with a line of 10 g/m (2.5 g interior nodes, omega dt = 8 when taut): every
  // slack / taut switch is located in time (CableTerm::passageFraction), 1 s here (bench: 20 s).
  // At the case's rho_inf = 1 the run makes energy up with nothing doing work on it (B = 0.117
  // J = 0.012 S by t = 0.34 s; continued, it exceeds 0.05 S at 1.6 s:
  // bench/results/energy_monitor.md), so it must end unstable by EB2 (docs/formulation.md), not
  // complete; with the numerical damping of rho_inf = 0.8 it completes without gaining energy.
  const auto s = run("snatch, line with mass (1 s)", "stress_snatch",
                     {"solver.t_end=1", "materials.line.density=10000"});
  const auto d = run("the same, rho_inf 0.8", "stress_snatch",
                     {"solver.t_end=1", "materials.line.density=10000", "solver.rho_inf=0.8"});
  printTable({s, d});
  EXPECT_EQ(s.r.status, RunStatus::Unstable);
  EXPECT_NE(s.r.reason.find("without external work"), std::string::npos) << s.r.reason;
  EXPECT_GT(s.r.eventRetries, 0);
  ASSERT_EQ(d.r.status, RunStatus::Completed) << d.r.reason;
  EXPECT_GT(d.r.eventRetries, 0);
  std::printf("rho_inf 0.8: largest balance %.3e of the scale %.4g (bound 1e-6)\n",
              d.r.balanceMax / d.r.balanceScale, d.r.balanceScale);
  EXPECT_LE(d.r.balanceMax, 1e-6 * d.r.balanceScale);
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
  // (g) 28 sliding groups sharing one slider point; the ring drops into its lines. Its snatches
  // are chaotic: round-off alone spreads the relative drift over 0.0128-0.0294 (12 runs of
  // `chute run cases/stress_ring28.toml --set nodes.ring=[0.2,0.1,-0.8000000000k]`, k = 0 ..
  // 11, 2026-11-27; 0.0194 as given), so the bound sits above that spread; an integration that
  // made energy up would go far past it.
  const auto s = run("ring28 (2 s)", "stress_ring28");
  printTable({s});
  expectBounded(s, 5e-2);
  EXPECT_EQ(s.r.handovers.size(), 28u);
}
