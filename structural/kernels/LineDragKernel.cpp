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
  const detail::LineFlow f = detail::lineFlow(xa, xb, va, vb, wind, coefficient);
  if (f.none) return out;
  out.residual << f.r, f.r;
  if (!withTangent || f.uu == 0.0) return out;
  const Vec3 &v = f.v, &u = f.u;
  const double l = std::sqrt(f.dd), s = std::sqrt(f.uu);
  const Vec3 e = f.d / l;
  const Mat3 P = Mat3::Identity() - e * e.transpose();
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
