// Line drag kernel: position and velocity tangents against central differences; drag opposes the
// normal relative motion.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "kernels/LineDragKernel.hpp"
#include "support/FiniteDifference.hpp"

using namespace chute::kernels;
using chute::testing::fdJacobian;
using chute::testing::relativeError;

TEST(DragKernel, PositionAndVelocityTangentsMatchFiniteDifferences) {
  std::mt19937 rng(2);
  std::normal_distribution<double> n(0, 1);
  const double c = 0.5 * 0.0023769 * 1.2 * 0.03;
  double worstX = 0, worstV = 0;
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::VectorXd x(6), v(6);
    for (int k = 0; k < 6; ++k) x[k] = n(rng), v[k] = 20 * n(rng);
    const Vec3 wind(3, -2, 1);
    auto at = [&](const Eigen::VectorXd& xx, const Eigen::VectorXd& vv, bool t) {
      return lineDrag(xx.head<3>(), xx.tail<3>(), vv.head<3>(), vv.tail<3>(), wind, c, t);
    };
    const auto d = at(x, v, true);
    auto fx = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd { return at(y, v, false).residual; };
    auto fv = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd { return at(x, y, false).residual; };
    worstX = std::max(worstX, relativeError(d.dPosition, fdJacobian(fx, x, 1e-6)));
    worstV = std::max(worstV, relativeError(d.dVelocity, fdJacobian(fv, v, 1e-5)));
    // Drag opposes the normal relative motion.
    const Vec3 e = (x.tail<3>() - x.head<3>()).normalized();
    Vec3 vr = 0.5 * (v.head<3>() + v.tail<3>()) - wind;
    vr -= vr.dot(e) * e;
    EXPECT_GT(d.residual.head<3>().dot(vr), 0.0);
  }
  std::printf("line drag: worst relative error dr/dx %.2e, dr/dv %.2e\n", worstX, worstV);
  EXPECT_LE(worstX, 1e-6);
  EXPECT_LE(worstV, 1e-6);
}

// The residual-only variant (explicit steps) is the kernel's residual on both nodes, bit for bit:
// random elements, velocities and winds, and the degenerate ones (no length, no drag).
TEST(DragKernel, NodeResidualIsTheKernelsResidualBitForBit) {
  std::mt19937 rng(5);
  std::normal_distribution<double> n(0, 1);
  for (int trial = 0; trial < 500; ++trial) {
    const Vec3 xa(n(rng), n(rng), n(rng)), va(20 * n(rng), 20 * n(rng), 20 * n(rng));
    const Vec3 xb = trial == 0 ? xa : Vec3(n(rng), n(rng), n(rng));
    const Vec3 vb(20 * n(rng), 20 * n(rng), 20 * n(rng)), wind(9 * n(rng), 9 * n(rng), 9 * n(rng));
    const double c = trial == 1 ? 0.0 : 0.5 * 0.0023769 * 1.2 * 0.03 * std::exp(n(rng));
    const auto d = lineDrag(xa, xb, va, vb, wind, c, false);
    const Vec3 r = lineDragNodeResidual(xa, xb, va, vb, wind, c);
    EXPECT_EQ(r, Vec3(d.residual.head<3>())) << trial;
    EXPECT_EQ(r, Vec3(d.residual.tail<3>())) << trial;
  }
}

// LD1 evaluated as the projector form P = I - e e^T, u = P v, (c l / 2) |u| u, against the
// kernel's one-root form (LineDragKernel.hpp): the same to round-off of the largest term, |v|^2.
TEST(DragKernel, ResidualIsTheProjectorFormToRoundOff) {
  std::mt19937 rng(13);
  std::normal_distribution<double> n(0, 1);
  double worst = 0.0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 xa(n(rng), n(rng), n(rng)), xb(n(rng), n(rng), n(rng));
    const Vec3 va(20 * n(rng), 20 * n(rng), 20 * n(rng)), vb(20 * n(rng), 20 * n(rng), 20 * n(rng));
    const Vec3 wind(9 * n(rng), 9 * n(rng), 9 * n(rng));
    const double c = 0.5 * 0.0023769 * 1.2 * 0.03;
    const Vec3 d = xb - xa;
    const double l = d.norm();
    const Vec3 e = d / l;
    const Mat3 P = Mat3::Identity() - e * e.transpose();
    const Vec3 v = 0.5 * (va + vb) - wind;
    const Vec3 u = P * v;
    const Vec3 r = 0.5 * c * l * u.norm() * u;
    const double scale = 0.5 * c * l * v.squaredNorm();
    const Vec3 got = lineDragNodeResidual(xa, xb, va, vb, wind, c);
    worst = std::max(worst, (got - r).norm() / scale);
    EXPECT_LE((got - r).norm(), 1e-14 * scale) << trial;
    EXPECT_EQ(Vec3(lineDrag(xa, xb, va, vb, wind, c, true).residual.head<3>()), got) << trial;
  }
  std::printf(
      "line drag: one-root form against the projector form, largest difference %.3g of "
      "c l |v|^2 / 2 (bound 1e-14)\n",
      worst);
}
