// Plane-stress wrinkling law: tangent against central differences of the stress, continuity of
// the stress across the taut / wrinkled boundary.
#include <gtest/gtest.h>

#include <algorithm>

#include "kernels/PlaneStressWrinkling.hpp"
#include "support/FiniteDifference.hpp"

using namespace chute::kernels;
using chute::testing::fdJacobian;
using chute::testing::relativeError;

TEST(MembraneKernel, PlaneStressTangentMatchesItsStressAcrossStates) {
  // The relaxed energy is C1: stress continuous across the state boundaries; tangent = dS/de.
  double worst = 0;
  for (const Vec3& e :
       {Vec3(0.02, 0.01, 0.004), Vec3(0.03, -0.02, 0.01), Vec3(0.01, -0.004, 0.002)}) {
    const auto ps = planeStressSVK(e, 1e6, 0.3, true);
    auto stress = [](const Eigen::VectorXd& y) -> Eigen::VectorXd {
      return planeStressSVK(Vec3(y), 1e6, 0.3, true).stress;
    };
    worst =
        std::max(worst, relativeError(ps.tangent, fdJacobian(stress, Eigen::VectorXd(e), 1e-9)));
  }
  EXPECT_LE(worst, 1e-6);
  // Continuity of the stress at the taut/wrinkled boundary E2 = -nu E1.
  const double nu = 0.3, e1 = 0.02;
  const auto below = planeStressSVK(Vec3(e1, -nu * e1 - 1e-12, 0), 1e6, nu, true);
  const auto above = planeStressSVK(Vec3(e1, -nu * e1 + 1e-12, 0), 1e6, nu, true);
  EXPECT_EQ(below.state, WrinkleState::Wrinkled);
  EXPECT_EQ(above.state, WrinkleState::Taut);
  EXPECT_LE((below.stress - above.stress).norm(), 1e-5 * above.stress.norm());
}
