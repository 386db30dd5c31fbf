#include "kernels/CanopyFlow.hpp"

#include <algorithm>
#include <stdexcept>

namespace chute::kernels {

ClothPermeability ClothPermeability::fromTest(double uRef, double dpRef, double inertial) {
  ClothPermeability c;
  if (!(uRef > 0.0)) return c;  // impermeable
  if (!(dpRef > 0.0) || !(inertial >= 0.0) || inertial * uRef * uRef >= dpRef)
    throw std::invalid_argument("cloth permeability: the test point leaves no viscous part");
  c.inertial = inertial;
  c.viscous = (dpRef - inertial * uRef * uRef) / uRef;
  c.perViscous = 1.0 / c.viscous;
  return c;
}

double orificeFlow(double dp, double area, double cd, double rho, double dpLinear) {
  const double k = cd * area * std::sqrt(2.0 / rho);
  const double a = std::abs(dp);
  const double q = a >= dpLinear ? k * std::sqrt(a) : k * std::sqrt(dpLinear) * (a / dpLinear);
  return dp < 0.0 ? -q : q;
}

double dOrificeFlow(double dp, double area, double cd, double rho, double dpLinear) {
  const double k = cd * area * std::sqrt(2.0 / rho);
  const double a = std::abs(dp);
  return a >= dpLinear ? 0.5 * k / std::sqrt(a) : k / std::sqrt(dpLinear);
}

template <int NumNodes>
CanopyFaceLoad<NumNodes> canopyFaceLoad(const std::array<Eigen::Vector3d, NumNodes>& x,
                                        const std::array<Eigen::Vector3d, NumNodes>& v,
                                        const CanopyFlowState& s, bool withTangent) {
  CanopyFaceLoad<NumNodes> out;
  out.residual.setZero();
  if (withTangent) {
    out.dPosition.setZero();
    out.dVelocity.setZero();
  }
  const Vec3 A = areaVector<NumNodes>(x);
  const double area = A.norm();
  out.area = area;
  if (area == 0.0) return out;  // a degenerate face carries nothing
  const Vec3 n = A / area;
  Vec3 vf = Vec3::Zero();
  for (const auto& vi : v) vf += vi;
  vf /= NumNodes;
  const Vec3 rel = vf - s.canopyVelocity;
  const FacePressure fp = facePressure(n, vf, s);
  const double c = fp.c, un = fp.un;
  out.staticDifference = fp.staticDifference;
  out.netPressure = fp.netPressure;
  const double share = 1.0 / NumNodes;
  for (int i = 0; i < NumNodes; ++i)
    out.residual.template segment<3>(3 * i) = -share * out.netPressure * A;
  if (!withTangent) return out;
  // d net / dn, then through n = A / |A|; d net / dv_j through u_n.
  const Eigen::RowVector3d dNetDn = -s.dynamicPressure *
                                        dOutsidePressureCoefficient(c, s.baseCoefficient) *
                                        s.flowDirection.transpose() -
                                    dNormalMotionPressure(s.normalDrag, un) * rel.transpose();
  const Eigen::Matrix<double, 3, 3 * NumNodes> dA = areaVectorJacobian<NumNodes>(x);
  const Eigen::Matrix<double, 1, 3 * NumNodes> dNetDx =
      dNetDn * (Eigen::Matrix3d::Identity() - n * n.transpose()) / area * dA;
  const Eigen::RowVector3d dNetDvj =
      -dNormalMotionPressure(s.normalDrag, un) * share * n.transpose();
  const Eigen::Matrix<double, 3, 3 * NumNodes> dr = -share * (A * dNetDx + out.netPressure * dA);
  const Eigen::Matrix3d drdv = -share * A * dNetDvj;
  for (int i = 0; i < NumNodes; ++i) {
    out.dPosition.template block<3, 3 * NumNodes>(3 * i, 0) = dr;
    for (int j = 0; j < NumNodes; ++j) out.dVelocity.template block<3, 3>(3 * i, 3 * j) = drdv;
  }
  return out;
}

template CanopyFaceLoad<3> canopyFaceLoad<3>(const std::array<Eigen::Vector3d, 3>&,
                                             const std::array<Eigen::Vector3d, 3>&,
                                             const CanopyFlowState&, bool);
template CanopyFaceLoad<4> canopyFaceLoad<4>(const std::array<Eigen::Vector3d, 4>&,
                                             const std::array<Eigen::Vector3d, 4>&,
                                             const CanopyFlowState&, bool);

}  // namespace chute::kernels
