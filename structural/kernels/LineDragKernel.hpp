#pragma once
// Drag on a line element relative to a wind (docs/formulation.md section 6).
#include <Eigen/Core>
#include <cmath>

namespace chute::kernels {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

// Drag on a line element of diameter d (docs/formulation.md section 6):
// f = -(1/2) rho_air Cd d l |v_n| v_n, v_n the air-relative velocity normal to the element, shared
// equally by the two nodes. Returned as the residual contribution r = -f (per node: half), with
// its derivatives with respect to the nodal positions and velocities.
struct LineDrag {
  Eigen::Matrix<double, 6, 1> residual;
  Eigen::Matrix<double, 6, 6> dPosition;  // set only withTangent
  Eigen::Matrix<double, 6, 6> dVelocity;  // set only withTangent
};
LineDrag lineDrag(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb, const Vec3& wind,
                  double coefficient /* (1/2) rho_air Cd d */, bool withTangent);

namespace detail {
// What residual and tangents share (LD1): the element's chord d = x_b - x_a and |d|^2, the
// relative velocity v and its normal part u = v - d (d.v) / |d|^2, |u|^2, and the node residual
// (c l / 2) |u| u. none: a zero-length element or no drag, which carries nothing.
struct LineFlow {
  bool none = true;
  Vec3 d, v, u, r;
  double dd = 0.0, uu = 0.0;
};

// Inlined into both callers. l |u| is taken as sqrt(|d|^2 |u|^2): one square root and one
// division on the residual's path, where the unit direction and |u| each took their own (the
// three waited on one another: 0.85 of a membrane triangle per segment, perf, the explicit C-9
// slider case). The tangent makes e, l, P and |u| from these.
[[gnu::always_inline]] inline LineFlow lineFlow(const Vec3& xa, const Vec3& xb, const Vec3& va,
                                                const Vec3& vb, const Vec3& wind,
                                                double coefficient) {
  LineFlow f;
  f.d = xb - xa;
  f.dd = f.d.squaredNorm();
  if (f.dd == 0.0 || coefficient == 0.0) return f;
  f.none = false;
  f.v = 0.5 * (va + vb) - wind;
  f.u = f.v - (f.d.dot(f.v) / f.dd) * f.d;
  f.uu = f.u.squaredNorm();
  // Residual (minus the drag force) on each node: (c l / 2) |u| u.
  f.r = (0.5 * coefficient * std::sqrt(f.dd * f.uu)) * f.u;
  return f;
}
}  // namespace detail

// Residual-only lineDrag: the residual each of the two nodes gets, the same operations as
// lineDrag's and so bit for bit each of its halves, without its two tangent matrices (the
// explicit path evaluates it every step on every line element). Inline, as faceDragNodeResidual:
// called across files, the nodes' positions and velocities went through memory to the call.
inline Vec3 lineDragNodeResidual(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb,
                                 const Vec3& wind, double coefficient) {
  const detail::LineFlow f = detail::lineFlow(xa, xb, va, vb, wind, coefficient);
  return f.none ? Vec3::Zero() : f.r;
}

}  // namespace chute::kernels
