#include "kernels/SliderFriction.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace chute::kernels {

double SliderFrictionLaw::mu(double slipRate) const {
  if (slipRateScale <= 0.0) return muDynamic;
  return muDynamic + (muStatic - muDynamic) * std::exp(-std::abs(slipRate) / slipRateScale);  // FR7
}

double SliderFrictionLaw::dMuDRate(double slipRate) const {
  if (slipRateScale <= 0.0) return 0.0;
  return -(muStatic - muDynamic) / slipRateScale * std::exp(-std::abs(slipRate) / slipRateScale);
}

namespace {
// One straight part with its own reference length Li (FR1-FR2): force N, dN/dl, dN/dLi, energy.
struct PartForce {
  double strain = 0.0, N = 0.0, dNdl = 0.0, dNdLi = 0.0, energy = 0.0;
};

PartForce partForce(double l, double Li, const LineMaterial& mat) {
  PartForce p;
  const double Li2 = Li * Li;
  p.strain = (l * l - Li2) / (2.0 * Li2);
  double Eeff = mat.E;
  if (p.strain < 0.0 && mat.tensionOnly) Eeff = mat.E * mat.compressionStiffnessRatio;
  if (p.strain == 0.0 && mat.tensionOnly) Eeff = 0.0;  // as uniformStrainPolyline: slack
  const double EA = Eeff * mat.area;
  p.N = EA * p.strain * l / Li;                                // FR2
  p.dNdl = EA / Li * (p.strain + l * l / Li2);                 // FR9
  p.dNdLi = EA * l * (Li2 - 3.0 * l * l) / (2.0 * Li2 * Li2);  // FR9
  p.energy = 0.5 * EA * Li * p.strain * p.strain;              // FR1
  return p;
}

// x / sin x, 1 at 0.
double xOverSin(double x) {
  return std::abs(x) < 1e-8 ? 1.0 : x / std::sin(x);
}
}  // namespace

WrapAngle wrapAngle(const Vec3& x1, const Vec3& x2, const Vec3& x3, double L) {
  const double r = kApexFraction * L;
  const PartLength p1 = partLength(x3 - x1, r), p2 = partLength(x3 - x2, r);
  // FR3: beta is the angle between g1 and -g2, g_i = d l_i / d x3 (the unit vectors from the
  // ends to the slider away from the apex): parallel parts beta = pi, a straight cable beta = 0.
  // atan2 keeps it accurate near 0 and pi, where acos of the cosine u would not.
  const Vec3& a = p1.gradient;
  const Vec3& bv = p2.gradient;
  const double na = a.norm(), nb = bv.norm();
  const double u = -a.dot(bv) / (na * nb);
  const double b = std::atan2(a.cross(bv).norm(), -a.dot(bv));
  const double t0 = kWrapApexAngle;
  double beta, dBetaDu;
  if (b < t0) {  // FR4: C1 quadratic within t0 of beta = 0
    beta = (b * b + t0 * t0) / (2.0 * t0);
    dBetaDu = -xOverSin(b) / t0;
  } else if (b > std::numbers::pi - t0) {  // and of beta = pi
    const double th = std::numbers::pi - b;
    beta = std::numbers::pi - (th * th + t0 * t0) / (2.0 * t0);
    dBetaDu = -xOverSin(th) / t0;
  } else {
    beta = b;
    dBetaDu = -1.0 / std::sin(b);
  }
  // du/da = -b / (|a||b|) - u a / |a|^2, and likewise for b; then through d g_i / d x = H_i.
  const Vec3 dUda = -bv / (na * nb) - u * a / (na * na);
  const Vec3 dUdb = -a / (na * nb) - u * bv / (nb * nb);
  const Vec3 h1 = p1.hessian * (dBetaDu * dUda), h2 = p2.hessian * (dBetaDu * dUdb);
  WrapAngle w;
  w.beta = beta;
  w.gradient.segment<3>(0) = -h1;  // d_1 = x3 - x1
  w.gradient.segment<3>(3) = -h2;
  w.gradient.segment<3>(6) = h1 + h2;
  return w;
}

double frictionRoundoffFloor(const Vec3& x1, const Vec3& x2, const Vec3& x3, double L, double s) {
  const double shortest = std::min(s, L - s);
  if (!(shortest > 0.0)) return 0.0;
  const double size = std::max({x1.lpNorm<Eigen::Infinity>(), x2.lpNorm<Eigen::Infinity>(),
                                x3.lpNorm<Eigen::Infinity>(), L});
  return kRoundoffFloorFactor * std::numeric_limits<double>::epsilon() * size * L /
         shortest;  // FR16
}

FrictionSlidingResult frictionSlidingForce(const Vec3& x1, const Vec3& x2, const Vec3& x3, double L,
                                           double sStart, const LineMaterial& mat,
                                           const SliderFrictionLaw& law, double dt, bool locked,
                                           bool withTangent, SliderStick startSlip) {
  const double r = kApexFraction * L;
  const PartLength p1 = partLength(x3 - x1, r), p2 = partLength(x3 - x2, r);
  const double l1 = p1.length, l2 = p2.length;
  // D_i = d l_i / dx in element dof order (node 1, node 2, slider).
  Vec9 D1 = Vec9::Zero(), D2 = Vec9::Zero();
  D1.segment<3>(0) = -p1.gradient;
  D1.segment<3>(6) = p1.gradient;
  D2.segment<3>(3) = -p2.gradient;
  D2.segment<3>(6) = p2.gradient;
  const WrapAngle wrap = wrapAngle(x1, x2, x3, L);
  const double beta = wrap.beta;

  // A split on the boundary (slider on an end node) is moved a hair inside: L_i > 0.
  const double sMin = 1e-12 * L;
  const double s0 = std::clamp(sStart, sMin, L - sMin);

  FrictionSlidingResult out;
  out.wrapAngle = beta;
  out.l1 = l1;
  out.l2 = l2;

  // Stick predictor (FR5): s = s_n, capstan limit with the static coefficient.
  PartForce f1 = partForce(l1, s0, mat), f2 = partForce(l2, L - s0, mat);
  const double limit = std::exp(law.muStatic * beta);
  int sigma = 0;  // slip direction of s: +1 part 1 pulls harder and gains material, -1 part 2
  if (f1.N > limit * f2.N) sigma = +1;
  if (f2.N > limit * f1.N) sigma = -1;
  if (locked || sigma * law.oneWay < 0) sigma = 0;  // locked, or a ratchet's blocked direction
  // FR15: at the converged positions of a slipping slider the stick predictor is on the slip limit
  // (to round-off); stick keeps s = sStart, and the tangent is that of the slip continuing.
  int tangentSigma = sigma;
  const int hint = static_cast<int>(startSlip);
  if (sigma == 0 && hint != 0 && !locked && hint * law.oneWay >= 0) tangentSigma = hint;

  double s = s0, E = 1.0, g = 0.0, dgds = 0.0, mu = law.muStatic;
  // Slip condition g(s) = N_high - exp(mu(v) beta) N_low = 0 (FR6) and dg/ds (FR8).
  auto evaluate = [&](double sv) {
    f1 = partForce(l1, sv, mat);
    f2 = partForce(l2, L - sv, mat);
    const double rate = dt > 0.0 ? (sv - s0) / dt : 0.0;
    mu = law.mu(rate);
    E = std::exp(mu * beta);
    const double dMu = dt > 0.0 ? law.dMuDRate(rate) * sigma / dt : 0.0;  // d mu / ds
    const bool plus = sigma > 0;
    const double Nhi = plus ? f1.N : f2.N, Nlo = plus ? f2.N : f1.N;
    const double dNhi = plus ? f1.dNdLi : -f2.dNdLi, dNlo = plus ? -f2.dNdLi : f1.dNdLi;
    g = Nhi - E * Nlo;
    dgds = dNhi - E * dNlo - E * Nlo * beta * dMu;
  };

  if (sigma == 0 && tangentSigma != 0) {
    sigma = tangentSigma;  // g and dg/ds at s = sStart for the tangent; the force stays stick's
    evaluate(s0);
    sigma = 0;
  } else if (sigma != 0) {
    // g decreases along u = sigma (s - s_n) >= 0, from g > 0 at u = 0 to -infinity where the
    // low side's reference length vanishes (its force grows without bound): a bracketed root,
    // found by Newton with bisection whenever Newton leaves the bracket (FR8).
    double uLo = 0.0, uHi = sigma > 0 ? L - s0 : s0;
    double u = 0.0;
    evaluate(s0);
    for (int it = 0; it < 200; ++it) {
      ++out.localIterations;
      const double dgdu = sigma * dgds;
      double uNew = dgdu < 0.0 ? u - g / dgdu : 0.5 * (uLo + uHi);
      if (!(uNew > uLo && uNew < uHi)) uNew = 0.5 * (uLo + uHi);
      const double step = std::abs(uNew - u);
      u = uNew;
      evaluate(s0 + sigma * u);
      if (g > 0.0) uLo = u;
      if (g < 0.0) uHi = u;
      const double scale = std::abs(f1.N) + std::abs(f2.N);
      if (g == 0.0 || step <= 1e-15 * L || std::abs(g) <= 1e-14 * scale) break;
    }
    s = s0 + sigma * u;
  }

  out.s = s;
  out.state = static_cast<SliderStick>(sigma);
  out.strain1 = f1.strain;
  out.strain2 = f2.strain;
  out.N1 = f1.N;
  out.N2 = f2.N;
  out.energy = f1.energy + f2.energy;
  out.force = f1.N * D1 + f2.N * D2;  // FR2
  out.stiffness.setZero();
  if (!withTangent) return out;

  // FR9: at a fixed split each part is a two-node cable: k_i D_i D_i^T + N_i G_i.
  out.stiffness.noalias() = f1.dNdl * (D1 * D1.transpose()) + f2.dNdl * (D2 * D2.transpose());
  auto addGeometric = [&](int node, const Mat3& h) {
    out.stiffness.block<3, 3>(3 * node, 3 * node) += h;
    out.stiffness.block<3, 3>(6, 6) += h;
    out.stiffness.block<3, 3>(3 * node, 6) -= h;
    out.stiffness.block<3, 3>(6, 3 * node) -= h;
  };
  addGeometric(0, f1.N * p1.hessian);
  addGeometric(1, f2.N * p2.hessian);
  // FR10: in slip s = s(x) through g(x, s(x)) = 0: ds/dx = -(dg/dx) / (dg/ds), and
  // K += (df/ds) (ds/dx)^T with df/ds = dN1/dL1 D1 - dN2/dL2 D2.
  if (tangentSigma != 0 && dgds != 0.0) {
    const bool plus = tangentSigma > 0;
    const double kHi = plus ? f1.dNdl : f2.dNdl, kLo = plus ? f2.dNdl : f1.dNdl;
    const double Nlo = plus ? f2.N : f1.N;
    const Vec9& Dhi = plus ? D1 : D2;
    const Vec9& Dlo = plus ? D2 : D1;
    const Vec9 dgdx = kHi * Dhi - E * kLo * Dlo - E * Nlo * mu * wrap.gradient;
    const Vec9 dsdx = -dgdx / dgds;
    const Vec9 dfds = f1.dNdLi * D1 - f2.dNdLi * D2;
    out.stiffness.noalias() += dfds * dsdx.transpose();
  }
  return out;
}

}  // namespace chute::kernels
