// solver.integrator = "energy_momentum" on the shipped bead of one sliding element
// (cases/bead_1.toml): a bead on a massless, very stiff rope, against the ellipse ODE of the
// inextensible rope (docs/formulation.md section 8), with Bossak (the shipped rho_inf = 0.9, and
// rho_inf = 1) beside it; bead_5 (five elements: its massless chain condensed, EM12) against the
// same reference, energy conserved across its hand-overs; a massless chain whose inner node
// carries a point mass is refused, and a bead on a rope with mass (hand-overs located, EM13)
// turns where central differences turn it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "app/RunCase.hpp"
#include "case/CaseError.hpp"
#include "case/CaseSpec.hpp"
#include "terms/sliding/SlidingGroupTerm.hpp"

using namespace chute;

namespace {
RunResult runBead(const std::string& name, const std::vector<std::string>& sets) {
  return runCase(readCase(CHUTE_SOURCE_DIR "/cases/" + name + ".toml", sets), RunOptions{});
}
void report(const std::string& label, const RunResult& r) {
  std::printf(
      "%-40s %s t=%.2f  ellipse error %.3e = %.4f %% of the motion  energy drift %.3e (max "
      "kinetic %.3e)  steps %ld  Newton/step %.2f\n",
      label.c_str(), std::string(runStatusName(r.status)).c_str(), r.finalTime,
      r.reference->maxError, 100 * r.reference->relative(), r.energyMaxDrift, r.kineticMax, r.steps,
      r.newtonPerStep());
}
}  // namespace

TEST(EnergyMomentumCases, BeadOneAgainstTheEllipse) {
  const std::string em = "solver.integrator=\"energy_momentum\"";
  const auto e4 = runBead("bead_1", {em});
  const auto e20 = runBead("bead_1", {em, "solver.t_end=20"});
  const auto b4 = runBead("bead_1", {});
  const auto b20 = runBead("bead_1", {"solver.rho_inf=1", "solver.t_end=20"});
  report("bead_1 energy_momentum", e4);
  report("bead_1 bossak (shipped)", b4);
  report("bead_1 energy_momentum to 20 s", e20);
  report("bead_1 bossak rho_inf = 1 to 20 s", b20);
  ASSERT_EQ(e4.status, RunStatus::Completed);
  ASSERT_EQ(e20.status, RunStatus::Completed);
  EXPECT_LE(e4.reference->relative(), 5e-3);  // the shipped case's bound (test_verification)
  EXPECT_LE(e20.reference->relative(), 5e-3);
  // EM7 with EM11: the energy is conserved to Newton's tolerance.
  EXPECT_LE(e20.energyMaxDrift, 1e-9 * e20.kineticMax);
}

TEST(EnergyMomentumCases, BeadFiveAgainstTheEllipseWithItsChainCondensed) {
  const std::string em = "solver.integrator=\"energy_momentum\"";
  const auto e = runBead("bead_5", {em});
  const auto e20 = runBead("bead_5", {em, "solver.t_end=20"});
  const auto b = runBead("bead_5", {});
  report("bead_5 energy_momentum", e);
  report("bead_5 bossak (shipped)", b);
  report("bead_5 energy_momentum to 20 s", e20);
  long handovers = 0;
  for (long h : e20.handovers) handovers += h;
  std::printf("bead_5 energy_momentum to 20 s: %ld rope nodes passed\n", handovers);
  ASSERT_EQ(e.status, RunStatus::Completed);
  ASSERT_EQ(e20.status, RunStatus::Completed);
  EXPECT_LE(e.reference->relative(), 5e-3);  // the shipped case's bound (test_verification)
  EXPECT_LE(e.reference->relative(), 2.0 * b.reference->relative());
  EXPECT_GE(handovers, 20);                              // it crosses the rope's nodes
  EXPECT_LE(e20.energyMaxDrift, 1e-9 * e20.kineticMax);  // EM7 with EM12, across them
}

TEST(EnergyMomentumCases, OnlyAChainsOwnInnerNodesAreCondensed) {
  // EM12's rule on bead_5's model: condensable as shipped; not with a point mass, a support or a
  // cable on an inner node, nor with line density.
  const CaseSpec spec = readCase(CHUTE_SOURCE_DIR "/cases/bead_5.toml");
  auto condensable = [](const Model& m) {
    return SlidingGroupTerm(m, 0, SliderSearch::MaterialCoordinate).condensable();
  };
  EXPECT_TRUE(condensable(spec.model));
  const int inner = spec.model.groups[0].chain[2];
  Model withMass = spec.model;
  withMass.pointMass[inner] = 0.1;
  EXPECT_FALSE(condensable(withMass));
  Model supported = spec.model;
  supported.constraint[inner].fixed = {false, false, true};
  EXPECT_FALSE(condensable(supported));
  Model withCable = spec.model;
  withCable.cables.push_back({inner, withCable.groups[0].chain[0], 1.0, 0, -1});
  EXPECT_FALSE(condensable(withCable));
  Model heavy = spec.model;
  heavy.materials[heavy.groups[0].material].density = 1.0;
  EXPECT_FALSE(condensable(heavy));
}

TEST(EnergyMomentumCases, BeadOnARopeWithMassTurnsWhereCentralDifferencesTurnIt) {
  // EM13: a rope with mass, hand-overs located as events; RG8 at the midpoint.
  auto run = [](const std::vector<std::string>& sets) {
    auto all = sets;
    all.push_back("solver.t_end=2");
    return runCase(readCase(CHUTE_SOURCE_DIR "/bench/explicit/bead_rope_mass.toml", all),
                   RunOptions{});
  };
  const auto em = run({"solver.integrator=\"energy_momentum\"", "solver.dt=1e-3"});
  const auto cd = run({"solver.integrator=\"central_difference\""});
  ASSERT_EQ(em.status, RunStatus::Completed) << em.reason;
  ASSERT_EQ(cd.status, RunStatus::Completed) << cd.reason;
  auto turn = [](const RunResult& r) {
    const auto col =
        std::find(r.columns.begin(), r.columns.end(), "bead_slider.s") - r.columns.begin();
    double s = 0;
    for (const auto& row : r.rows) s = std::max(s, row[col]);
    return s;
  };
  long handovers = 0;
  for (long h : em.handovers) handovers += h;
  std::printf(
      "bead on a rope with mass: turns at s = %.5f (energy_momentum, %ld hand-overs) / "
      "%.5f (central differences) ft; the massless rope's ellipse turns at 1.581\n",
      turn(em), handovers, turn(cd));
  EXPECT_GE(handovers, 2);
  EXPECT_NEAR(turn(em), turn(cd), 1e-3 * turn(cd));
}
