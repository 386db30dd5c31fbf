#include "kernels/ContactFriction.hpp"

#include <cmath>

namespace chute::kernels {

FrictionResponse contactFriction(const FrictionLag& lag, const std::array<Vec3, 4>& v, double mu,
                                 double epsV, bool withTangent) {
  FrictionResponse out;
  const double scale = mu * lag.normalForce;
  if (!(scale > 0.0)) return out;
  Vec3 vr = Vec3::Zero();
  for (int i = 0; i < 4; ++i) vr += lag.weight[i] * v[i];
  const Vec3& n = lag.normal;
  const Vec3 u = vr - n * n.dot(vr);
  const double y = u.norm();
  out.slipSpeed = y;
  // CT7: phi = f1(y) / y, and phi' / y for the tangent (its limit 0 times u u^T as y -> 0).
  const bool stick = y < epsV;
  const double phi = stick ? 2.0 / epsV - y / (epsV * epsV) : 1.0 / y;
  for (int i = 0; i < 4; ++i) out.residual.segment<3>(3 * i) = scale * lag.weight[i] * phi * u;
  if (!withTangent) return out;
  const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - n * n.transpose();
  Eigen::Matrix3d block = phi * P;
  if (y > 0.0) block += (stick ? -1.0 / (epsV * epsV * y) : -1.0 / (y * y * y)) * u * u.transpose();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      out.dVelocity.block<3, 3>(3 * i, 3 * j) = scale * lag.weight[i] * lag.weight[j] * block;
  return out;
}

}  // namespace chute::kernels
