// The whirl damping of a line node next to a slider (RG8, kernels/SliderWhirlDamping.hpp):
// derivatives against finite differences in every regime (between the floor and the capture
// distance, below the floor, explicit cap), its dissipation and momentum, and where it is off.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "kernels/SliderWhirlDamping.hpp"
#include "support/FiniteDifference.hpp"
#include "support/LineGeometry.hpp"

using namespace chute;
using namespace chute::kernels;
using chute::testing::fdJacobian;
using chute::testing::randomUnit;
using chute::testing::relativeError;
using chute::testing::rope;

namespace {

// A taut element of reference length L with the slider at distance `gap` from end `end`.
Vec9 configuration(std::mt19937& rng, double L, double gap, int end, double strain) {
  const double l = L * std::sqrt(1 + 2 * strain);
  const Vec3 x3(0.3, -0.2, 1.1);
  const Vec3 near = x3 - gap * randomUnit(rng), far = x3 - (l - gap) * randomUnit(rng);
  Vec9 x;
  x << (end == 0 ? near : far), (end == 0 ? far : near), x3;
  return x;
}

Vec9 randomVelocity(std::mt19937& rng) {
  std::normal_distribution<double> n(0, 1);
  Vec9 v;
  for (int i = 0; i < 9; ++i) v[i] = n(rng);
  return v;
}

WhirlDampingParams params(const LineMaterial& mat, double L, double explicitStep = 0.0) {
  WhirlDampingParams p;
  p.endMass[0] = 0.5 * mat.density * mat.area * 0.8 * L;
  p.endMass[1] = 0.5 * mat.density * mat.area * 1.3 * L;
  p.sliderMass = 0.5 * mat.density * mat.area * L;
  p.explicitStep = explicitStep;
  return p;
}

struct Regime {
  const char* name;
  double gap;  // distance slider - node as a fraction of L
  double explicitStep;
};

class WhirlDampingFD : public ::testing::TestWithParam<Regime> {};

}  // namespace

TEST_P(WhirlDampingFD, DerivativesMatchFiniteDifferences) {
  const Regime rg = GetParam();
  const auto mat = rope();
  std::mt19937 rng(7);
  double worstX = 0, worstV = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const double L = 0.5 + 0.05 * trial;
    const int end = trial % 2;
    const Vec9 x = configuration(rng, L, rg.gap * L, end, 0.01);
    const Vec9 v = randomVelocity(rng);
    const auto par = params(mat, L, rg.explicitStep);
    const auto r = sliderWhirlDamping(x, v, L, mat, par, true);
    ASSERT_TRUE(r.active);
    auto ofX = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
      return sliderWhirlDamping(y, v, L, mat, par, false).force;
    };
    auto ofV = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
      return sliderWhirlDamping(x, y, L, mat, par, false).force;
    };
    // Within 1e-4 of the nearest kink of the coefficient (the node, the capture distance) so
    // that the stencil's truncation error stays far below the tolerance.
    const double h = 1e-4 * std::min(rg.gap, kWhirlDampingFraction - rg.gap) * L;
    worstX = std::max(worstX, relativeError(r.dPosition, fdJacobian(ofX, x, h)));
    worstV = std::max(worstV, relativeError(r.dVelocity, fdJacobian(ofV, v, 1e-4)));
  }
  std::printf("%s: worst relative error  df/dx vs FD %.2e  df/dv vs FD %.2e\n", rg.name, worstX,
              worstV);
  EXPECT_LE(worstX, 1e-6);
  EXPECT_LE(worstV, 1e-8);
}

INSTANTIATE_TEST_SUITE_P(Regimes, WhirlDampingFD,
                         ::testing::Values(Regime{"inside_the_capture_distance", 0.04, 0.0},
                                           Regime{"near_the_capture_distance", 0.095, 0.0},
                                           Regime{"below_the_floor", 4e-4, 0.0},
                                           Regime{"explicit_cap", 0.02, 1e-2}),
                         [](const auto& p) { return std::string(p.param.name); });

TEST(WhirlDamping, DissipatesKeepsMomentumAndIgnoresACommonVelocity) {
  const auto mat = rope();
  std::mt19937 rng(11);
  double worstMomentum = 0, worstGalilei = 0, worstPower = 0, least = 1e300;
  for (int trial = 0; trial < 200; ++trial) {
    const double L = 1.0;
    const Vec9 x = configuration(rng, L, 0.001 + 0.0005 * trial, trial % 2, 0.02);
    const Vec9 v = randomVelocity(rng);
    const auto par = params(mat, L);
    const auto r = sliderWhirlDamping(x, v, L, mat, par, false);
    const Vec3 sum = r.force.segment<3>(0) + r.force.segment<3>(3) + r.force.segment<3>(6);
    worstMomentum = std::max(worstMomentum, sum.norm() / std::max(r.force.norm(), 1e-300));
    // The power it takes out: f . v, never negative.
    worstPower =
        std::max(worstPower, std::abs(r.force.dot(v) - r.power) / std::max(r.power, 1e-300));
    least = std::min(least, r.power);
    Vec9 shifted = v;
    const Vec3 common(3.0, -1.0, 7.0);
    for (int n = 0; n < 3; ++n) shifted.segment<3>(3 * n) += common;
    worstGalilei = std::max(
        worstGalilei,
        relativeError(sliderWhirlDamping(x, shifted, L, mat, par, false).force, r.force, 1e-300));
  }
  std::printf(
      "sum of forces / |f| %.2e, |f.v - power| / power %.2e, least power %.3e, common "
      "velocity changes f by %.2e\n",
      worstMomentum, worstPower, least, worstGalilei);
  EXPECT_LE(worstMomentum, 1e-14);
  EXPECT_LE(worstPower, 1e-12);
  EXPECT_GE(least, 0.0);
  EXPECT_LE(worstGalilei, 1e-12);
}

TEST(WhirlDamping, IsTheCriticalDampingOfTheWhirlFadedInAndCapped) {
  // End 1 at distance l from the slider, across the part only: f = c w with
  // c = 2 (1 - l/d_c)^2 sqrt(mu N / l).
  const auto mat = rope();
  const double L = 1.0, l = 0.03, strain = 0.01;
  const double len = L * std::sqrt(1 + 2 * strain);
  Vec9 x;
  x << -l, 0, 0, len - l, 0, 0, 0, 0, 0;  // end 1, end 2, slider on a straight line
  Vec9 v = Vec9::Zero();
  v[1] = 0.25;  // end 1 moves across the part
  const auto par = params(mat, L);
  const auto r = sliderWhirlDamping(x, v, L, mat, par, false);
  const double N = mat.E * mat.area * strain * len / L;
  const double mu = par.endMass[0] * par.sliderMass / (par.endMass[0] + par.sliderMass);
  const double dc = kWhirlDampingFraction * L;
  const double c = 2 * std::pow(1 - l / dc, 2) * std::sqrt(mu * N / l);
  std::printf("force %.9e expected %.9e\n", r.force[1], c * 0.25);
  EXPECT_NEAR(r.force[1], c * 0.25, 1e-12 * c);
  EXPECT_NEAR(r.force[7], -c * 0.25, 1e-12 * c);
  EXPECT_NEAR(r.force[0], 0.0, 1e-15);  // along the part: nothing (the slider slides freely)
  // The explicit cap: at most mu / dt.
  auto capped = par;
  capped.explicitStep = 10.0 * mu / c;
  EXPECT_NEAR(sliderWhirlDamping(x, v, L, mat, capped, false).force[1],
              mu / capped.explicitStep * 0.25, 1e-12 * c);
}

TEST(WhirlDamping, IsOffBeyondTheCaptureDistanceWhenSlackOrWithoutMass) {
  const auto mat = rope();
  std::mt19937 rng(3);
  const double L = 1.0;
  const Vec9 v = randomVelocity(rng);
  const Vec9 far = configuration(rng, L, 1.01 * kWhirlDampingFraction * L, 0, 0.01);
  const Vec9 slack = configuration(rng, L, 0.02, 0, -1e-3);
  const Vec9 near = configuration(rng, L, 0.02, 0, 0.01);
  EXPECT_FALSE(sliderWhirlDamping(far, v, L, mat, params(mat, L), false).active);
  EXPECT_EQ(sliderWhirlDamping(slack, v, L, mat, params(mat, L), false).force.norm(), 0.0);
  auto massless = params(mat, L);
  massless.endMass[0] = 0.0;
  EXPECT_EQ(sliderWhirlDamping(near, v, L, mat, massless, false).force.norm(), 0.0);
  EXPECT_GT(sliderWhirlDamping(near, v, L, mat, params(mat, L), false).force.norm(), 0.0);
}
