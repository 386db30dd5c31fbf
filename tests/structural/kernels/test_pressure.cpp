// Follower pressure kernel: load stiffness against central differences, total force against
// pressure times area.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "kernels/PressureKernel.hpp"
#include "support/FiniteDifference.hpp"
#include "support/MembraneGeometry.hpp"

using namespace chute::kernels;
using chute::testing::deformed;
using chute::testing::fdJacobian;
using chute::testing::referenceNodes;
using chute::testing::relativeError;
using chute::testing::stack;
using chute::testing::unstack;

TEST(PressureKernel, LoadStiffnessMatchesFiniteDifferencesAndTotalsPressureTimesArea) {
  std::mt19937 rng(9);
  const double p = 3.7;
  double worst = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const auto x3 = deformed<3>(referenceNodes<3>(), 1.1, 0.9, 0.2, rng, 0.05);
    const auto x4 = deformed<4>(referenceNodes<4>(), 1.1, 0.9, 0.2, rng, 0.05);
    const auto l3 = pressureLoad<3>(x3, p, true);
    const auto l4 = pressureLoad<4>(x4, p, true);
    auto f3 = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
      return pressureLoad<3>(unstack<3>(y), p, false).force;
    };
    auto f4 = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
      return pressureLoad<4>(unstack<4>(y), p, false).force;
    };
    worst = std::max(worst, relativeError(l3.dForce, fdJacobian(f3, stack<3>(x3), 1e-6)));
    worst = std::max(worst, relativeError(l4.dForce, fdJacobian(f4, stack<4>(x4), 1e-6)));
    // Total force = p times the vector area.
    const Vec3 area3 = 0.5 * (x3[1] - x3[0]).cross(x3[2] - x3[0]);
    Vec3 total = Vec3::Zero();
    for (int i = 0; i < 3; ++i) total += l3.force.segment<3>(3 * i);
    EXPECT_LE((total - p * area3).norm(), 1e-12 * p * area3.norm());
  }
  std::printf("pressure load stiffness: worst relative error vs FD %.2e\n", worst);
  EXPECT_LE(worst, 1e-6);
}

// The residual-only triangle force (explicit steps) is the kernel's force on each node, bit for
// bit, on random triangles (stretched, sheared, tilted, inverted) and pressures of either sign.
TEST(PressureKernel, TriangleForceIsTheKernelsForceBitForBit) {
  std::mt19937 rng(21);
  std::normal_distribution<double> nd(0, 1);
  for (int trial = 0; trial < 500; ++trial) {
    std::array<Vec3, 3> x;
    for (auto& xi : x) xi = Vec3(nd(rng), nd(rng), nd(rng));
    if (trial == 0) x[2] = x[1];  // no area
    const double p = trial == 1 ? 0.0 : 5.0 * nd(rng);
    const auto load = pressureLoad<3>(x, p, false);
    const Vec3 f = trianglePressureForce(x, p);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(f, Vec3(load.force.segment<3>(3 * i))) << trial;
  }
}
