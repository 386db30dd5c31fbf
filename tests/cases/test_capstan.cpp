// Friction at slider points against analytic capstan mechanics (docs/friction.md): two masses
// over a ring that hold or slip, the paper's pulley with a capstan factor, mu = 0 against the
// frictionless element, the belt through two rings, Newton's order and cost with friction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "app/RunCase.hpp"
#include "case/CaseSpec.hpp"
#include "solver/GeneralizedAlpha.hpp"
#include "solver/StaticLoadStepper.hpp"
#include "terms/sliding/SlidingGroupTerm.hpp"

using namespace chute;

namespace {
CaseSpec shipped(const std::string& name, const std::vector<std::string>& sets = {}) {
  return readCase(CHUTE_SOURCE_DIR "/cases/" + name + ".toml", sets);
}

// Column of a probe quantity in a run's rows.
std::vector<double> column(const RunResult& r, const std::string& name) {
  const auto it = std::find(r.columns.begin(), r.columns.end(), name);
  EXPECT_NE(it, r.columns.end()) << name;
  const long c = it - r.columns.begin();
  std::vector<double> v;
  for (const auto& row : r.rows) v.push_back(row[c]);
  return v;
}

// Heavy mass acceleration over a fixed ring, massless rope, both strands vertical (FR13).
double capstanAcceleration(double g, double m1, double m2, double mu) {
  const double k = std::exp(mu * std::numbers::pi);
  return g * (m2 - m1 * k) / (m2 + m1 * k);
}
}  // namespace

TEST(Capstan, TwoMassesSlipWithTheCapstanAcceleration) {
  const double g = 10.0, mu = 0.2, m1 = 1.0, m2 = 2.5;
  const auto r = runCase(shipped("capstan_masses"), RunOptions{});
  ASSERT_EQ(r.status, RunStatus::Completed);
  const auto z = column(r, "heavy.z"), state = column(r, "ring.state");
  const auto ratio = column(r, "ring.tension_ratio");
  // z(t) = z0 + v0 t - a t^2 / 2 once slipping: a from the second difference of z over the
  // last half (the first steps carry the elastic start-up of the prestressed rope).
  const size_t n = z.size() - 1, m = n / 2, q = (n + m) / 2;
  ASSERT_EQ(n - q, q - m);
  const double h = r.times[n] - r.times[q];
  const double a = -(z[m] - 2 * z[q] + z[n]) / (h * h);
  const double aRef = capstanAcceleration(g, m1, m2, mu);
  const double k = std::exp(mu * std::numbers::pi);
  std::printf(
      "capstan masses m2/m1 = %.2f > exp(mu pi) = %.4f: a = %.6f, analytic %.6f, "
      "error %.4f %%; tension ratio %.8f vs %.8f; Newton/step %.2f\n",
      m2 / m1, k, a, aRef, 100 * std::abs(a / aRef - 1), ratio.back(), k, r.newtonPerStep());
  EXPECT_LT(std::abs(a / aRef - 1), 5e-3);
  EXPECT_EQ(state.back(), -1.0);  // slipping towards the heavy side (part 2)
  EXPECT_LT(std::abs(ratio.back() / k - 1), 1e-6);
}

TEST(Capstan, TwoMassesHoldBelowTheCapstanLimitAndSlipAbove) {
  // Released from an unstretched rope the two sides ring at different frequencies and the
  // dynamic tension ratio overshoots: start from static equilibrium instead. m2 / m1 = 1.8 <
  // exp(0.2 pi) = 1.874 holds; raising m2 to 1.95 slips at the capstan acceleration.
  CaseSpec spec = shipped("capstan_masses", {"point_masses.1.mass=1.8"});
  StructuralSystem sys(spec.model, spec.solver.search);
  GeneralizedAlpha integ(sys, 0.9, AlphaScheme::Bossak, NewtonSettings{}, 5e-3, 0.0);
  StructuralState s = sys.initialState();
  sys.commit(CommitPoint{s.x, s.t, 0.0, s.t});
  const auto& st = sys.termList().slidingGroups()[0]->state();
  const double split0 = st.friction(0).s;
  ASSERT_TRUE(StaticLoadStepper(sys, integ.newton()).solve(s, 1).converged);
  EXPECT_EQ(st.friction(0).state, kernels::SliderStick::Stick);
  const int heavy = spec.model.nodeId("heavy");
  const double zStatic = s.x[3 * heavy + 2];
  const double ratioStatic = st.friction(0).tensionRatio();
  double drop = 0.0;
  for (int k = 0; k < 40; ++k) {
    ASSERT_TRUE(integ.tryStep(s, 5e-3).converged);
    EXPECT_EQ(st.friction(0).state, kernels::SliderStick::Stick);
    drop = std::max(drop, std::abs(s.x[3 * heavy + 2] - zStatic));
  }
  std::printf(
      "capstan masses m2/m1 = 1.80 <= 1.8745: static tension ratio %.6f, split change "
      "%.1e ft, held for 0.2 s: max drift %.2e ft\n",
      ratioStatic, std::abs(st.friction(0).s - split0), drop);
  EXPECT_EQ(st.friction(0).s, split0);
  EXPECT_LT(drop, 1e-9);
  EXPECT_NEAR(ratioStatic, 1.8, 1e-9);
  // Above the limit: the same ring slips.
  spec.model.pointMass[heavy] = 1.95;
  std::vector<double> z;  // at 0.1, 0.2, 0.3 s after the change (second difference)
  for (int k = 1; k <= 60; ++k) {
    ASSERT_TRUE(integ.tryStep(s, 5e-3).converged);
    if (k % 20 == 0) z.push_back(s.x[3 * heavy + 2]);
  }
  const double a = -(z[0] - 2 * z[1] + z[2]) / (0.1 * 0.1);
  const double aRef = capstanAcceleration(10.0, 1.0, 1.95, 0.2);
  std::printf("  m2 raised to 1.95 > 1.8745: slips, a = %.6f ft/s^2 vs analytic %.6f (%.4f %%)\n",
              a, aRef, 100 * std::abs(a / aRef - 1));
  EXPECT_EQ(st.friction(0).state, kernels::SliderStick::SlipMinus);
  EXPECT_LT(std::abs(a / aRef - 1), 5e-3);
}

TEST(Capstan, PulleyWithFrictionFollowsTheCapstanFactorSolution) {
  const double g = 10.0, L = 100.0, mu = 0.05;
  const auto r = runCase(shipped("capstan_pulley"), RunOptions{});
  ASSERT_EQ(r.status, RunStatus::Completed);
  const auto zl = column(r, "left_end.z");
  // Reference: l2'' = g (l2 - k (L - l2)) / (l2 + k (L - l2)) (FR14), RK4 with 1e-4 s steps.
  const double k = std::exp(mu * std::numbers::pi);
  auto acc = [&](double l2) { return g * (l2 - k * (L - l2)) / (l2 + k * (L - l2)); };
  double l2 = 60.0, v = 0.0, t = 0.0, maxErr = 0.0, maxErrFrictionless = 0.0;
  const double h = 1e-4;
  for (size_t i = 0; i < r.times.size(); ++i) {
    while (t < r.times[i] - 1e-12) {
      const double step = std::min(h, r.times[i] - t);
      const double k1x = v, k1v = acc(l2);
      const double k2x = v + 0.5 * step * k1v, k2v = acc(l2 + 0.5 * step * k1x);
      const double k3x = v + 0.5 * step * k2v, k3v = acc(l2 + 0.5 * step * k2x);
      const double k4x = v + step * k3v, k4v = acc(l2 + step * k3x);
      l2 += step / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
      v += step / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
      t += step;
    }
    const double l1 = -zl[i];  // the pulley is at the origin
    maxErr = std::max(maxErr, std::abs(l1 - (L - l2)));
    const double l1Free = L / 2 + (40.0 - L / 2) * std::cosh(std::sqrt(2 * g / L) * t);  // F13
    maxErrFrictionless = std::max(maxErrFrictionless, std::abs(l1 - l1Free));
  }
  const double motion = 40.0 - (L - l2);
  std::printf(
      "pulley, mu = 0.05: left part 40 -> %.4f ft (frictionless %.4f) by t = %.1f s; max "
      "error vs capstan ODE %.3e ft = %.4f %% of the motion (vs F13: %.2f %%); Newton/step "
      "%.2f\n",
      -zl.back(), L / 2 + (40.0 - L / 2) * std::cosh(std::sqrt(2 * g / L) * t), t, maxErr,
      100 * maxErr / motion, 100 * maxErrFrictionless / motion, r.newtonPerStep());
  EXPECT_LT(maxErr / motion, 1e-3);
  EXPECT_GT(maxErrFrictionless / motion, 0.1);  // the friction does show
}

TEST(Capstan, ZeroFrictionReproducesTheFrictionlessElement) {
  // mu = 0 keys: the frictionless element itself, bit for bit. A frictionless ratchet open in
  // the flow direction runs the friction element with N1 = N2: equal to round-off.
  const auto plain = runCase(shipped("pulley"), RunOptions{});
  const auto zero =
      runCase(shipped("capstan_pulley", {"sliding_groups.0.friction.mu_static=0"}), RunOptions{});
  const auto ratchet = runCase(shipped("pulley", {"sliding_groups.0.one_way=\"-\""}), RunOptions{});
  ASSERT_EQ(ratchet.status, RunStatus::Completed);
  const auto a = column(plain, "left_end.z"), b = column(zero, "left_end.z"),
             c = column(ratchet, "left_end.z");
  ASSERT_EQ(a.size(), b.size());
  ASSERT_EQ(a.size(), c.size());
  double dZero = 0.0, dRatchet = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    dZero = std::max(dZero, std::abs(a[i] - b[i]));
    dRatchet = std::max(dRatchet, std::abs(a[i] - c[i]));
  }
  std::printf(
      "pulley: mu = 0 vs frictionless max |dz| = %.1e ft; frictionless ratchet (friction "
      "element) %.2e ft over a %.2f ft motion; pulley error vs F13 %.4f %% (ratchet "
      "%.4f %%)\n",
      dZero, dRatchet, a.front() - a.back(), 100 * plain.reference->relative(),
      100 * ratchet.reference->relative());
  EXPECT_EQ(dZero, 0.0);
  EXPECT_LT(dRatchet, 1e-9 * std::abs(a.front()));
}

TEST(Capstan, BeltThroughTwoRingsSharingANode) {
  CaseSpec spec = shipped("capstan_belt");
  StructuralSystem sys(spec.model, spec.solver.search);
  NewtonSettings ns;
  ns.tolDisplacement = 1e-12;
  GeneralizedAlpha integ(sys, 0.9, AlphaScheme::Bossak, ns, 0.1, 0.0);
  StructuralState s = sys.initialState();
  sys.commit(CommitPoint{s.x, s.t, 0.0, s.t});
  const Model& m = spec.model;
  const int load = m.nodeId("load_ring"), pull = m.nodeId("pull");
  ASSERT_TRUE(StaticLoadStepper(sys, integ.newton()).solve(s, 1).converged);
  const double z0 = s.x[3 * load + 2];
  // Pull 2.25 ft of belt out in 45 increments, each a static equilibrium.
  const int n = 45;
  int iterations = 0;
  for (int i = 0; i < n; ++i) {
    s.x[3 * pull] += 2.25 / n;
    const auto rep = StaticLoadStepper(sys, integ.newton()).solve(s, 1);
    ASSERT_TRUE(rep.converged) << rep.failure;
    iterations += rep.iterations;
  }
  const double rise = s.x[3 * load + 2] - z0;
  const auto* group = sys.termList().slidingGroups()[0];
  double maxTensionError = 0.0;
  const double W = 10.0;
  for (int k = 0; k < m.groups[0].numElements(); ++k) {
    const auto p = group->activeParts(k, s.x);
    maxTensionError =
        std::max({maxTensionError, std::abs(p.N1 / (0.5 * W) - 1), std::abs(p.N2 / (0.5 * W) - 1)});
  }
  std::printf(
      "belt through two rings: pulled 2.25 ft, load ring rose %.9f ft (1.125), "
      "max |N / (W/2) - 1| = %.2e over the four parts, %.1f Newton iterations per "
      "increment\n",
      rise, maxTensionError, double(iterations) / n);
  EXPECT_NEAR(rise, 1.125, 1e-6);
  EXPECT_LT(maxTensionError, 1e-6);
}

TEST(Capstan, NewtonStaysQuadraticInSlip) {
  CaseSpec spec = shipped("capstan_masses");
  StructuralSystem sys(spec.model, spec.solver.search);
  NewtonSettings ns;
  ns.tolDisplacement = 1e-13;
  GeneralizedAlpha integ(sys, 0.9, AlphaScheme::Bossak, ns, 0.1, 0.0);
  StructuralState s = sys.initialState();
  integ.computeAcceleration(s);
  sys.commit(CommitPoint{s.x, s.t, 0.0, s.t});
  double bestOrder = 0.0;
  for (int k = 0; k < 3; ++k) {
    const NewtonReport rep = integ.tryStep(s, 0.1);
    ASSERT_TRUE(rep.converged) << rep.failure;
    const auto& r = rep.residualNorms;
    std::printf("capstan masses, slip step %d (dt = 0.1): residual norms", k + 1);
    for (double v : r) std::printf(" %.3e", v);
    const double floor = 1e-10 * *std::max_element(r.begin(), r.end());
    double order = 0.0;
    for (size_t i = 2; i < r.size(); ++i) {
      if (r[i] < floor || r[i - 1] >= r[i - 2]) continue;
      order = std::max(order, std::log(r[i] / r[i - 1]) / std::log(r[i - 1] / r[i - 2]));
    }
    std::printf("  order %.2f\n", order);
    bestOrder = std::max(bestOrder, order);
  }
  EXPECT_EQ(sys.termList().slidingGroups()[0]->state().friction(0).state,
            kernels::SliderStick::SlipMinus);
  EXPECT_GE(bestOrder, 1.8);
}

TEST(Capstan, BeadFiveCrossesNodesWithFrictionAtNewtonCost) {
  // The bead on its five-element rope with capstan friction at the bead, slipping across the
  // rope's interior nodes (docs/friction.md FR15-FR16): the run completes with hand-overs,
  // Newton iterations per step at most 1.5x the frictionless run, and friction only dissipates
  // (total energy non-increasing between outputs, to the frictionless run's own drift).
  const auto plain = runCase(shipped("bead_5"), RunOptions{});
  ASSERT_EQ(plain.status, RunStatus::Completed);
  const auto plainE = column(plain, "energy.total");
  double plainDrift = 0.0;
  for (double e : plainE) plainDrift = std::max(plainDrift, std::abs(e - plainE.front()));
  struct Law {
    double muS, muD, vs;
  };
  for (const Law l : {Law{0.05, 0.04, 0.05}, Law{0.1, 0.1, 0.0}}) {
    CaseSpec spec = shipped("bead_5");
    spec.reference.reset();
    kernels::SliderFrictionLaw law;
    law.muStatic = l.muS;
    law.muDynamic = l.muD;
    law.slipRateScale = l.vs;
    spec.model.groups[0].friction.assign(1, law);
    const auto fr = runCase(spec, RunOptions{});
    ASSERT_EQ(fr.status, RunStatus::Completed) << fr.reason;
    const auto e = column(fr, "energy.total");
    double rise = 0.0;
    for (size_t i = 1; i < e.size(); ++i) rise = std::max(rise, e[i] - e[i - 1]);
    const double ratio = fr.newtonPerStep() / plain.newtonPerStep();
    std::printf(
        "bead_5 to 4 s, mu_s %.2f mu_d %.2f: hand-overs %ld (frictionless %ld), Newton/step %.3f "
        "vs %.3f frictionless: ratio %.3f; steps %ld, event retries %ld, rejected %ld; energy "
        "%.6f -> %.6f (dissipated %.4f), largest rise between outputs %.2e (frictionless drift "
        "%.2e)\n",
        l.muS, l.muD, fr.handovers.at(0), plain.handovers.at(0), fr.newtonPerStep(),
        plain.newtonPerStep(), ratio, fr.steps, fr.eventRetries, fr.rejectedSteps, e.front(),
        e.back(), e.front() - e.back(), rise, plainDrift);
    EXPECT_GT(fr.handovers.at(0), 0);
    EXPECT_LE(ratio, 1.5);
    EXPECT_LT(e.back(), e.front());
    EXPECT_LE(rise, std::max(plainDrift, 1e-9));
  }
}
