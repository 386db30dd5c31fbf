#pragma once
// Drag on a line element relative to a wind (docs/formulation.md section 6).
#include <Eigen/Core>

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
// What residual and tangents share (LD1): the element's length l and direction e, the projector
// P = I - e e^T, the relative velocity v and its normal part u = P v with |u| = s, and the node
// residual (c l / 2) |u| u. none: a zero-length element or no drag, which carries nothing.
struct LineFlow {
  bool none = true;
  Vec3 e, v, u, r;
  Mat3 P;
  double l = 0.0, s = 0.0;
};

// Inlined into both callers, so that the residual-only one needs no P at all.
[[gnu::always_inline]] inline LineFlow lineFlow(const Vec3& xa, const Vec3& xb, const Vec3& va,
                                                const Vec3& vb, const Vec3& wind,
                                                double coefficient) {
  LineFlow f;
  const Vec3 d = xb - xa;
  f.l = d.norm();
  if (f.l == 0.0 || coefficient == 0.0) return f;
  f.none = false;
  f.e = d / f.l;
  f.v = 0.5 * (va + vb) - wind;
  // P = I - e e^T and the normal relative velocity u = P v, entry by entry in the order of the
  // matrix expressions (rows 0 and 1 summed over the columns in turn, row 2 as Eigen's scalar
  // tail, P20 v0 + (P21 v1 + P22 v2)): the same bits. Eigen's 3 x 3 P went through memory and
  // was read back across the stores' boundaries, a stall (perf, the explicit C-9).
  const Vec3 &e = f.e, &v = f.v;
  double P[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) P[i][j] = (i == j ? 1.0 : 0.0) - e[i] * e[j];
  f.P << P[0][0], P[0][1], P[0][2], P[1][0], P[1][1], P[1][2], P[2][0], P[2][1], P[2][2];
  f.u = Vec3((P[0][0] * v[0] + P[0][1] * v[1]) + P[0][2] * v[2],
             (P[1][0] * v[0] + P[1][1] * v[1]) + P[1][2] * v[2],
             P[2][0] * v[0] + (P[2][1] * v[1] + P[2][2] * v[2]));
  f.s = f.u.norm();
  // Residual (minus the drag force) on each node: (c l / 2) |u| u.
  f.r = 0.5 * coefficient * f.l * f.s * f.u;
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
