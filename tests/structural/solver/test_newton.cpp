// Newton with the consistent tangent converges quadratically on a stiff sliding step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "case/CaseSpec.hpp"
#include "solver/GeneralizedAlpha.hpp"

using namespace chute;

namespace {
void checkQuadratic(const std::string& caseFile, double dt, int steps, double rhoInf) {
  CaseSpec spec = readCase(caseFile);
  StructuralSystem sys(spec.model, spec.solver.search);
  NewtonSettings ns;
  ns.tolDisplacement = 1e-13 * 100.0;  // iterate close to round-off to see the whole sequence
  GeneralizedAlpha integ(sys, rhoInf, AlphaScheme::Bossak, ns, dt, 0.0);
  StructuralState s = sys.initialState();
  integ.computeAcceleration(s);
  sys.commit(CommitPoint{s.x, s.t, 0.0, s.t});
  double bestOrder = 0.0;
  for (int k = 0; k < steps; ++k) {
    const NewtonReport rep = integ.tryStep(s, dt);
    ASSERT_TRUE(rep.converged) << rep.failure;
    if (k + 1 < steps) continue;
    std::printf("%s, step %d (dt = %g): residual norms", caseFile.c_str(), k + 1, dt);
    for (double r : rep.residualNorms) std::printf(" %.3e", r);
    std::printf("\n  update norms ");
    const auto& u = rep.updateNorms;
    for (double v : u) std::printf(" %.3e", v);
    // Observed order from consecutive residuals above round-off (1e-10 of the largest):
    // q = log(r[k+1] / r[k]) / log(r[k] / r[k-1]), 2 for Newton with a consistent tangent.
    const auto& r = rep.residualNorms;
    const double floor = 1e-10 * *std::max_element(r.begin(), r.end());
    for (size_t i = 2; i < r.size(); ++i) {
      if (r[i] < floor || r[i - 1] >= r[i - 2]) continue;
      bestOrder = std::max(bestOrder, std::log(r[i] / r[i - 1]) / std::log(r[i - 1] / r[i - 2]));
    }
    std::printf("\n  observed convergence order %.2f\n", bestOrder);
  }
  EXPECT_GE(bestOrder, 1.8);
}
}  // namespace

TEST(Newton, QuadraticOnAStiffSlidingStep) {
  // The bead on its very stiff rope, with a step ten times the shipped one.
  checkQuadratic(CHUTE_SOURCE_DIR "/cases/bead_1.toml", 0.1, 3, 0.9);
}

TEST(Newton, QuadraticOnThePulleyWithConfigurationDependentMass) {
  // Lumped mass and weight depend on where the rope sits on the pulley (F10, F11); their
  // derivatives are part of the tangent.
  checkQuadratic(CHUTE_SOURCE_DIR "/cases/pulley.toml", 0.1, 3, 0.9);
}
