// The energy-momentum force of the two-node cable / truss (docs/formulation.md EM3-EM6, EM8):
// the discrete-gradient property W(x_{n+1}) - W(x_n) = f_alg . (x_{n+1} - x_n) to round-off on
// both branches and across the tension-only kink, its tangent against finite differences, its
// momentum invariants and its limit x_{n+1} -> x_n (the ordinary force F2).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "kernels/CableDiscreteGradient.hpp"
#include "kernels/CableKernel.hpp"
#include "support/FiniteDifference.hpp"
#include "support/LineGeometry.hpp"

using namespace chute;
using namespace chute::kernels;
using chute::testing::fdJacobian;
using chute::testing::randomUnit;
using chute::testing::relativeError;
using chute::testing::rope;

namespace {
struct Pair {
  Vec3 a0, b0, a1, b1;
  double L;
};
// Two configurations of one element with strains e0 and e1 (random directions, random drift).
Pair randomPair(std::mt19937& rng, double e0, double e1) {
  std::uniform_real_distribution<double> u(-1, 1);
  Pair p;
  p.L = 0.7 + 0.3 * u(rng);
  p.a0 = Vec3(u(rng), u(rng), u(rng));
  p.b0 = p.a0 + p.L * std::sqrt(1 + 2 * e0) * randomUnit(rng);
  p.a1 = p.a0 + 0.2 * Vec3(u(rng), u(rng), u(rng));
  p.b1 = p.a1 + p.L * std::sqrt(1 + 2 * e1) * randomUnit(rng);
  return p;
}
Eigen::VectorXd stack(const Vec3& a, const Vec3& b) {
  Eigen::VectorXd x(6);
  x << a, b;
  return x;
}
}  // namespace

TEST(CableDiscreteGradient, EnergyDifferenceIsForceTimesMotion) {
  // EM4-EM5: exact for any W(E) -- same branch, the truss in compression, and a tension-only
  // cable going slack or taut within the step (with and without a compression ratio).
  std::mt19937 rng(3);
  double worst = 0.0;
  const std::vector<std::pair<double, double>> strains = {{1e-3, 2e-3},
                                                          {2e-3, 1e-3},
                                                          {-1e-3, 2e-3},
                                                          {3e-3, -1e-3},
                                                          {-2e-3, -1e-3},
                                                          {0.0, 1e-3},
                                                          {1e-4, 1e-4 * (1 + 1e-12)}};
  for (bool tensionOnly : {true, false})
    for (double ratio : {0.0, 0.1})
      for (auto [e0, e1] : strains)
        for (int trial = 0; trial < 20; ++trial) {
          const Pair p = randomPair(rng, e0, e1);
          auto mat = rope(tensionOnly);
          mat.compressionStiffnessRatio = ratio;
          const auto r = cableDiscreteGradient(p.a0, p.b0, p.a1, p.b1, p.L, mat, 0.0, false);
          const double dW = r.energy1 - r.energy0;
          const double work = r.force.dot(stack(p.a1, p.b1) - stack(p.a0, p.b0));
          // Round-off scale: the energies themselves and force x motion term by term.
          const double scale = std::max(
              {std::abs(r.energy0), std::abs(r.energy1),
               r.force.cwiseAbs().dot((stack(p.a1, p.b1) - stack(p.a0, p.b0)).cwiseAbs()), 1e-300});
          worst = std::max(worst, std::abs(dW - work) / scale);
          // The energies are the element's own (F1-F2 without the apex rounding).
          EXPECT_NEAR(r.energy1, cableForce(p.a1, p.b1, p.L, mat, false).energy,
                      1e-9 * std::max(r.energy1, 1e-12));
        }
  std::printf("discrete gradient: worst |dW - f.dx| / scale = %.2e\n", worst);
  EXPECT_LE(worst, 1e-12);
}

TEST(CableDiscreteGradient, TangentMatchesFiniteDifferenceOfForce) {
  std::mt19937 rng(5);
  double worst = 0.0;
  for (bool tensionOnly : {true, false})
    for (double chi : {0.0, 0.3})
      for (auto [e0, e1] :
           std::vector<std::pair<double, double>>{{1e-3, 3e-3}, {-1e-3, 2e-3}, {2e-3, -1e-3}})
        for (int trial = 0; trial < 20; ++trial) {
          const Pair p = randomPair(rng, e0, e1);
          const auto mat = rope(tensionOnly);
          const auto r = cableDiscreteGradient(p.a0, p.b0, p.a1, p.b1, p.L, mat, chi, true);
          auto force = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
            return cableDiscreteGradient(p.a0, p.b0, y.head<3>(), y.tail<3>(), p.L, mat, chi, false)
                .force;
          };
          worst =
              std::max(worst, relativeError(r.dForce, fdJacobian(force, stack(p.a1, p.b1), 1e-7)));
        }
  std::printf("discrete gradient: worst relative error d f / d x_{n+1} vs FD %.2e\n", worst);
  EXPECT_LE(worst, 1e-6);
}

TEST(CableDiscreteGradient, ConservesMomentaAndTendsToTheForce) {
  std::mt19937 rng(9);
  const Pair p = randomPair(rng, 1e-3, 4e-3);
  const auto mat = rope(false);
  const auto r = cableDiscreteGradient(p.a0, p.b0, p.a1, p.b1, p.L, mat, 0.2, false);
  // EM6: no net force, no net moment about any point for the midpoint lever arms.
  const Vec3 fa = r.force.head<3>(), fb = r.force.tail<3>();
  EXPECT_LE((fa + fb).norm(), 1e-14 * fa.norm());
  const Vec3 am = 0.5 * (p.a0 + p.a1), bm = 0.5 * (p.b0 + p.b1), o(0.3, -7.0, 2.0);
  EXPECT_LE(((am - o).cross(fa) + (bm - o).cross(fb)).norm(), 1e-13 * fa.norm() * 8.0);
  // x_{n+1} = x_n: the element's force F2.
  const auto same = cableDiscreteGradient(p.a1, p.b1, p.a1, p.b1, p.L, mat, 0.0, false);
  const auto f = cableForce(p.a1, p.b1, p.L, mat, false);
  EXPECT_LE(relativeError(same.force, f.force), 1e-13);
}

TEST(CableDiscreteGradient, DissipationNeverAddsEnergy) {
  // EM8: f_alg . dx = dW + chi c dE^2 / 2 >= dW.
  std::mt19937 rng(11);
  for (int trial = 0; trial < 50; ++trial) {
    const Pair p = randomPair(rng, 2e-3 * (trial % 3 - 1), 1e-3 * (trial % 5 - 2));
    const auto mat = rope(trial % 2 == 0);
    const auto r = cableDiscreteGradient(p.a0, p.b0, p.a1, p.b1, p.L, mat, 0.5, false);
    const Eigen::VectorXd dx = stack(p.a1, p.b1) - stack(p.a0, p.b0);
    const double work = r.force.dot(dx);
    const double c = std::max(cableEnergyBranches(p.L, mat).at(r.strain0),
                              cableEnergyBranches(p.L, mat).at(r.strain1));
    const double expected =
        r.energy1 - r.energy0 + 0.25 * c * (r.strain1 - r.strain0) * (r.strain1 - r.strain0);
    // Round-off scale: the energies and force x motion term by term (a step on the kink
    // between two strains of 1e-17 does work of that order).
    const double scale =
        std::max({r.energy0, r.energy1, r.force.cwiseAbs().dot(dx.cwiseAbs()), 1e-300});
    EXPECT_NEAR(work, expected, 1e-12 * scale);
    EXPECT_GE(work - (r.energy1 - r.energy0), -1e-12 * scale);
  }
}
