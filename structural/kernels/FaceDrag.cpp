#include "kernels/FaceDrag.hpp"

#include <cmath>

#include "kernels/PressureKernel.hpp"

namespace chute::kernels {

template <int NumNodes>
FaceDrag<NumNodes> faceDrag(const std::array<Vec3, NumNodes>& x,
                            const std::array<Vec3, NumNodes>& v, const Vec3& wind,
                            double coefficient, bool steadySubtracted, bool withTangent) {
  FaceDrag<NumNodes> out;
  out.residual.setZero();
  if (withTangent) {  // residual-only evaluations (explicit steps) never read them
    out.dPosition.setZero();
    out.dVelocity.setZero();
  }
  const detail::FaceFlow f = detail::faceFlow<NumNodes>(x, v, wind, coefficient, steadySubtracted);
  if (f.none) return out;
  const Vec3 &a = f.a, &rel = f.rel;
  const double s = f.s, g = f.g;
  const double share = coefficient / NumNodes;  // per node
  for (int i = 0; i < NumNodes; ++i) out.residual.template segment<3>(3 * i) = share * g * a;
  if (!withTangent) return out;
  const double area = std::sqrt(f.aa);
  const Vec3 n = a / area;
  const double u = rel.dot(n), u0 = -wind.dot(n);
  // Velocity: du/dv_j = n^T / N, d(|u| u)/du = 2 |u|.
  const Mat3 dv = share * 2.0 * std::abs(u) / NumNodes * a * n.transpose();
  // Position: dn/dx = (I - n n^T) / |a| da/dx; dg/dx = (2|u| rel + 2 s |u0| w)^T dn/dx.
  const Eigen::Matrix<double, 3, 3 * NumNodes> dA = areaVectorJacobian<NumNodes>(x);
  const Eigen::Matrix<double, 3, 3 * NumNodes> dn =
      (Mat3::Identity() - n * n.transpose()) / area * dA;
  const Eigen::Matrix<double, 1, 3 * NumNodes> dg =
      (2.0 * std::abs(u) * rel + 2.0 * s * std::abs(u0) * wind).transpose() * dn;
  const Eigen::Matrix<double, 3, 3 * NumNodes> dr = share * (a * dg + g * dA);
  for (int i = 0; i < NumNodes; ++i) {
    out.dPosition.template block<3, 3 * NumNodes>(3 * i, 0) = dr;
    for (int j = 0; j < NumNodes; ++j) out.dVelocity.template block<3, 3>(3 * i, 3 * j) = dv;
  }
  return out;
}

template FaceDrag<3> faceDrag<3>(const std::array<Vec3, 3>&, const std::array<Vec3, 3>&,
                                 const Vec3&, double, bool, bool);
template FaceDrag<4> faceDrag<4>(const std::array<Vec3, 4>&, const std::array<Vec3, 4>&,
                                 const Vec3&, double, bool, bool);

}  // namespace chute::kernels
