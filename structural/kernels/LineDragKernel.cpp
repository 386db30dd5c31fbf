#include "kernels/LineDragKernel.hpp"

namespace chute::kernels {

// ---- line drag ---------------------------------------------------------------------------------
LineDrag lineDrag(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb, const Vec3& wind,
                  double coefficient, bool withTangent) {
  LineDrag out;
  out.residual.setZero();
  if (withTangent) {  // residual-only evaluations (explicit steps) never read them
    out.dPosition.setZero();
    out.dVelocity.setZero();
  }
  const Vec3 d = xb - xa;
  const double l = d.norm();
  if (l == 0.0 || coefficient == 0.0) return out;
  const Vec3 e = d / l;
  const Mat3 P = Mat3::Identity() - e * e.transpose();
  const Vec3 v = 0.5 * (va + vb) - wind;
  const Vec3 u = P * v;  // normal relative velocity
  const double s = u.norm();
  // Residual (minus the drag force) on each node: (c l / 2) |u| u.
  const Vec3 r = 0.5 * coefficient * l * s * u;
  out.residual << r, r;
  if (!withTangent || s == 0.0) return out;
  const Mat3 dQdu = s * Mat3::Identity() + u * u.transpose() / s;  // d(|u| u)/du
  const Mat3 dv = 0.5 * coefficient * l * dQdu * P * 0.5;          // per node velocity
  const Mat3 dxb =
      0.5 * coefficient *
      (s * u * e.transpose() - dQdu * (e * v.transpose() + v.dot(e) * Mat3::Identity()) * P);
  for (int i = 0; i < 2; ++i) {
    out.dVelocity.block<3, 3>(3 * i, 0) = dv;
    out.dVelocity.block<3, 3>(3 * i, 3) = dv;
    out.dPosition.block<3, 3>(3 * i, 0) = -dxb;
    out.dPosition.block<3, 3>(3 * i, 3) = dxb;
  }
  return out;
}

}  // namespace chute::kernels
