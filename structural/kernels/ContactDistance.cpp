#include "kernels/ContactDistance.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace chute::kernels {

namespace {

using Weights = std::array<double, 4>;

// A region's separation vector, affine in its free parameters (CT2): w(u) = w0 + sum_k u_k dw_k.
struct AffineRegion {
  Weights w0{};
  std::array<Weights, 2> dw{};
  int numFree = 0;
};

double clamp01(double v) {
  return std::clamp(v, 0.0, 1.0);
}

// CT2: the squared distance of a region and its derivatives; the region's optimum u* solves
// f_u = 0 (the classification put it inside the region), then
//   grad s = f_x,  Hess s = f_xx - f_xu f_uu^{-1} f_ux.
SquaredDistance closestPair(const std::array<Vec3, 4>& x, const AffineRegion& region,
                            bool withHessian) {
  const int m = region.numFree;
  Vec3 r0 = Vec3::Zero();
  std::array<Vec3, 2> g{Vec3::Zero(), Vec3::Zero()};
  for (int i = 0; i < 4; ++i) {
    r0 += region.w0[i] * x[i];
    for (int k = 0; k < m; ++k) g[k] += region.dw[k][i] * x[i];
  }
  Eigen::Matrix2d gg = Eigen::Matrix2d::Identity();
  Eigen::Vector2d u = Eigen::Vector2d::Zero();
  if (m == 1) {
    gg(0, 0) = g[0].squaredNorm();
    u[0] = -g[0].dot(r0) / gg(0, 0);
  } else if (m == 2) {
    gg << g[0].squaredNorm(), g[0].dot(g[1]), g[0].dot(g[1]), g[1].squaredNorm();
    u = gg.inverse() * Eigen::Vector2d(-g[0].dot(r0), -g[1].dot(r0));
  }
  SquaredDistance out;
  Vec3 r = r0;
  for (int k = 0; k < m; ++k) r += u[k] * g[k];
  for (int i = 0; i < 4; ++i) {
    double w = region.w0[i];
    for (int k = 0; k < m; ++k) w += u[k] * region.dw[k][i];
    out.weight[i] = w;
    out.gradient.segment<3>(3 * i) = 2.0 * w * r;
  }
  out.separation = r;
  out.value = r.squaredNorm();
  if (!withHessian) return out;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      out.hessian.block<3, 3>(3 * i, 3 * j)
          .diagonal()
          .setConstant(2.0 * out.weight[i] * out.weight[j]);
  if (m == 0) return out;
  Eigen::Matrix<double, 12, 2> f = Eigen::Matrix<double, 12, 2>::Zero();
  for (int k = 0; k < m; ++k)
    for (int i = 0; i < 4; ++i)
      f.block<3, 1>(3 * i, k) = 2.0 * region.dw[k][i] * r + 2.0 * out.weight[i] * g[k];
  if (m == 1) {
    out.hessian -= f.col(0) * f.col(0).transpose() / (2.0 * gg(0, 0));
  } else {
    out.hessian -= f * (2.0 * gg).inverse() * f.transpose();
  }
  return out;
}

// The nearest point of segment a -> b to p: its parameter, clamped to [0, 1].
double segmentParameter(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 e = b - a;
  const double ee = e.squaredNorm();
  return ee > 0.0 ? clamp01((p - a).dot(e) / ee) : 0.0;
}

// A degenerate triangle (collinear corners) has no face region: the nearest of its edges.
PointTriangleRegion nearestEdgeRegion(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const std::array<PointTriangleRegion, 3> edges{
      PointTriangleRegion::EdgeAB, PointTriangleRegion::EdgeBC, PointTriangleRegion::EdgeCA};
  const std::array<const Vec3*, 4> v{&a, &b, &c, &a};
  const std::array<std::array<PointTriangleRegion, 2>, 3> ends{
      {{PointTriangleRegion::VertexA, PointTriangleRegion::VertexB},
       {PointTriangleRegion::VertexB, PointTriangleRegion::VertexC},
       {PointTriangleRegion::VertexC, PointTriangleRegion::VertexA}}};
  double best = -1.0;
  PointTriangleRegion region = PointTriangleRegion::VertexA;
  for (int k = 0; k < 3; ++k) {
    const double t = segmentParameter(p, *v[k], *v[k + 1]);
    const double d2 = (p - (*v[k] + t * (*v[k + 1] - *v[k]))).squaredNorm();
    if (best >= 0.0 && d2 >= best) continue;
    best = d2;
    region = t <= 0.0 ? ends[k][0] : t >= 1.0 ? ends[k][1] : edges[k];
  }
  return region;
}

AffineRegion pointTriangleRegion(PointTriangleRegion region) {
  using R = PointTriangleRegion;
  AffineRegion a;
  switch (region) {
    case R::VertexA:
      a.w0 = {1, -1, 0, 0};
      break;
    case R::VertexB:
      a.w0 = {1, 0, -1, 0};
      break;
    case R::VertexC:
      a.w0 = {1, 0, 0, -1};
      break;
    case R::EdgeAB:  // p - a - t (b - a)
      a.w0 = {1, -1, 0, 0}, a.dw[0] = {0, 1, -1, 0}, a.numFree = 1;
      break;
    case R::EdgeBC:  // p - b - t (c - b)
      a.w0 = {1, 0, -1, 0}, a.dw[0] = {0, 0, 1, -1}, a.numFree = 1;
      break;
    case R::EdgeCA:  // p - c - t (a - c)
      a.w0 = {1, 0, 0, -1}, a.dw[0] = {0, -1, 0, 1}, a.numFree = 1;
      break;
    case R::Face:  // p - a - beta (b - a) - gamma (c - a)
      a.w0 = {1, -1, 0, 0}, a.dw[0] = {0, 1, -1, 0}, a.dw[1] = {0, 1, 0, -1}, a.numFree = 2;
      break;
  }
  return a;
}

}  // namespace

// CT1: the Voronoi regions of the triangle's vertices and edges, tested in turn with the
// barycentric sign tests; what is left is the face.
PointTriangleRegion classifyPointTriangle(const Vec3& p, const Vec3& a, const Vec3& b,
                                          const Vec3& c) {
  using R = PointTriangleRegion;
  const Vec3 ab = b - a, ac = c - a;
  const Vec3 n = ab.cross(ac);
  if (!(n.squaredNorm() > kParallel * ab.squaredNorm() * ac.squaredNorm()))
    return nearestEdgeRegion(p, a, b, c);
  const Vec3 ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return R::VertexA;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return R::VertexB;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return R::VertexC;
  if (d1 * d4 - d3 * d2 <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return R::EdgeAB;
  if (d5 * d2 - d1 * d6 <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return R::EdgeCA;
  if (d3 * d6 - d5 * d4 <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) return R::EdgeBC;
  return R::Face;
}

// CT1: the closest parameters of two segments, clamped to [0, 1]: s from the lines' closest
// points (s = 0 for parallel segments, where any s of the overlap is as close), t from s, and s
// again from a clamped t.
SegmentParameters classifyEdgeEdge(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1) {
  const Vec3 d1 = a1 - a0, d2 = b1 - b0, r = a0 - b0;
  const double A = d1.squaredNorm(), E = d2.squaredNorm();
  const double B = d1.dot(d2), C = d1.dot(r), F = d2.dot(r);
  SegmentParameters out;
  if (!(A > 0.0) && !(E > 0.0)) {
    out.s = out.t = 0.0;
  } else if (!(A > 0.0)) {
    out.s = 0.0, out.t = clamp01(F / E);
  } else if (!(E > 0.0)) {
    out.t = 0.0, out.s = clamp01(-C / A);
  } else {
    const double denom = A * E - B * B;
    out.s = denom > kParallel * A * E ? clamp01((B * F - C * E) / denom) : 0.0;
    out.t = (B * out.s + F) / E;
    if (out.t < 0.0) {
      out.t = 0.0, out.s = clamp01(-C / A);
    } else if (out.t > 1.0) {
      out.t = 1.0, out.s = clamp01((B - C) / A);
    }
  }
  const bool sFree = out.s > 0.0 && out.s < 1.0 && A > 0.0;
  const bool tFree = out.t > 0.0 && out.t < 1.0 && E > 0.0;
  // Parallel segments (within kParallel) keep s at an end above, so never reach the interior
  // region, whose f_uu would be singular.
  if (sFree && tFree) {
    out.region = EdgeEdgeRegion::Interior;
  } else if (tFree) {
    out.region = EdgeEdgeRegion::EndOfFirst;
  } else if (sFree) {
    out.region = EdgeEdgeRegion::EndOfSecond;
  } else {
    out.region = EdgeEdgeRegion::EndToEnd;
  }
  return out;
}

double pointTriangleSquaredDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  using R = PointTriangleRegion;
  const auto onSegment = [&](const Vec3& u, const Vec3& w) {
    const double t = segmentParameter(p, u, w);
    return (p - (u + t * (w - u))).squaredNorm();
  };
  switch (classifyPointTriangle(p, a, b, c)) {
    case R::VertexA:
      return (p - a).squaredNorm();
    case R::VertexB:
      return (p - b).squaredNorm();
    case R::VertexC:
      return (p - c).squaredNorm();
    case R::EdgeAB:
      return onSegment(a, b);
    case R::EdgeBC:
      return onSegment(b, c);
    case R::EdgeCA:
      return onSegment(c, a);
    case R::Face: {
      const Vec3 n = (b - a).cross(c - a);
      const double h = n.dot(p - a);
      return h * h / n.squaredNorm();
    }
  }
  return 0.0;
}

double edgeEdgeSquaredDistance(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1) {
  const SegmentParameters sp = classifyEdgeEdge(a0, a1, b0, b1);
  return (a0 + sp.s * (a1 - a0) - b0 - sp.t * (b1 - b0)).squaredNorm();
}

SquaredDistance pointTriangleDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                                      bool withHessian) {
  return closestPair({p, a, b, c}, pointTriangleRegion(classifyPointTriangle(p, a, b, c)),
                     withHessian);
}

SquaredDistance edgeEdgeDistance(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1,
                                 bool withHessian) {
  const SegmentParameters sp = classifyEdgeEdge(a0, a1, b0, b1);
  AffineRegion region;
  // r = (1 - s) a0 + s a1 - (1 - t) b0 - t b1
  switch (sp.region) {
    case EdgeEdgeRegion::Interior:
      region.w0 = {1, 0, -1, 0}, region.dw[0] = {-1, 1, 0, 0}, region.dw[1] = {0, 0, 1, -1};
      region.numFree = 2;
      break;
    case EdgeEdgeRegion::EndOfFirst:
      region.w0 = {1 - sp.s, sp.s, -1, 0}, region.dw[0] = {0, 0, 1, -1}, region.numFree = 1;
      break;
    case EdgeEdgeRegion::EndOfSecond:
      region.w0 = {1, 0, -(1 - sp.t), -sp.t}, region.dw[0] = {-1, 1, 0, 0}, region.numFree = 1;
      break;
    case EdgeEdgeRegion::EndToEnd:
      region.w0 = {1 - sp.s, sp.s, -(1 - sp.t), -sp.t};
      break;
  }
  return closestPair({a0, a1, b0, b1}, region, withHessian);
}

Distance unsignedDistance(const SquaredDistance& s, const Vec3& fallbackNormal, bool withHessian) {
  Distance out;
  out.value = std::sqrt(s.value);
  out.weight = s.weight;
  out.normal = out.value > 0.0 ? Vec3(s.separation / out.value) : fallbackNormal;
  for (int i = 0; i < 4; ++i) out.gradient.segment<3>(3 * i) = s.weight[i] * out.normal;
  if (withHessian && out.value > 0.0)
    out.hessian = (s.hessian - 2.0 * out.gradient * out.gradient.transpose()) / (2.0 * out.value);
  return out;
}

}  // namespace chute::kernels
