#include "kernels/FaceDrag.hpp"

#include <cmath>

#include "kernels/PressureKernel.hpp"

namespace chute::kernels {

namespace {
// What residual and tangents share (FD1): the area vector a = |a| n, the face's velocity relative
// to the wind rel, u = rel . n, u0 = -w . n and g = |u| u - s |u0| u0. none: a degenerate face or
// no drag, which carries nothing.
struct FaceFlow {
  bool none = true;
  Vec3 a, n, rel;
  double area = 0.0, u = 0.0, u0 = 0.0, s = 0.0, g = 0.0;
};

template <int NumNodes>
FaceFlow faceFlow(const std::array<Vec3, NumNodes>& x, const std::array<Vec3, NumNodes>& v,
                  const Vec3& wind, double coefficient, bool steadySubtracted) {
  FaceFlow f;
  f.a = areaVector<NumNodes>(x);
  f.area = f.a.norm();
  if (f.area == 0.0 || coefficient == 0.0) return f;
  f.none = false;
  f.n = f.a / f.area;
  Vec3 vFace = Vec3::Zero();
  for (const auto& vi : v) vFace += vi;
  vFace /= NumNodes;
  f.rel = vFace - wind;
  f.u = f.rel.dot(f.n);
  f.s = steadySubtracted ? 1.0 : 0.0;
  f.u0 = -wind.dot(f.n);
  f.g = std::abs(f.u) * f.u - f.s * std::abs(f.u0) * f.u0;  // |u| u - s |u0| u0
  return f;
}
}  // namespace

template <int NumNodes>
Vec3 faceDragNodeResidual(const std::array<Vec3, NumNodes>& x, const std::array<Vec3, NumNodes>& v,
                          const Vec3& wind, double coefficient, bool steadySubtracted) {
  const FaceFlow f = faceFlow<NumNodes>(x, v, wind, coefficient, steadySubtracted);
  if (f.none) return Vec3::Zero();
  const double share = coefficient / NumNodes;  // per node
  return share * f.g * f.a;
}

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
  const FaceFlow f = faceFlow<NumNodes>(x, v, wind, coefficient, steadySubtracted);
  if (f.none) return out;
  const Vec3 &a = f.a, &n = f.n, &rel = f.rel;
  const double area = f.area, u = f.u, u0 = f.u0, s = f.s, g = f.g;
  const double share = coefficient / NumNodes;  // per node
  for (int i = 0; i < NumNodes; ++i) out.residual.template segment<3>(3 * i) = share * g * a;
  if (!withTangent) return out;
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
template Vec3 faceDragNodeResidual<3>(const std::array<Vec3, 3>&, const std::array<Vec3, 3>&,
                                      const Vec3&, double, bool);
template Vec3 faceDragNodeResidual<4>(const std::array<Vec3, 4>&, const std::array<Vec3, 4>&,
                                      const Vec3&, double, bool);

}  // namespace chute::kernels
