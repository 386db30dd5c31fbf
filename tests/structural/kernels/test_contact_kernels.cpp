// Contact kernels (docs/contact.md CT1-CT8): distances against an independent reference (every
// feature pair enumerated, the feasible minimum kept), their gradients and Hessians against
// central differences in every closest-feature region, on region boundaries, for parallel edges
// and at vanishing distance; the penalty, mollifier, damping and friction against central
// differences of their energy or residual, and the sign of their power.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "kernels/ContactFriction.hpp"
#include "kernels/ContactPotential.hpp"
#include "support/FiniteDifference.hpp"

using namespace chute::kernels;
using chute::testing::fdGradient;
using chute::testing::fdJacobian;
using chute::testing::relativeError;
using Nodes = std::array<Vec3, 4>;

namespace {

Eigen::VectorXd flat(const Nodes& x) {
  Eigen::VectorXd y(12);
  for (int i = 0; i < 4; ++i) y.segment<3>(3 * i) = x[i];
  return y;
}
Nodes unflat(const Eigen::VectorXd& y) {
  Nodes x;
  for (int i = 0; i < 4; ++i) x[i] = y.segment<3>(3 * i);
  return x;
}

// ---- independent references: every feature pair's unconstrained minimum, kept if feasible ----
double pointSegment2(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 e = b - a;
  double t = e.squaredNorm() > 0 ? (p - a).dot(e) / e.squaredNorm() : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return (p - a - t * e).squaredNorm();
}
double referencePointTriangle2(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  double best = std::min({pointSegment2(p, a, b), pointSegment2(p, b, c), pointSegment2(p, c, a)});
  // The face: barycentric coordinates of p's projection by Cramer's rule on the normal equations.
  const Vec3 e1 = b - a, e2 = c - a, q = p - a;
  const double A = e1.dot(e1), B = e1.dot(e2), C = e2.dot(e2), D = q.dot(e1), E = q.dot(e2);
  const double det = A * C - B * B;
  if (det > 0) {
    const double beta = (C * D - B * E) / det, gamma = (A * E - B * D) / det;
    if (beta >= 0 && gamma >= 0 && beta + gamma <= 1)
      best = std::min(best, (q - beta * e1 - gamma * e2).squaredNorm());
  }
  return best;
}
double referenceEdgeEdge2(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1) {
  double best = std::min({pointSegment2(a0, b0, b1), pointSegment2(a1, b0, b1),
                          pointSegment2(b0, a0, a1), pointSegment2(b1, a0, a1)});
  const Vec3 d1 = a1 - a0, d2 = b1 - b0, r = a0 - b0;
  const double A = d1.dot(d1), B = d1.dot(d2), E = d2.dot(d2), C = d1.dot(r), F = d2.dot(r);
  const double det = A * E - B * B;
  if (det > 1e-14 * A * E) {
    const double s = (B * F - C * E) / det, t = (A * F - B * C) / det;
    if (s >= 0 && s <= 1 && t >= 0 && t <= 1)
      best = std::min(best, (r + s * d1 - t * d2).squaredNorm());
  }
  return best;
}

SquaredDistance squared(ContactPairKind kind, const Nodes& x, bool hessian) {
  return kind == ContactPairKind::PointTriangle
             ? pointTriangleDistance(x[0], x[1], x[2], x[3], hessian)
             : edgeEdgeDistance(x[0], x[1], x[2], x[3], hessian);
}

struct Errors {
  double gradient = 0, hessian = 0;
};

// The squared distance's gradient and Hessian against central differences at x.
Errors checkSquaredDistance(ContactPairKind kind, const Nodes& x, double h = 1e-6) {
  const auto s = squared(kind, x, true);
  const auto value = [&](const Eigen::VectorXd& y) {
    return squared(kind, unflat(y), false).value;
  };
  const auto grad = [&](const Eigen::VectorXd& y) {
    return Eigen::VectorXd(squared(kind, unflat(y), false).gradient);
  };
  Errors e;
  e.gradient = relativeError(s.gradient, fdGradient(value, flat(x), h), 1e-8);
  e.hessian = relativeError(Eigen::MatrixXd(s.hessian), fdJacobian(grad, flat(x), h), 1e-8);
  return e;
}

// Configurations that put the point in each region of triangle (0,0,0), (1,0,0), (0,1,0).
const Vec3 kA(0, 0, 0), kB(1, 0, 0), kC(0, 1, 0);
struct RegionCase {
  const char* name;
  Vec3 p;
  PointTriangleRegion region;
};
const RegionCase kPointRegions[] = {
    {"vertex a", {-0.3, -0.2, 0.4}, PointTriangleRegion::VertexA},
    {"vertex b", {1.3, -0.1, -0.2}, PointTriangleRegion::VertexB},
    {"vertex c", {-0.1, 1.4, 0.3}, PointTriangleRegion::VertexC},
    {"edge ab", {0.4, -0.3, 0.2}, PointTriangleRegion::EdgeAB},
    {"edge bc", {0.7, 0.6, -0.3}, PointTriangleRegion::EdgeBC},
    {"edge ca", {-0.2, 0.5, 0.1}, PointTriangleRegion::EdgeCA},
    {"face", {0.2, 0.3, 0.25}, PointTriangleRegion::Face},
};

}  // namespace

TEST(ContactDistance, PointTriangleMatchesEnumerationInEveryRegion) {
  std::mt19937 rng(7);
  std::normal_distribution<double> nd(0, 1);
  double worst = 0;
  int counts[7] = {};
  for (int k = 0; k < 20000; ++k) {
    Nodes x;
    for (auto& v : x) v = Vec3(nd(rng), nd(rng), nd(rng));
    const auto s = pointTriangleDistance(x[0], x[1], x[2], x[3], false);
    const double ref = referencePointTriangle2(x[0], x[1], x[2], x[3]);
    worst = std::max(worst, std::abs(s.value - ref) / std::max(ref, 1e-12));
    // The value-only path (the narrow phase's test) gives the same squared distance.
    worst = std::max(worst, std::abs(pointTriangleSquaredDistance(x[0], x[1], x[2], x[3]) - ref) /
                                std::max(ref, 1e-12));
    ++counts[static_cast<int>(classifyPointTriangle(x[0], x[1], x[2], x[3]))];
    // The closest point (sum of the triangle's weights times its nodes) is on the triangle.
    EXPECT_NEAR(s.weight[0], 1.0, 1e-12);
    EXPECT_NEAR(s.weight[1] + s.weight[2] + s.weight[3], -1.0, 1e-12);
  }
  std::printf(
      "point-triangle: worst relative error of s against enumeration %.2e; regions hit "
      "%d %d %d %d %d %d %d\n",
      worst, counts[0], counts[1], counts[2], counts[3], counts[4], counts[5], counts[6]);
  EXPECT_LT(worst, 1e-10);
  for (int c : counts) EXPECT_GT(c, 100);
  for (const auto& rc : kPointRegions)
    EXPECT_EQ(classifyPointTriangle(rc.p, kA, kB, kC), rc.region) << rc.name;
}

TEST(ContactDistance, EdgeEdgeMatchesEnumerationInEveryRegion) {
  std::mt19937 rng(11);
  std::normal_distribution<double> nd(0, 1);
  double worst = 0;
  int counts[4] = {};
  for (int k = 0; k < 20000; ++k) {
    Nodes x;
    for (auto& v : x) v = Vec3(nd(rng), nd(rng), nd(rng));
    const auto s = edgeEdgeDistance(x[0], x[1], x[2], x[3], false);
    const double ref = referenceEdgeEdge2(x[0], x[1], x[2], x[3]);
    worst = std::max(worst, std::abs(s.value - ref) / std::max(ref, 1e-12));
    worst = std::max(worst, std::abs(edgeEdgeSquaredDistance(x[0], x[1], x[2], x[3]) - ref) /
                                std::max(ref, 1e-12));
    ++counts[static_cast<int>(classifyEdgeEdge(x[0], x[1], x[2], x[3]).region)];
  }
  std::printf(
      "edge-edge: worst relative error of s against enumeration %.2e; regions hit %d %d "
      "%d %d\n",
      worst, counts[0], counts[1], counts[2], counts[3]);
  EXPECT_LT(worst, 1e-10);
  for (int c : counts) EXPECT_GT(c, 100);
}

TEST(ContactDistance, GradientAndHessianInEveryPointTriangleRegion) {
  double worstG = 0, worstH = 0;
  for (const auto& rc : kPointRegions) {
    // A generic triangle: the unit one sheared and lifted, the point moved with it.
    Eigen::Matrix3d T;
    T << 1.1, 0.2, 0.1, -0.1, 0.9, 0.3, 0.2, -0.2, 1.2;
    const Vec3 o(0.3, -0.4, 0.5);
    const Nodes x{T * rc.p + o, T * kA + o, T * kB + o, T * kC + o};
    ASSERT_EQ(classifyPointTriangle(x[0], x[1], x[2], x[3]), rc.region) << rc.name;
    const Errors e = checkSquaredDistance(ContactPairKind::PointTriangle, x);
    std::printf("  point-triangle %-8s: gradient %.1e, Hessian %.1e\n", rc.name, e.gradient,
                e.hessian);
    worstG = std::max(worstG, e.gradient), worstH = std::max(worstH, e.hessian);
  }
  EXPECT_LT(worstG, 1e-8);
  EXPECT_LT(worstH, 1e-6);
}

TEST(ContactDistance, GradientAndHessianInEveryEdgeEdgeRegion) {
  struct Case {
    const char* name;
    Nodes x;
    EdgeEdgeRegion region;
  };
  const Case cases[] = {
      {"interior",
       {Vec3(0, 0, 0), Vec3(1, 0.1, 0), Vec3(0.5, -0.5, 0.3), Vec3(0.4, 0.6, 0.35)},
       EdgeEdgeRegion::Interior},
      {"end of first",
       {Vec3(0, 0, 0), Vec3(-1, 0.1, 0), Vec3(0.5, -0.5, 0.3), Vec3(0.4, 0.6, 0.35)},
       EdgeEdgeRegion::EndOfFirst},
      {"end of second",
       {Vec3(0, 0, 0), Vec3(1, 0.1, 0), Vec3(0.5, 0.5, 0.3), Vec3(0.4, 1.6, 0.35)},
       EdgeEdgeRegion::EndOfSecond},
      {"end to end",
       {Vec3(0, 0, 0), Vec3(-1, 0.1, 0), Vec3(0.5, 0.5, 0.3), Vec3(0.7, 1.6, 0.35)},
       EdgeEdgeRegion::EndToEnd},
  };
  double worstG = 0, worstH = 0;
  for (const auto& c : cases) {
    ASSERT_EQ(classifyEdgeEdge(c.x[0], c.x[1], c.x[2], c.x[3]).region, c.region) << c.name;
    const Errors e = checkSquaredDistance(ContactPairKind::EdgeEdge, c.x);
    std::printf("  edge-edge %-13s: gradient %.1e, Hessian %.1e\n", c.name, e.gradient, e.hessian);
    worstG = std::max(worstG, e.gradient), worstH = std::max(worstH, e.hessian);
  }
  EXPECT_LT(worstG, 1e-8);
  EXPECT_LT(worstH, 1e-6);
}

TEST(ContactDistance, RandomConfigurationsAgreeWithCentralDifferences) {
  std::mt19937 rng(3);
  std::normal_distribution<double> nd(0, 1);
  double worstG = 0, worstH = 0;
  int checked = 0;
  for (int k = 0; k < 400; ++k) {
    Nodes x;
    for (auto& v : x) v = Vec3(nd(rng), nd(rng), nd(rng));
    for (auto kind : {ContactPairKind::PointTriangle, ContactPairKind::EdgeEdge}) {
      // Skip configurations within the FD step of a region boundary (the Hessian jumps there;
      // the boundaries have their own test).
      bool nearBoundary = false;
      const auto reg = [&](const Nodes& y) {
        return kind == ContactPairKind::PointTriangle
                   ? static_cast<int>(classifyPointTriangle(y[0], y[1], y[2], y[3]))
                   : static_cast<int>(classifyEdgeEdge(y[0], y[1], y[2], y[3]).region);
      };
      for (int j = 0; j < 12 && !nearBoundary; ++j)
        for (double sgn : {-1.0, 1.0}) {
          Eigen::VectorXd y = flat(x);
          y[j] += sgn * 1e-4;
          nearBoundary |= reg(unflat(y)) != reg(x);
        }
      if (nearBoundary) continue;
      const Errors e = checkSquaredDistance(kind, x);
      worstG = std::max(worstG, e.gradient), worstH = std::max(worstH, e.hessian);
      ++checked;
    }
  }
  std::printf("%d random pairs: worst gradient error %.1e, Hessian %.1e\n", checked, worstG,
              worstH);
  EXPECT_GT(checked, 600);
  EXPECT_LT(worstG, 1e-7);
  EXPECT_LT(worstH, 1e-5);
}

// On a boundary between regions s and grad s are continuous (the central difference straddling
// it matches), the Hessian is that of either side (each side checked a hair inside it).
TEST(ContactDistance, RegionBoundaries) {
  struct Boundary {
    const char* name;
    Vec3 p;  // on the boundary
    Vec3 across;
  };
  // Triangle (0,0,0), (1,0,0), (0,1,0): p above edge ab's line (face / edge ab), p on the plane
  // through a normal to ab (vertex a / edge ab), p in the plane on the extension of ca.
  const Boundary boundaries[] = {
      {"face | edge ab", Vec3(0.4, 0.0, 0.3), Vec3(0, 1, 0)},
      {"edge ab | vertex a", Vec3(0.0, -0.3, 0.2), Vec3(1, 0, 0)},
      {"edge bc | vertex b", Vec3(1.2, 0.2, 0.1), Vec3(-1, 1, 0)},
      {"face | vertex-free point on edge", Vec3(0.5, 0.5, 0.0) + Vec3(0, 0, 0.2), Vec3(1, 1, 0)},
  };
  double worstG = 0, worstH = 0;
  for (const auto& b : boundaries) {
    const Nodes x{b.p, kA, kB, kC};
    // A step of 1e-8: the central difference straddling a jump dH of the Hessian is off by
    // h dH / 4.
    worstG =
        std::max(worstG, checkSquaredDistance(ContactPairKind::PointTriangle, x, 1e-8).gradient);
    for (double side : {-1.0, 1.0}) {
      const Nodes y{b.p + side * 1e-4 * b.across.normalized(), kA, kB, kC};
      const Errors e = checkSquaredDistance(ContactPairKind::PointTriangle, y, 1e-7);
      worstH = std::max(worstH, e.hessian);
    }
  }
  // Edge-edge: the second segment's end exactly at the first's interior projection.
  const Nodes ee{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0.0, 0.4), Vec3(0.5, 1.0, 0.4)};
  worstG = std::max(worstG, checkSquaredDistance(ContactPairKind::EdgeEdge, ee, 1e-8).gradient);
  for (double side : {-1.0, 1.0}) {
    Nodes y = ee;
    y[2].y() += side * 1e-4, y[3].y() += side * 1e-4;
    worstH = std::max(worstH, checkSquaredDistance(ContactPairKind::EdgeEdge, y, 1e-7).hessian);
  }
  std::printf("region boundaries: gradient across %.1e, Hessian either side %.1e\n", worstG,
              worstH);
  EXPECT_LT(worstG, 1e-7);
  EXPECT_LT(worstH, 1e-5);
}

TEST(ContactDistance, ParallelEdgesAreExactAndFinite) {
  double worst = 0;
  for (double offset : {-0.5, 0.0, 0.3, 0.9, 1.5})
    for (double angle : {0.0, 1e-9, 1e-7, 1e-5}) {
      const Nodes x{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(offset, 0.2, 0.1),
                    Vec3(offset + std::cos(angle), 0.2 + std::sin(angle), 0.1)};
      const auto s = edgeEdgeDistance(x[0], x[1], x[2], x[3], true);
      const double ref = referenceEdgeEdge2(x[0], x[1], x[2], x[3]);
      worst = std::max(worst, std::abs(s.value - ref) / ref);
      EXPECT_TRUE(s.gradient.allFinite() && s.hessian.allFinite()) << offset << " " << angle;
      EXPECT_LT(s.hessian.cwiseAbs().maxCoeff(), 1e3) << offset << " " << angle;
    }
  std::printf("parallel and near-parallel edges: worst relative error of s %.1e\n", worst);
  EXPECT_LT(worst, 1e-9);
}

TEST(ContactDistance, UnsignedDistanceDerivatives) {
  // d = sqrt(s) down to 1e-6 of the coordinates: gradient and Hessian against central differences
  // with a step below d.
  for (double gap : {0.3, 1e-3, 1e-6})
    for (auto kind : {ContactPairKind::PointTriangle, ContactPairKind::EdgeEdge}) {
      const Nodes x =
          kind == ContactPairKind::PointTriangle
              ? Nodes{Vec3(0.2, 0.3, gap), kA, kB, kC}
              : Nodes{Vec3(0, 0, 0), Vec3(1, 0.1, 0), Vec3(0.5, -0.5, gap), Vec3(0.4, 0.6, gap)};
      const auto d = pairDistance(kind, x, true);
      const double h = std::min(1e-6, 0.3 * gap);  // below the gap: d = 0 is not straddled
      const auto value = [&](const Eigen::VectorXd& y) {
        return pairDistance(kind, unflat(y), false).value;
      };
      const auto grad = [&](const Eigen::VectorXd& y) {
        return Eigen::VectorXd(pairDistance(kind, unflat(y), false).gradient);
      };
      const double eg = relativeError(d.gradient, fdGradient(value, flat(x), h));
      // The central difference's own round-off: the gradient carries ~1e-16 / gap relative error
      // (n = r / d), so the reference is good to ~1e-16 / (gap h) and no better.
      const double eh = relativeError(Eigen::MatrixXd(d.hessian), fdJacobian(grad, flat(x), h));
      const double allowed = std::max(1e-6, 100 * 1e-16 / (gap * h));
      std::printf("  gap %.0e %s: gradient %.1e, Hessian %.1e (allowed %.0e)\n", gap,
                  kind == ContactPairKind::PointTriangle ? "point-triangle" : "edge-edge", eg, eh,
                  allowed);
      EXPECT_LT(eh, allowed);
      EXPECT_LT(eg, 1e-6);
    }
  // Exactly zero: the face's normal, finite, and no Hessian.
  const auto d0 =
      pairDistance(ContactPairKind::PointTriangle, {Vec3(0.2, 0.3, 0), kA, kB, kC}, true);
  EXPECT_EQ(d0.value, 0.0);
  EXPECT_NEAR(std::abs(d0.normal.z()), 1.0, 1e-15);
  EXPECT_TRUE(d0.gradient.allFinite() && d0.hessian.allFinite());
}

// ---- the penalty, mollifier and damping ----

namespace {
const ContactLaw kLaw{2.0e3, 0.05, 0.0};

Eigen::VectorXd residualOf(ContactPairKind kind, const Eigen::VectorXd& y, const Nodes& v,
                           const ContactLaw& law, double eps) {
  return contactPair(kind, unflat(y), v, law, eps, false).residual;
}
}  // namespace

TEST(ContactPotential, PenaltyForceAndStiffnessAgainstCentralDifferences) {
  const Nodes zero{Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  double worstF = 0, worstK = 0;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  int active = 0;
  for (int k = 0; k < 300; ++k) {
    for (auto kind : {ContactPairKind::PointTriangle, ContactPairKind::EdgeEdge}) {
      Nodes x = kind == ContactPairKind::PointTriangle
                    ? Nodes{Vec3(0.3 * u(rng) + 0.2, 0.3 * u(rng) + 0.2, 0.05 * u(rng)), kA, kB, kC}
                    : Nodes{Vec3(0, 0, 0), Vec3(1, 0.5 * u(rng), 0.1 * u(rng)),
                            Vec3(0.5 + 0.3 * u(rng), -0.5, 0.05 * u(rng)),
                            Vec3(0.5 + 0.3 * u(rng), 0.5, 0.05 * u(rng))};
      const double eps = mollifierThreshold(Vec3(1, 0, 0), Vec3(0, 1, 0));
      const auto r = contactPair(kind, x, zero, kLaw, eps, true);
      if (!r.active || r.distance.value < 1e-3) continue;
      ++active;
      const auto energy = [&](const Eigen::VectorXd& y) {
        return contactPair(kind, unflat(y), zero, kLaw, eps, false).energy;
      };
      const auto res = [&](const Eigen::VectorXd& y) {
        return residualOf(kind, y, zero, kLaw, eps);
      };
      const double h = 1e-7;
      worstF = std::max(worstF, relativeError(r.residual, fdGradient(energy, flat(x), h), 1e-6));
      worstK = std::max(
          worstK, relativeError(Eigen::MatrixXd(r.dPosition), fdJacobian(res, flat(x), h), 1e-3));
    }
  }
  std::printf("%d active pairs: force against the energy %.1e, stiffness against the force %.1e\n",
              active, worstF, worstK);
  EXPECT_GT(active, 200);
  EXPECT_LT(worstF, 1e-6);
  EXPECT_LT(worstK, 1e-5);
}

TEST(ContactPotential, ForceIsContinuousAtTheContactThickness) {
  // CT4: C1 at d = dHat: energy and force go to zero there; the central difference of the
  // energy straddling dHat matches the kernel's force (zero) to the step's order.
  const Nodes zero{Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  for (double d : {kLaw.thickness * (1 - 1e-9), kLaw.thickness, kLaw.thickness * (1 + 1e-9)}) {
    const Nodes x{Vec3(0.2, 0.3, d), kA, kB, kC};
    const auto r = contactPair(ContactPairKind::PointTriangle, x, zero, kLaw, 0, false);
    EXPECT_LT(r.residual.norm(), kLaw.stiffness * kLaw.thickness * 2e-9) << d;
    const auto energy = [&](const Eigen::VectorXd& y) {
      return contactPair(ContactPairKind::PointTriangle, unflat(y), zero, kLaw, 0, false).energy;
    };
    const Eigen::VectorXd g = fdGradient(energy, flat(x), 1e-6);
    EXPECT_LT((g - r.residual).norm(), kLaw.stiffness * 1e-6) << d;
  }
  // Approaching zero gap the force tends to k dHat, finite and along the normal.
  const auto r0 = contactPair(ContactPairKind::PointTriangle, {Vec3(0.2, 0.3, 1e-12), kA, kB, kC},
                              zero, kLaw, 0, true);
  EXPECT_NEAR(-r0.residual[2], kLaw.stiffness * kLaw.thickness, 1e-6);
  EXPECT_TRUE(r0.dPosition.allFinite());
}

TEST(ContactPotential, MollifierAgainstCentralDifferencesAndParallelEdges) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  double worstG = 0, worstH = 0;
  const double eps = mollifierThreshold(Vec3(1, 0, 0), Vec3(1, 0, 0));
  for (int k = 0; k < 100; ++k) {
    const double a = 0.05 * u(rng);  // small angles: inside the mollified range
    const Nodes x{Vec3(0, 0, 0), Vec3(1, 0.01 * u(rng), 0), Vec3(0.2 * u(rng), 0.1, 0.02),
                  Vec3(0.2 * u(rng) + std::cos(a), 0.1 + std::sin(a), 0.02 + 0.01 * u(rng))};
    const auto m = edgeEdgeMollifier(x, eps, true);
    const auto value = [&](const Eigen::VectorXd& y) {
      return edgeEdgeMollifier(unflat(y), eps, false).value;
    };
    const auto grad = [&](const Eigen::VectorXd& y) {
      return Eigen::VectorXd(edgeEdgeMollifier(unflat(y), eps, false).gradient);
    };
    worstG = std::max(worstG, relativeError(m.gradient, fdGradient(value, flat(x), 1e-7), 1e-3));
    worstH = std::max(
        worstH, relativeError(Eigen::MatrixXd(m.hessian), fdJacobian(grad, flat(x), 1e-7), 1e-1));
  }
  std::printf("mollifier: gradient %.1e, Hessian %.1e\n", worstG, worstH);
  EXPECT_LT(worstG, 1e-6);
  EXPECT_LT(worstH, 1e-5);
  // Parallel, overlapping edges within dHat: the distance has a kink under rotation about the
  // normal there, the mollified energy is C1 (zero gradient from the mollifier's side, the
  // central difference of the energy matches the kernel's force).
  const Nodes zero{Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  const Nodes par{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.3, 0.0, 0.02), Vec3(1.3, 0.0, 0.02)};
  const auto r = contactPair(ContactPairKind::EdgeEdge, par, zero, kLaw, eps, false);
  EXPECT_TRUE(r.active);
  EXPECT_EQ(r.energy, 0.0);
  const auto energy = [&](const Eigen::VectorXd& y) {
    return contactPair(ContactPairKind::EdgeEdge, unflat(y), zero, kLaw, eps, false).energy;
  };
  const Eigen::VectorXd g = fdGradient(energy, flat(par), 1e-6);
  std::printf("parallel edges in contact: |force| %.1e, central difference of the energy %.1e\n",
              r.residual.norm(), g.norm());
  EXPECT_LT((g - r.residual).norm(), 1e-6 * kLaw.stiffness * kLaw.thickness);
}

TEST(ContactPotential, DampingOnlyWhileApproachingAndItsDerivatives) {
  ContactLaw law = kLaw;
  law.damping = 30.0;
  std::mt19937 rng(21);
  std::normal_distribution<double> nd(0, 1);
  double worstX = 0, worstV = 0, worstPower = -1;
  int approaching = 0, separating = 0;
  const double eps = mollifierThreshold(Vec3(1, 0, 0), Vec3(0, 1, 0));
  for (int k = 0; k < 200; ++k) {
    for (auto kind : {ContactPairKind::PointTriangle, ContactPairKind::EdgeEdge}) {
      const Nodes x =
          kind == ContactPairKind::PointTriangle
              ? Nodes{Vec3(0.2 + 0.05 * nd(rng), 0.3, 0.02 + 0.005 * nd(rng)), kA, kB, kC}
              : Nodes{Vec3(0, 0, 0), Vec3(1, 0.1, 0), Vec3(0.5, -0.5, 0.02 + 0.005 * nd(rng)),
                      Vec3(0.4, 0.6, 0.03)};
      Nodes v;
      for (auto& vi : v) vi = Vec3(nd(rng), nd(rng), nd(rng));
      const auto r = contactPair(kind, x, v, law, eps, true);
      const auto rNoDamp = contactPair(kind, x, v, kLaw, eps, false);
      ASSERT_TRUE(r.active);
      const Eigen::VectorXd rd = r.residual - rNoDamp.residual;
      // Power of the damping force -rd: never positive; zero while separating.
      const double power = -rd.dot(flat(v));
      worstPower = std::max(worstPower, power);
      const double ddot = r.distance.gradient.dot(flat(v));
      if (ddot >= 0) {
        ++separating;
        EXPECT_EQ(rd.norm(), 0.0);
        continue;
      }
      ++approaching;
      const auto byX = [&](const Eigen::VectorXd& y) {
        return Eigen::VectorXd(contactPair(kind, unflat(y), v, law, eps, false).residual);
      };
      const auto byV = [&](const Eigen::VectorXd& w) {
        return Eigen::VectorXd(contactPair(kind, x, unflat(w), law, eps, false).residual);
      };
      worstX = std::max(worstX, relativeError(Eigen::MatrixXd(r.dPosition),
                                              fdJacobian(byX, flat(x), 1e-8), 1e-3));
      worstV = std::max(worstV, relativeError(Eigen::MatrixXd(r.dVelocity),
                                              fdJacobian(byV, flat(v), 1e-6), 1e-3));
    }
  }
  std::printf(
      "damping: %d approaching, %d separating; dr/dx %.1e, dr/dv %.1e, largest power %.1e\n",
      approaching, separating, worstX, worstV, worstPower);
  EXPECT_GT(approaching, 50);
  EXPECT_GT(separating, 50);
  EXPECT_LE(worstPower, 0.0);
  EXPECT_LT(worstX, 1e-5);
  EXPECT_LT(worstV, 1e-6);
}

TEST(ContactFriction, TangentAgainstCentralDifferencesAndNeverSupplyingEnergy) {
  std::mt19937 rng(13);
  std::normal_distribution<double> nd(0, 1);
  const double mu = 0.3, epsV = 1e-2;
  double worstV = 0, worstPower = -1, worstMagnitude = 0;
  int stick = 0, slip = 0;
  for (int k = 0; k < 400; ++k) {
    FrictionLag lag;
    lag.normal = Vec3(nd(rng), nd(rng), nd(rng)).normalized();
    std::uniform_real_distribution<double> uni(0, 1);
    double b = uni(rng), g = uni(rng);
    if (b + g > 1) b = 1 - b, g = 1 - g;
    lag.weight = {1.0, -(1.0 - b - g), -b, -g};
    lag.normalForce = 5.0;
    const double speed = k % 2 ? 0.3 * epsV : 5 * epsV;  // half in stick, half in slip
    Nodes v;
    for (auto& vi : v) vi = speed * Vec3(nd(rng), nd(rng), nd(rng));
    const auto f = contactFriction(lag, v, mu, epsV, true);
    (f.slipSpeed < epsV ? stick : slip)++;
    const auto byV = [&](const Eigen::VectorXd& w) {
      return Eigen::VectorXd(contactFriction(lag, unflat(w), mu, epsV, false).residual);
    };
    const double h = 1e-4 * epsV;
    if (std::abs(f.slipSpeed - epsV) > 1e-2 * epsV)
      worstV = std::max(
          worstV, relativeError(Eigen::MatrixXd(f.dVelocity), fdJacobian(byV, flat(v), h), 1e-6));
    worstPower = std::max(worstPower, -f.residual.dot(flat(v)));
    // |f| at the point-side node at most mu lambda.
    worstMagnitude =
        std::max(worstMagnitude, f.residual.segment<3>(0).norm() / (mu * lag.normalForce));
    // Symmetric positive semi-definite.
    EXPECT_LT((f.dVelocity - f.dVelocity.transpose()).norm(), 1e-12 * f.dVelocity.norm());
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Mat12>(f.dVelocity).eigenvalues().minCoeff(),
              -1e-10 * f.dVelocity.norm());
  }
  std::printf(
      "friction: %d in stick, %d in slip; dr/dv %.1e; largest power %.1e; largest |f| / "
      "(mu lambda) %.3f\n",
      stick, slip, worstV, worstPower, worstMagnitude);
  EXPECT_GT(stick, 100);
  EXPECT_GT(slip, 100);
  EXPECT_LT(worstV, 1e-6);
  EXPECT_LE(worstPower, 0.0);
  EXPECT_LE(worstMagnitude, 1.0 + 1e-12);
}
