// The energy-momentum force of a condensed massless chain (docs/formulation.md EM12): the
// discrete-gradient property W(x_{n+1}) - W(x_n) = f . (x_{n+1} - x_n) to round-off for paths of
// 2 to 5 nodes (taut, slack, across the kink), the tangent against finite differences, momenta,
// equality with EM11 for one slider, and the placement of the chain's nodes along the path.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "kernels/PolylineDiscreteGradient.hpp"
#include "kernels/SlidingDiscreteGradient.hpp"
#include "support/FiniteDifference.hpp"
#include "support/LineGeometry.hpp"

using namespace chute;
using namespace chute::kernels;
using chute::testing::fdJacobian;
using chute::testing::relativeError;
using chute::testing::rope;

namespace {
// A zig-zag path of n nodes whose length is (1 + stretch) L.
std::vector<Vec3> path(std::mt19937& rng, int n, double L, double stretch) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3> p(n);
  p[0] = Vec3(u(rng), u(rng), u(rng));
  double len = 0.0;
  for (int k = 1; k < n; ++k) {
    p[k] = p[k - 1] + Vec3(1.0, 0.4 * u(rng), 0.4 * u(rng));
    len += (p[k] - p[k - 1]).norm();
  }
  const double scale = (1 + stretch) * L / len;
  for (int k = 1; k < n; ++k) p[k] = p[0] + scale * (p[k] - p[0]);
  return p;
}
Eigen::VectorXd stack(const std::vector<Vec3>& p) {
  Eigen::VectorXd v(3 * p.size());
  for (size_t k = 0; k < p.size(); ++k) v.segment<3>(3 * k) = p[k];
  return v;
}
std::vector<Vec3> unstack(const Eigen::VectorXd& v) {
  std::vector<Vec3> p(v.size() / 3);
  for (size_t k = 0; k < p.size(); ++k) p[k] = v.segment<3>(3 * k);
  return p;
}
}  // namespace

TEST(PolylineDiscreteGradient, EnergyDifferenceIsForceTimesMotionTangentAndMomenta) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  double worstDG = 0, worstK = 0, worstP = 0, worstM = 0;
  for (int n = 2; n <= 5; ++n)
    for (double chi : {0.0, 0.3})
      for (const auto& st : std::vector<std::array<double, 2>>{
               {1e-3, 2e-3}, {2e-3, -1e-3}, {-1e-3, -5e-4}, {1e-3, 1e-3 * (1 + 1e-9)}})
        for (int trial = 0; trial < 8; ++trial) {
          const double L = 1.0 + 0.2 * trial;
          const auto mat = rope(trial % 2 == 0);
          const auto x0 = path(rng, n, L, st[0]);
          auto x1 = path(rng, n, L, st[1]);
          for (auto& p : x1) p += Vec3(0.01 * u(rng), 0.0, 0.0);  // any motion between them
          const auto r = polylineDiscreteGradient(x0, x1, L, mat, chi, true);
          const double dW = r.energy1 - r.energy0;
          const double work = r.force.dot(stack(x1) - stack(x0));
          // Exact for chi = 0; with chi the dissipation chi c (dE)^2 / 2 is added.
          const double diss = chi > 0 ? work - dW : 0.0;
          EXPECT_GE(diss, -1e-12 * std::abs(work));
          if (chi == 0.0)
            worstDG = std::max(worstDG, std::abs(dW - work) / std::max(std::abs(dW), 1e-300));
          auto ofX1 = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
            return polylineDiscreteGradient(x0, unstack(y), L, mat, chi, false).force;
          };
          worstK = std::max(worstK, relativeError(r.dForce, fdJacobian(ofX1, stack(x1), 1e-7 * L),
                                                  1e-9 * r.dForce.cwiseAbs().maxCoeff()));
          Vec3 sum = Vec3::Zero(), moment = Vec3::Zero();
          for (int k = 0; k < n; ++k) {
            sum += r.force.segment<3>(3 * k);
            moment += (0.5 * (x0[k] + x1[k])).cross(Vec3(r.force.segment<3>(3 * k)));
          }
          worstP = std::max(worstP, sum.norm() / r.force.norm());
          worstM = std::max(worstM, moment.norm() / (r.force.norm() * (x1.back() - x1[0]).norm()));
        }
  std::printf("worst |dW - f.dx| / |dW| %.2e, tangent vs FD %.2e, |sum f| %.2e, |sum x x f| %.2e\n",
              worstDG, worstK, worstP, worstM);
  EXPECT_LE(worstDG, 1e-9);
  EXPECT_LE(worstK, 1e-5);
  EXPECT_LE(worstP, 1e-13);
  EXPECT_LE(worstM, 1e-13);
}

TEST(PolylineDiscreteGradient, IsEM11ForOneSlider) {
  std::mt19937 rng(8);
  double worst = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const auto mat = rope();
    const auto p0 = path(rng, 3, 1.3, 1e-3), p1 = path(rng, 3, 1.3, 2e-3);
    // Path (end 1, slider, end 2) against EM11's node order (end 1, end 2, slider).
    const auto a = polylineDiscreteGradient(p0, p1, 1.3, mat, 0.2, true);
    const auto b =
        slidingDiscreteGradient({p0[0], p0[2], p0[1]}, {p1[0], p1[2], p1[1]}, 1.3, mat, 0.2, true);
    const int order[3] = {0, 2, 1};
    for (int i = 0; i < 3; ++i) {
      worst =
          std::max(worst, (a.force.segment<3>(3 * order[i]) - b.force.segment<3>(3 * i)).norm() /
                              b.force.norm());
      for (int j = 0; j < 3; ++j)
        worst = std::max(worst, (a.dForce.block<3, 3>(3 * order[i], 3 * order[j]) -
                                 b.dForce.block<3, 3>(3 * i, 3 * j))
                                        .norm() /
                                    b.dForce.norm());
    }
  }
  std::printf("EM12 with one slider against EM11: %.2e\n", worst);
  EXPECT_LE(worst, 1e-14);
}

TEST(PolylineDiscreteGradient, ChainNodesSitAtTheirArcFraction) {
  std::mt19937 rng(13);
  double worstPos = 0, worstD = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const int n = 2 + trial % 4;
    const auto P = path(rng, n, 2.0, 1e-3);
    const double phi = (trial + 0.37) / 31.0;
    Eigen::MatrixXd dX;
    const Vec3 X = polylinePoint(P, phi, &dX);
    // Arc length to X along the path.
    double total = 0, before = 0;
    for (int k = 0; k + 1 < n; ++k) total += (P[k + 1] - P[k]).norm();
    bool found = false;
    for (int k = 0; k + 1 < n && !found; ++k) {
      const Vec3 d = P[k + 1] - P[k];
      const double t = (X - P[k]).dot(d) / d.squaredNorm();
      if (t >= -1e-12 && t <= 1 + 1e-12 && (P[k] + t * d - X).norm() < 1e-12) {
        worstPos = std::max(worstPos, std::abs(before + t * d.norm() - phi * total));
        found = true;
      }
      before += d.norm();
    }
    EXPECT_TRUE(found);
    auto point = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
      return polylinePoint(unstack(y), phi, nullptr);
    };
    worstD = std::max(worstD, relativeError(dX, fdJacobian(point, stack(P), 1e-7)));
  }
  std::printf("placement: arc-length error %.2e, derivative vs FD %.2e\n", worstPos, worstD);
  EXPECT_LE(worstPos, 1e-12);
  EXPECT_LE(worstD, 1e-6);
}
