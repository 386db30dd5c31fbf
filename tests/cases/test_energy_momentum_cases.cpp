// solver.integrator = "energy_momentum" on the shipped bead of one sliding element
// (cases/bead_1.toml): a bead on a massless, very stiff rope, against the ellipse ODE of the
// inextensible rope (docs/formulation.md section 8), with Bossak (the shipped rho_inf = 0.9, and
// rho_inf = 1) beside it. bead_5 (five elements, hand-overs at rope nodes) is refused by the
// case reader: its first hand-over's step fails (docs/formulation.md section 10).
#include <gtest/gtest.h>

#include <cmath>

#include "app/RunCase.hpp"
#include "case/CaseError.hpp"
#include "case/CaseSpec.hpp"

using namespace chute;

namespace {
RunResult runBead(const std::string& name, const std::vector<std::string>& sets) {
  return runCase(readCase(CHUTE_SOURCE_DIR "/cases/" + name + ".toml", sets), RunOptions{});
}
void report(const std::string& label, const RunResult& r) {
  std::printf(
      "%-40s %s t=%.2f  ellipse error %.3e = %.4f %% of the motion  energy drift %.3e (max "
      "kinetic %.3e)  steps %ld  Newton/step %.2f\n",
      label.c_str(), r.status.c_str(), r.finalTime, r.reference->maxError,
      100 * r.reference->relative(), r.energyMaxDrift, r.kineticMax, r.steps, r.newtonPerStep());
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
  ASSERT_EQ(e4.status, "completed");
  ASSERT_EQ(e20.status, "completed");
  EXPECT_LE(e4.reference->relative(), 5e-3);  // the shipped case's bound (test_verification)
  EXPECT_LE(e20.reference->relative(), 5e-3);
  // EM7 with EM11: the energy is conserved to Newton's tolerance.
  EXPECT_LE(e20.energyMaxDrift, 1e-9 * e20.kineticMax);
}

TEST(EnergyMomentumCases, BeadFiveIsRefused) {
  EXPECT_THROW(
      readCase(CHUTE_SOURCE_DIR "/cases/bead_5.toml", {"solver.integrator=\"energy_momentum\""}),
      CaseError);
}
