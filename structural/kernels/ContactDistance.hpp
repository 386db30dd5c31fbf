#pragma once
// Distances between the primitives of fabric contact (docs/contact.md CT1-CT3): a point and a
// triangle, and two segments (edge-edge). Pure functions of the four nodes' positions.
//
// The closest points are found by classifying the configuration into its closest-feature
// region (CT1: vertex, edge or face of the triangle; interior or end point of each segment). In
// each region the separation vector is affine in the nodes and in the region's free parameters
// u (barycentric coordinates, segment parameters),
//   r(x, u) = sum_i w_i(u) x_i,   w(u) = w0 + sum_k u_k dw_k,
// and the squared distance is s(x) = min_u |r(x, u)|^2. Its derivatives follow from the
// envelope theorem and the implicit function theorem (CT2):
//   grad s = f_x,   Hess s = f_xx - f_xu f_uu^{-1} f_ux,   f = |r|^2,
// one formula for every region (no region-specific algebra to get wrong). Across a region
// boundary s and grad s are continuous (the distance to a convex set is C1 away from it); the
// Hessian jumps. Near-parallel edges make f_uu singular: the edge-edge potential is multiplied
// by a mollifier that vanishes there (CT5), and a configuration within kParallel of parallel is
// classified into its end-point regions, where f_uu is well conditioned.
#include <Eigen/Core>
#include <algorithm>
#include <array>

namespace chute::kernels {

using Vec3 = Eigen::Vector3d;
using Vec12 = Eigen::Matrix<double, 12, 1>;
using Mat12 = Eigen::Matrix<double, 12, 12>;

// Closest-feature regions (CT1). Point-triangle: the point against a vertex, an edge or the face
// of triangle (a, b, c). Edge-edge: which parameters of the two segments are interior.
enum class PointTriangleRegion { VertexA, VertexB, VertexC, EdgeAB, EdgeBC, EdgeCA, Face };
enum class EdgeEdgeRegion { Interior, EndOfFirst, EndOfSecond, EndToEnd };

// The squared distance of one pair of primitives on its four nodes (point, a, b, c) or
// (a0, a1, b0, b1), with the closest-point weights: r = sum_i weight_i x_i is the separation
// vector from the second primitive's closest point to the first's (weights of the first
// primitive's nodes are >= 0 and sum to 1, the second's <= 0 and sum to -1).
struct SquaredDistance {
  double value = 0.0;
  Vec3 separation = Vec3::Zero();  // r
  std::array<double, 4> weight{};  // w_i at the closest points
  Vec12 gradient = Vec12::Zero();  // d s / d x
  Mat12 hessian = Mat12::Zero();   // set only withHessian
};

// Below this |e1 x e2|^2 / (|e1|^2 |e2|^2) (a sine squared) two edges count as parallel: the
// interior region is not used (its f_uu would be singular, and the mollifier of CT5 is below
// 1e-9 there, so the choice moves the energy by less than 1e-9 of a pair's).
constexpr double kParallel = 1e-12;

PointTriangleRegion classifyPointTriangle(const Vec3& p, const Vec3& a, const Vec3& b,
                                          const Vec3& c);
// The closest parameters s (on a0 -> a1) and t (on b0 -> b1) and the region they lie in.
struct SegmentParameters {
  double s = 0.0, t = 0.0;
  EdgeEdgeRegion region = EdgeEdgeRegion::EndToEnd;
};
SegmentParameters classifyEdgeEdge(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1);

// The squared distance alone, without derivatives (the narrow phase's test of every candidate).
double pointTriangleSquaredDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);
double edgeEdgeSquaredDistance(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1);

SquaredDistance pointTriangleDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                                      bool withHessian);
SquaredDistance edgeEdgeDistance(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1,
                                 bool withHessian);

// The unsigned distance d = sqrt(s) with its derivatives (CT2): grad d = sum_i w_i n (n = r / d,
// the envelope theorem, well defined for any d > 0), Hess d = (Hess s - 2 grad d grad d^T) / (2d).
// At d = 0 the direction is that of `fallbackNormal` (a point-triangle pair in its face region:
// the triangle's normal), and the Hessian is left zero.
struct Distance {
  double value = 0.0;
  Vec3 normal = Vec3::Zero();  // n: unit separation
  std::array<double, 4> weight{};
  Vec12 gradient = Vec12::Zero();
  Mat12 hessian = Mat12::Zero();  // set only withHessian
};
Distance unsignedDistance(const SquaredDistance& s, const Vec3& fallbackNormal, bool withHessian);

// A cheap test that a pair is farther apart than r (CT10): the bounding boxes of its two
// primitives (the point alone, or nodes 1-3 of a point-triangle pair; nodes 0-1 and 2-3 of an
// edge pair) are more than r apart along some axis. false says nothing.
inline bool boxesApart(bool pointTriangle, const std::array<Vec3, 4>& x, double r) {
  const int split = pointTriangle ? 1 : 2;
  for (int k = 0; k < 3; ++k) {
    double lo0 = x[0][k], hi0 = x[0][k], lo1 = x[split][k], hi1 = x[split][k];
    for (int i = 1; i < split; ++i) lo0 = std::min(lo0, x[i][k]), hi0 = std::max(hi0, x[i][k]);
    for (int i = split + 1; i < 4; ++i) lo1 = std::min(lo1, x[i][k]), hi1 = std::max(hi1, x[i][k]);
    if (lo0 - hi1 > r || lo1 - hi0 > r) return true;
  }
  return false;
}

}  // namespace chute::kernels
