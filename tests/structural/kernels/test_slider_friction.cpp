// The friction element of a slider (docs/friction.md): central finite-difference checks of the
// wrap angle's gradient, of force against energy at a fixed split, and of the algorithmic
// tangent against the force in stick and in slip (with and without rate dependence); a
// frictionless one-way slider reproduces the uniform-strain element.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "kernels/SliderFriction.hpp"
#include "kernels/SlidingCableKernel.hpp"
#include "support/FiniteDifference.hpp"

using namespace chute;
using namespace chute::kernels;
using chute::testing::fdGradient;
using chute::testing::fdJacobian;
using chute::testing::relativeError;

namespace {
LineMaterial rope() {
  LineMaterial m;
  m.E = 1.0e3;
  m.area = 1.0;
  return m;
}

struct ElementGeometry {
  Vec3 x1{0.0, 0.0, 0.0}, x2{2.0, 0.1, 0.0}, x3{0.8, 0.05, -0.6};
  double L = 2.2;
  Vec9 pack() const {
    Vec9 v;
    v << x1, x2, x3;
    return v;
  }
};

FrictionSlidingResult evalAt(const Eigen::VectorXd& v, const ElementGeometry& su, double sStart,
                             const SliderFrictionLaw& law, double dt, bool locked, bool tangent) {
  return frictionSlidingForce(v.segment<3>(0), v.segment<3>(3), v.segment<3>(6), su.L, sStart,
                              rope(), law, dt, locked, tangent);
}

// Tangent vs central differences of the force; every perturbed point must stay in `state`.
double tangentError(const ElementGeometry& su, double sStart, const SliderFrictionLaw& law,
                    double dt, bool locked, SliderStick state) {
  const Eigen::VectorXd x0 = su.pack();
  const auto r0 = evalAt(x0, su, sStart, law, dt, locked, true);
  EXPECT_EQ(r0.state, state);
  const double h = 1e-6;
  const Eigen::MatrixXd Kfd = fdJacobian(
      [&](const Eigen::VectorXd& y) {
        const auto r = evalAt(y, su, sStart, law, dt, locked, false);
        EXPECT_EQ(r.state, state);
        return Eigen::VectorXd(r.force);
      },
      x0, h);
  return relativeError(r0.stiffness, Kfd);
}

double uniformSplit(const ElementGeometry& su) {
  return sliderReferenceOffset(su.x1, su.x2, su.x3, su.L);
}
}  // namespace

TEST(SliderFriction, WrapAngleGradientMatchesFiniteDifferences) {
  // A generic angle, and a slider whose parts are parallel to within the apex angle (beta ~ pi).
  ElementGeometry su;
  ElementGeometry par;
  par.x1 = Vec3(0.0, 0.0, -1.0);
  par.x2 = Vec3(3e-7, 0.0, -1.2);
  par.x3 = Vec3(0.0, 0.0, 0.0);
  for (const ElementGeometry* s : {&su, &par}) {
    const Eigen::VectorXd x0 = s->pack();
    const auto w = wrapAngle(s->x1, s->x2, s->x3, s->L);
    const Eigen::VectorXd g = fdGradient(
        [&](const Eigen::VectorXd& y) {
          return wrapAngle(y.segment<3>(0), y.segment<3>(3), y.segment<3>(6), s->L).beta;
        },
        x0, s == &su ? 1e-6 : 1e-9);
    const double err = relativeError(w.gradient, g);
    std::printf("wrap angle %.9f rad: gradient vs central FD, max relative error %.2e\n", w.beta,
                err);
    EXPECT_LT(err, 1e-5);
  }
  // Exactly parallel parts: beta = pi - kWrapApexAngle / 2, a bounded (zero) gradient.
  const auto w = wrapAngle(Vec3(0, 0, -1), Vec3(0, 0, -2), Vec3::Zero(), 2.0);
  EXPECT_NEAR(w.beta, std::numbers::pi - 0.5 * kWrapApexAngle, 1e-12);
  EXPECT_TRUE(w.gradient.allFinite());
}

TEST(SliderFriction, StickForceIsTheEnergyGradientAndTangentMatchesFD) {
  ElementGeometry su;
  SliderFrictionLaw law;
  law.muStatic = 0.3;
  law.muDynamic = 0.2;
  // The uniform split: equal tensions, well inside the capstan limit.
  const double s0 = uniformSplit(su) * 1.01;
  const Eigen::VectorXd x0 = su.pack();
  const auto r0 = evalAt(x0, su, s0, law, 0.01, false, true);
  ASSERT_EQ(r0.state, SliderStick::Stick);
  EXPECT_EQ(r0.s, s0);
  const Eigen::VectorXd gfd = fdGradient(
      [&](const Eigen::VectorXd& y) { return evalAt(y, su, s0, law, 0.01, false, false).energy; },
      x0, 1e-6);
  const double eForce = relativeError(r0.force, gfd);
  const double eTangent = tangentError(su, s0, law, 0.01, false, SliderStick::Stick);
  std::printf("stick (N2/N1 = %.4f, limit %.4f): force vs FD energy %.2e, tangent vs FD %.2e\n",
              r0.N2 / r0.N1, std::exp(law.muStatic * r0.wrapAngle), eForce, eTangent);
  EXPECT_LT(eForce, 1e-7);
  EXPECT_LT(eTangent, 1e-6);
}

TEST(SliderFriction, SlipSatisfiesCapstanAndTangentMatchesFD) {
  ElementGeometry su;
  const double sUni = uniformSplit(su);
  struct Variant {
    const char* name;
    double muS, muD, vs, sStart;
    SliderStick state;
  };
  const Variant variants[] = {
      {"slip -, constant mu", 0.2, 0.2, 0.0, 1.2 * sUni, SliderStick::SlipMinus},
      {"slip +, constant mu", 0.2, 0.2, 0.0, 0.8 * sUni, SliderStick::SlipPlus},
      {"slip -, rate-dependent mu", 0.3, 0.15, 0.5, 1.2 * sUni, SliderStick::SlipMinus},
      {"slip +, rate-dependent mu", 0.3, 0.15, 0.5, 0.8 * sUni, SliderStick::SlipPlus},
  };
  const double dt = 0.05;
  for (const auto& v : variants) {
    SliderFrictionLaw law;
    law.muStatic = v.muS;
    law.muDynamic = v.muD;
    law.slipRateScale = v.vs;
    const auto r = evalAt(su.pack(), su, v.sStart, law, dt, false, true);
    ASSERT_EQ(r.state, v.state) << v.name;
    // The slip condition N_high = exp(mu(rate) beta) N_low at the converged split.
    const double mu = law.mu((r.s - v.sStart) / dt);
    const double hi = v.state == SliderStick::SlipPlus ? r.N1 : r.N2;
    const double lo = v.state == SliderStick::SlipPlus ? r.N2 : r.N1;
    const double capstan = std::abs(hi / lo / std::exp(mu * r.wrapAngle) - 1.0);
    const double err = tangentError(su, v.sStart, law, dt, false, v.state);
    std::printf(
        "%s: s %.6f -> %.6f in %d local iterations, |ratio / exp(mu beta) - 1| = %.1e, "
        "tangent vs FD %.2e\n",
        v.name, v.sStart, r.s, r.localIterations, capstan, err);
    EXPECT_LT(capstan, 1e-12);
    EXPECT_LT(err, 1e-6);
  }
}

TEST(SliderFriction, LockAndOneWayHoldTheSplit) {
  ElementGeometry su;
  const double sStart = 1.2 * uniformSplit(su);  // would slip towards smaller s
  SliderFrictionLaw law;
  law.muStatic = law.muDynamic = 0.1;
  const auto locked = evalAt(su.pack(), su, sStart, law, 0.01, true, true);
  EXPECT_EQ(locked.state, SliderStick::Stick);
  EXPECT_EQ(locked.s, sStart);
  law.oneWay = +1;  // only growing s: the slip towards smaller s is blocked
  EXPECT_EQ(evalAt(su.pack(), su, sStart, law, 0.01, false, false).state, SliderStick::Stick);
  law.oneWay = -1;
  EXPECT_EQ(evalAt(su.pack(), su, sStart, law, 0.01, false, false).state, SliderStick::SlipMinus);
  const double err = tangentError(su, sStart, law, 0.01, true, SliderStick::Stick);
  std::printf("locked slider: tangent vs FD %.2e\n", err);
  EXPECT_LT(err, 1e-6);
}

TEST(SliderFriction, FrictionlessOneWayReproducesTheUniformStrainElement) {
  // mu = 0 with a ratchet open in the direction of the flow: the slip condition N1 = N2 gives
  // the uniform strain of F6-F9.
  ElementGeometry su;
  SliderFrictionLaw law;
  law.oneWay = -1;
  const auto r = evalAt(su.pack(), su, 1.3 * uniformSplit(su), law, 0.01, false, true);
  ASSERT_EQ(r.state, SliderStick::SlipMinus);
  const auto u = slidingForce(su.x1, su.x2, su.x3, su.L, rope(), true);
  const double eF = relativeError(r.force, u.force), eK = relativeError(r.stiffness, u.stiffness);
  std::printf("frictionless one-way vs uniform strain: split %.2e, force %.2e, tangent %.2e\n",
              std::abs(r.s - uniformSplit(su)) / su.L, eF, eK);
  EXPECT_LT(std::abs(r.s - uniformSplit(su)), 1e-12 * su.L);
  EXPECT_LT(eF, 1e-12);
  EXPECT_LT(eK, 1e-9);
}

TEST(SliderFriction, StartOfStepTangentIsTheSlipTangentOnTheLimit) {
  // FR15: at the split a slip step converged to (the stick predictor on the slip limit), the
  // start-of-step call returns the stick force with the tangent of the slip continuing: equal to
  // the slip tangent of a predictor a hair behind the limit (which slips by that hair).
  ElementGeometry su;
  const double sUni = uniformSplit(su);
  SliderFrictionLaw law;
  law.muStatic = law.muDynamic = 0.2;
  const double dt = 0.05;
  const auto slip = evalAt(su.pack(), su, 0.8 * sUni, law, dt, false, true);
  ASSERT_EQ(slip.state, SliderStick::SlipPlus);
  const auto x = su.pack();
  const auto start =
      frictionSlidingForce(x.segment<3>(0), x.segment<3>(3), x.segment<3>(6), su.L, slip.s, rope(),
                           law, dt, false, true, SliderStick::SlipPlus);
  const auto behind = evalAt(x, su, slip.s - 1e-9 * su.L, law, dt, false, true);
  const auto stick = evalAt(x, su, slip.s, law, dt, false, true);
  const double forceDiff = (start.force - stick.force).norm() / stick.force.norm();
  const double tangentDiff = relativeError(start.stiffness, behind.stiffness);
  const double stickDiff = relativeError(stick.stiffness, behind.stiffness);
  std::printf(
      "start-of-step tangent on the slip limit (state %d): force vs stick %.1e, tangent vs slip "
      "tangent %.2e (the stick tangent differs by %.2e)\n",
      static_cast<int>(stick.state), forceDiff, tangentDiff, stickDiff);
  EXPECT_EQ(start.state, stick.state);
  EXPECT_EQ(forceDiff, 0.0);
  EXPECT_LT(tangentDiff, 1e-6);
  EXPECT_GT(stickDiff, 1e-2);
}
