// The energy-momentum force of the frictionless active sliding element (docs/formulation.md
// EM11): the discrete-gradient property W(x_{n+1}) - W(x_n) = f_alg . (x_{n+1} - x_n) to
// round-off (taut, slack, across the kink, the slider moving along the cable), the tangent
// d f_alg / d x_{n+1} against finite differences, the momentum invariants and the limit
// x_{n+1} -> x_n (the force F8).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "kernels/SlidingCableKernel.hpp"
#include "kernels/SlidingDiscreteGradient.hpp"
#include "support/FiniteDifference.hpp"
#include "support/LineGeometry.hpp"

using namespace chute;
using namespace chute::kernels;
using chute::testing::fdJacobian;
using chute::testing::relativeError;
using chute::testing::rope;

namespace {
using Nodes = std::array<Vec3, 3>;
// Ends 1 and 2 and the slider 3 placed so that the element has total length (1 + stretch) L.
Nodes place(std::mt19937& rng, double L, double stretch, double split) {
  std::uniform_real_distribution<double> u(-1, 1);
  const Vec3 a(u(rng), u(rng), u(rng)), b = a + Vec3(0.6 * L, 0.1 * u(rng), 0.1 * u(rng));
  // Slider below the chord, scaled so that |x3 - a| + |x3 - b| = (1 + stretch) L.
  const Vec3 dir = Vec3(0.0, 0.3 * u(rng), -1.0).normalized();
  const Vec3 base = a + split * (b - a);
  double lo = 0.0, hi = 10.0 * L;
  for (int i = 0; i < 200; ++i) {
    const double h = 0.5 * (lo + hi);
    const Vec3 s = base + h * dir;
    ((s - a).norm() + (s - b).norm() < (1 + stretch) * L ? lo : hi) = h;
  }
  return {a, b, base + lo * dir};
}
Eigen::VectorXd stack(const Nodes& x) {
  Eigen::VectorXd v(9);
  v << x[0], x[1], x[2];
  return v;
}
Nodes unstack(const Eigen::VectorXd& v) {
  return {v.segment<3>(0), v.segment<3>(3), v.segment<3>(6)};
}
}  // namespace

TEST(SlidingDiscreteGradient, EnergyDifferenceIsForceTimesMotionAndTangentIsConsistent) {
  std::mt19937 rng(21);
  double worstDG = 0, worstK = 0;
  const std::vector<std::array<double, 4>> steps = {{1e-3, 0.3, 2e-3, 0.35},
                                                    {2e-3, 0.5, -1e-3, 0.45},
                                                    {-1e-3, 0.2, 1e-3, 0.25},
                                                    {1e-3, 0.4, 1e-3 * (1 + 1e-10), 0.4000001}};
  for (bool tensionOnly : {true, false})
    for (double chi : {0.0, 0.4})
      for (const auto& st : steps)
        for (int trial = 0; trial < 10; ++trial) {
          const double L = 1.0 + 0.1 * trial;
          const unsigned seed = rng();
          std::mt19937 r0(seed), r1(seed);
          const Nodes x0 = place(r0, L, st[0], st[1]), x1 = place(r1, L, st[2], st[3]);
          const auto mat = rope(tensionOnly);
          const auto r = slidingDiscreteGradient(x0, x1, L, mat, chi, true);
          if (chi == 0.0) {
            const Eigen::VectorXd dx = stack(x1) - stack(x0);
            const double scale =
                std::max({r.energy0, r.energy1, r.force.cwiseAbs().dot(dx.cwiseAbs()), 1e-300});
            worstDG = std::max(worstDG, std::abs(r.energy1 - r.energy0 - r.force.dot(dx)) / scale);
            EXPECT_NEAR(r.energy1, slidingForce(x1[0], x1[1], x1[2], L, mat, false).energy,
                        1e-9 * std::max(r.energy1, 1e-12));
          }
          auto force = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
            return slidingDiscreteGradient(x0, unstack(y), L, mat, chi, false).force;
          };
          worstK = std::max(worstK, relativeError(r.dForce, fdJacobian(force, stack(x1), 1e-7)));
        }
  std::printf(
      "sliding discrete gradient: worst |dW - f.dx| / scale %.2e, d f / d x_{n+1} vs FD %.2e\n",
      worstDG, worstK);
  EXPECT_LE(worstDG, 1e-12);
  EXPECT_LE(worstK, 1e-6);
}

TEST(SlidingDiscreteGradient, ConservesMomentaAndTendsToTheForce) {
  std::mt19937 r0(4), r1(4);
  const Nodes x0 = place(r0, 1.0, 1e-3, 0.3), x1 = place(r1, 1.0, 3e-3, 0.4);
  const auto r = slidingDiscreteGradient(x0, x1, 1.0, rope(), 0.2, false);
  Vec3 F = Vec3::Zero(), M = Vec3::Zero();
  for (int i = 0; i < 3; ++i) {
    F += r.force.segment<3>(3 * i);
    M += (0.5 * (x0[i] + x1[i])).cross(Vec3(r.force.segment<3>(3 * i)));
  }
  EXPECT_LE(F.norm(), 1e-13 * r.force.norm());
  EXPECT_LE(M.norm(), 1e-12 * r.force.norm());
  const auto same = slidingDiscreteGradient(x1, x1, 1.0, rope(), 0.0, false);
  EXPECT_LE(relativeError(same.force, slidingForce(x1[0], x1[1], x1[2], 1.0, rope(), false).force),
            1e-12);
}
