// Finite-difference and invariant checks of the sliding-element kernel (F6-F11) at many random
// configurations: taut, near-slack, slider near an end (RG1).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstring>
#include <random>

#include "kernels/CableKernel.hpp"
#include "kernels/SlidingCableKernel.hpp"
#include "support/FiniteDifference.hpp"
#include "support/LineGeometry.hpp"

using namespace chute;
using namespace chute::kernels;
using chute::testing::fdGradient;
using chute::testing::fdJacobian;
using chute::testing::randomUnit;
using chute::testing::relativeError;
using chute::testing::rope;

namespace {

// A sliding configuration: ends x1, x2 and slider x3 such that l1 / l = split and l = L (1 + s).
struct SlidingConfig {
  Vec3 x1, x2, x3;
  double L;
};

SlidingConfig makeSliding(std::mt19937& rng, double split, double strain) {
  std::uniform_real_distribution<double> u(0.2, 3.0);
  SlidingConfig c;
  c.L = u(rng);
  const double l = c.L * std::sqrt(1 + 2 * strain);  // eps = (l^2 - L^2) / 2L^2
  c.x3 = Vec3(u(rng), -u(rng), u(rng));
  c.x1 = c.x3 - split * l * randomUnit(rng);
  c.x2 = c.x3 - (1 - split) * l * randomUnit(rng);
  return c;
}

Eigen::VectorXd stack(const SlidingConfig& c) {
  Eigen::VectorXd x(9);
  x << c.x1, c.x2, c.x3;
  return x;
}

// Node coordinates of a stacked 9-vector (node 1, node 2, slider).
std::array<Vec3, 3> split3(const Eigen::VectorXd& y) {
  return {y.segment<3>(0), y.segment<3>(3), y.segment<3>(6)};
}

// The sliding element's force and energy as functions of the stacked coordinates.
auto slidingForceOf(double L, const LineMaterial& mat) {
  return [L, mat](const Eigen::VectorXd& y) -> Eigen::VectorXd {
    const auto p = split3(y);
    return slidingForce(p[0], p[1], p[2], L, mat, false).force;
  };
}
auto slidingEnergyOf(double L, const LineMaterial& mat) {
  return [L, mat](const Eigen::VectorXd& y) {
    const auto p = split3(y);
    return slidingForce(p[0], p[1], p[2], L, mat, false).energy;
  };
}

struct Case {
  const char* name;
  double split;   // l1 / l
  double strain;  // Green-Lagrange strain of the configuration
};

class SlidingKernelFD : public ::testing::TestWithParam<Case> {};

}  // namespace

TEST_P(SlidingKernelFD, TangentInertiaAndGravityMatchFiniteDifferences) {
  const Case cs = GetParam();
  std::mt19937 rng(42);
  const auto mat = rope();
  const Vec3 g(0.3, -1.0, -9.81);
  double worstK = 0, worstF = 0, worstM[2] = {0, 0}, worstG = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const auto c = makeSliding(rng, cs.split, cs.strain);
    const Eigen::VectorXd x = stack(c);
    const double L = c.L;
    // Step well below the shortest part (the stencil must not reach the slider apex) and below
    // the strain (it must not cross the slack kink at eps = 0).
    const double h = std::min(1e-5 * std::min(cs.split, 1 - cs.split), 1e-3 * cs.strain) * L;
    const auto r = slidingForce(c.x1, c.x2, c.x3, L, mat, true);
    const auto force = slidingForceOf(L, mat);
    const auto energy = slidingEnergyOf(L, mat);
    worstK = std::max(worstK, relativeError(r.stiffness, fdJacobian(force, x, h)));
    worstF = std::max(worstF, relativeError(r.force, fdGradient(energy, x, h)));

    Vec9 a;
    a << 1.0, -2.0, 0.5, 3.0, 0.1, -1.0, -0.7, 2.2, 0.4;
    for (auto kind : {MassKind::Lumped, MassKind::Consistent}) {
      const auto in = slidingInertia(c.x1, c.x2, c.x3, a, L, mat, kind);
      auto inertia = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
        const auto p = split3(y);
        return slidingInertia(p[0], p[1], p[2], a, L, mat, kind).force;
      };
      worstM[kind == MassKind::Consistent] =
          std::max(worstM[kind == MassKind::Consistent],
                   relativeError(in.dForce, fdJacobian(inertia, x, h), 1e-12 * in.force.norm()));
    }
    const auto gr = slidingGravity(c.x1, c.x2, c.x3, L, mat, g);
    auto gravity = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
      const auto p = split3(y);
      return slidingGravity(p[0], p[1], p[2], L, mat, g).force;
    };
    worstG = std::max(worstG,
                      relativeError(gr.dForce, fdJacobian(gravity, x, h), 1e-12 * gr.force.norm()));
  }
  std::printf(
      "%s: worst relative error  K vs FD(f) %.2e  f vs FD(W) %.2e  "
      "dM/dx lumped %.2e consistent %.2e  dFg/dx %.2e\n",
      cs.name, worstK, worstF, worstM[0], worstM[1], worstG);
  EXPECT_LE(worstK, 1e-6);
  EXPECT_LE(worstF, 1e-6);
  EXPECT_LE(worstM[0], 1e-6);
  EXPECT_LE(worstM[1], 1e-6);
  EXPECT_LE(worstG, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Configurations, SlidingKernelFD,
                         ::testing::Values(Case{"taut", 0.37, 0.02}, Case{"near_slack", 0.6, 1e-5},
                                           Case{"slider_near_end_1", 1e-3, 0.01},
                                           Case{"slider_near_end_2", 1 - 1e-3, 0.01},
                                           Case{"strongly_stretched", 0.5, 0.4}),
                         [](const auto& p) { return std::string(p.param.name); });

TEST(SlidingKernel, SliderOnTheStraightLineEqualsTheCable) {
  const auto mat = rope();
  const Vec3 x1(0, 0, 0), x2(1.2, 0.3, -0.4);
  for (double s : {0.1, 0.5, 0.93}) {
    const Vec3 x3 = x1 + s * (x2 - x1);
    const auto sl = slidingForce(x1, x2, x3, 1.1, mat, false);
    const auto cb = cableForce(x1, x2, 1.1, mat, false);
    EXPECT_NEAR(sl.energy, cb.energy, 1e-12 * cb.energy);
    // No net force on a slider that sits on a straight cable.
    EXPECT_LE(sl.force.segment<3>(6).norm(), 1e-9 * cb.force.norm());
    EXPECT_LE((sl.force.head<3>() - cb.force.head<3>()).norm(), 1e-9 * cb.force.norm());
  }
}

TEST(SlidingKernel, MassAndWeightAreInvariantAsTheSliderMoves) {
  const auto mat = rope();
  const Vec3 x1(0, 0, 0), x2(2, 0, 0), g(0, 0, -10);
  const double L = 2.2;
  const double mTotal = mat.density * mat.area * L;
  Vec9 ones;
  for (int k = 0; k < 9; ++k) ones[k] = (k % 3 == 2) ? 1.0 : 0.0;  // unit z acceleration
  for (double s = 0.0; s <= 1.0; s += 0.05) {
    const Vec3 x3(2 * s, 0, -0.3);
    for (auto kind : {MassKind::Lumped, MassKind::Consistent}) {
      const auto in = slidingInertia(x1, x2, x3, ones, L, mat, kind);
      // Sum of z inertia forces under a uniform unit z acceleration is the total mass.
      double mz = 0;
      for (int n = 0; n < 3; ++n) mz += in.force[3 * n + 2];
      EXPECT_NEAR(mz, mTotal, 1e-13 * mTotal) << "s=" << s;
    }
    const auto consistent = slidingInertia(x1, x2, x3, ones, L, mat, MassKind::Consistent);
    const auto lumped = slidingInertia(x1, x2, x3, ones, L, mat, MassKind::Lumped);
    EXPECT_LE((consistent.mass.rowwise().sum() - lumped.mass.diagonal()).norm(), 1e-13);
    const auto gr = slidingGravity(x1, x2, x3, L, mat, g);
    const double wz = gr.force[2] + gr.force[5] + gr.force[8];
    EXPECT_NEAR(wz, -10 * mTotal, 1e-12 * mTotal) << "s=" << s;
  }
}

TEST(SlidingKernel, SliderOnAnEndNodeIsExactForThePairAndRegularOnlyWithinTheApexRadius) {
  const auto mat = rope();
  const Vec3 x1(0, 0, 0), x2(1.5, 0, 0);
  const double L = 1.4, r = kApexFraction * L;
  for (const Vec3& x3 : {x1, x2}) {
    const auto sl = slidingForce(x1, x2, x3, L, mat, true);
    ASSERT_TRUE(sl.force.allFinite());
    ASSERT_TRUE(sl.stiffness.allFinite());
    const auto cb = cableForce(x1, x2, L, mat, false);
    // The coincident node pair together receives the cable's end force (up to the r/2 the
    // regularised apex adds to the length).
    const Vec3 end1 = sl.force.head<3>() + (x3 == x1 ? Vec3(sl.force.tail<3>()) : Vec3::Zero());
    const Vec3 end2 = sl.force.segment<3>(3) + (x3 == x2 ? Vec3(sl.force.tail<3>()) : Vec3::Zero());
    EXPECT_LE((end1 - cb.force.head<3>()).norm(), 2e-5 * cb.force.norm());
    EXPECT_LE((end2 - cb.force.tail<3>()).norm(), 2e-5 * cb.force.norm());
    EXPECT_NEAR(sl.length, cb.length + 0.5 * r, 1e-15);
  }
  // Outside the apex radius the part lengths are exact.
  const Vec3 x3 = x1 + Vec3(0, 1.01 * r, 0);
  EXPECT_NEAR(slidingForce(x1, x2, x3, L, mat, false).segmentLength[0], 1.01 * r, 1e-20);
}

TEST(SlidingKernel, TangentMatchesFiniteDifferencesInsideTheApexRadius) {
  const auto mat = rope();
  const double L = 1.4, r = kApexFraction * L;
  const Vec3 u = Vec3(0.3, -0.5, 0.8).normalized();
  double worstK = 0, worstF = 0;
  for (double frac : {0.0, 0.3, 0.8}) {
    // Slider within the apex radius of node 1; node 2 far enough for a taut element.
    Eigen::VectorXd x(9);
    x << 0, 0, 0, 1.5, 0.2, -0.1, (frac * r * u).eval();
    const auto force = slidingForceOf(L, mat);
    const auto energy = slidingEnergyOf(L, mat);
    const auto p = split3(x);
    const auto res = slidingForce(p[0], p[1], p[2], L, mat, true);
    const double h = 1e-2 * r;  // the stencil stays inside the apex radius
    // Columns of node 1 and the slider (coordinates ~r: no round-off in x + h); node 2's columns
    // are those of an ordinary part, checked by the other tests.
    const Eigen::MatrixXd Kfd = fdJacobian(force, x, h);
    const Eigen::VectorXd ffd = fdGradient(energy, x, h);
    for (int c : {0, 1, 2, 6, 7, 8})
      worstK = std::max(worstK, relativeError(res.stiffness.col(c), Kfd.col(c)));
    // The element energy differences are round-off bound here (the long part dominates the
    // length), so check the regularised part length itself: gradient against its value.
    const Vec3 d = frac * r * u + Vec3(0.1, 0.2, -0.3) * r;
    const PartLength pl = partLength(d, r);
    auto len = [&](const Eigen::VectorXd& y) { return partLength(Vec3(y), r).length; };
    auto grad = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
      return partLength(Vec3(y), r).gradient;
    };
    worstF =
        std::max(worstF, relativeError(pl.gradient, fdGradient(len, Eigen::VectorXd(d), 1e-3 * r)));
    worstK =
        std::max(worstK, relativeError(pl.hessian, fdJacobian(grad, Eigen::VectorXd(d), 1e-3 * r)));
  }
  std::printf("slider within the apex radius: K vs FD(f) %.2e  part length gradient vs FD %.2e\n",
              worstK, worstF);
  EXPECT_LE(worstK, 1e-6);
  EXPECT_LE(worstF, 1e-6);
}

// Residual-only evaluations (explicit steps) skip the Hessians and the stiffness: everything else
// is bit for bit the evaluation with the tangent, taut, slack and with the slider at or near an
// end (inside the apex radius). slidingInertiaForce is slidingInertia's force, bit for bit.
TEST(SlidingKernel, ResidualOnlyIsTheFullEvaluationBitForBit) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> n(0, 1);
  const auto mat = rope();
  for (int trial = 0; trial < 300; ++trial) {
    const double split = trial % 4 == 0 ? 1e-9 : (trial % 4 == 1 ? 1.0 : u(rng));
    const double strain = trial % 2 == 0 ? 0.02 * u(rng) : -0.1 * u(rng);
    auto c = makeSliding(rng, split, strain);
    if (trial % 7 == 0) c.x3 = c.x1;  // on an end node
    const auto full = slidingForce(c.x1, c.x2, c.x3, c.L, mat, true);
    const auto res = slidingForce(c.x1, c.x2, c.x3, c.L, mat, false);
    EXPECT_EQ(res.length, full.length);
    EXPECT_EQ(res.strain, full.strain);
    EXPECT_EQ(res.axialForce, full.axialForce);
    EXPECT_EQ(res.energy, full.energy);
    EXPECT_EQ(res.segmentLength, full.segmentLength);
    EXPECT_EQ(res.dLength, full.dLength);
    EXPECT_EQ(res.force, full.force) << trial;
    // slidingForceOnly, the explicit path's: the same bits, signs of zeros included, taut and
    // slack, on both materials (the compression stiffness of a line that is not tension-only),
    // at an exactly zero strain, on an end node (the apex's quadratic) and with no length at all.
    for (bool tension : {true, false}) {
      const auto m = rope(tension);
      auto same = [&](const SlidingConfig& q) {
        const Vec9 only = slidingForceOnly(q.x1, q.x2, q.x3, q.L, m);
        const Vec9 whole = slidingForce(q.x1, q.x2, q.x3, q.L, m, true).force;
        EXPECT_EQ(std::memcmp(only.data(), whole.data(), sizeof(double) * 9), 0) << trial;
      };
      same(c);
      SlidingConfig zero = c;  // on the straight line, at exactly the reference length
      zero.x1 = Vec3::Zero(), zero.x2 = Vec3(c.L, 0.0, 0.0), zero.x3 = Vec3(0.25 * c.L, 0.0, 0.0);
      if (trial == 3) same(zero);
      SlidingConfig none = c;  // all three nodes at one point
      none.x2 = none.x3 = none.x1;
      if (trial == 5) same(none);
    }
    Vec9 a;
    for (int k = 0; k < 9; ++k) a[k] = n(rng);
    if (trial == 0) a.setOnes();  // the explicit path's M(x) 1
    for (auto kind : {MassKind::Lumped, MassKind::Consistent}) {
      const auto in = slidingInertia(c.x1, c.x2, c.x3, a, c.L, mat, kind);
      EXPECT_EQ(slidingInertiaForce(c.x1, c.x2, c.x3, a, c.L, mat, kind), in.force) << trial;
    }
  }
}
