// Plane-stress wrinkling law: tangent against central differences of the stress, continuity of
// the stress across the taut / wrinkled boundary.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

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

// Residual-only evaluations (explicit steps) leave the tangent unset: energy, stress and state
// are bit for bit those with the tangent, on random strains in every state, with and without
// wrinkling.
TEST(MembraneKernel, PlaneStressWithoutTangentIsBitForBitTheSame) {
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0, 0.02);
  int seen[3] = {0, 0, 0};
  for (int trial = 0; trial < 3000; ++trial) {
    const Vec3 e(n(rng), n(rng), n(rng));
    for (bool wrinkling : {true, false}) {
      const auto full = planeStressSVK(e, 4.32e6, 0.3, wrinkling, true);
      const auto res = planeStressSVK(e, 4.32e6, 0.3, wrinkling, false);
      EXPECT_EQ(res.state, full.state);
      EXPECT_EQ(res.energy, full.energy);
      EXPECT_EQ(res.stress, full.stress);
      ++seen[static_cast<int>(full.state)];
    }
  }
  EXPECT_GT(seen[0], 100);  // taut
  EXPECT_GT(seen[1], 100);  // wrinkled
  EXPECT_GT(seen[2], 100);  // slack
}
