#include "kernels/UniformStrainPolyline.hpp"

#include <cmath>

namespace chute::kernels {

PartLength partLength(const Vec3& d, double r, bool withHessian) {
  PartLength p;
  const double n = d.norm();
  if (n >= r) {
    const Vec3 e = d / n;
    p.length = n;
    p.gradient = e;
    if (withHessian) p.hessian = (Mat3::Identity() - e * e.transpose()) / n;
  } else {
    p.length = (n * n + r * r) / (2.0 * r);
    p.gradient = d / r;
    if (withHessian) p.hessian = Mat3::Identity() / r;
  }
  return p;
}

template <int NumNodes>
PolylineResult<NumNodes> uniformStrainPolyline(const std::array<Vec3, NumNodes>& x, double L,
                                               const LineMaterial& mat, bool withTangent) {
  constexpr int kSeg = NumNodes - 1;
  PolylineResult<NumNodes> r;
  std::array<Mat3, kSeg> hess;
  const double apex = kApexFraction * L;

  r.length = 0.0;
  r.dLength.setZero();
  for (int k = 0; k < kSeg; ++k) {
    const PartLength p = partLength(x[k + 1] - x[k], apex, withTangent);
    r.segmentLength[k] = p.length;
    r.segmentGradient[k] = p.gradient;
    if (withTangent) hess[k] = p.hessian;
    r.length += p.length;
    r.dLength.template segment<3>(3 * k) -= p.gradient;
    r.dLength.template segment<3>(3 * (k + 1)) += p.gradient;
  }

  const double L2 = L * L;
  r.strain = uniformStrain(r.length, L);  // F1 / F6
  const double Eeff = strainModulus(r.strain, mat);

  const double EAoverL = Eeff * mat.area / L;
  r.axialForce = EAoverL * r.strain * r.length;  // F2: N = E A0 eps l / L
  r.energy = 0.5 * Eeff * mat.area * L * r.strain * r.strain;
  r.force = r.axialForce * r.dLength;  // F2 / F8: f = N D

  if (!withTangent) return r;  // residual only: no Hessians, no stiffness
  r.stiffness.setZero();
  if (Eeff == 0.0) return r;
  // F3 / F9: K = (E A0/L) [(eps + l^2/L^2) D D^T + eps l G]; G = sum_k h_k [I -I; -I I],
  // h_k = (I - e_k e_k^T) / l_k (I / r at the apex). eps l (E A0 / L) = N: geometric part N G.
  r.stiffness.noalias() =
      EAoverL * (r.strain + r.length * r.length / L2) * (r.dLength * r.dLength.transpose());
  for (int k = 0; k < kSeg; ++k) {
    const Mat3 h = r.axialForce * hess[k];
    r.stiffness.template block<3, 3>(3 * k, 3 * k) += h;
    r.stiffness.template block<3, 3>(3 * (k + 1), 3 * (k + 1)) += h;
    r.stiffness.template block<3, 3>(3 * k, 3 * (k + 1)) -= h;
    r.stiffness.template block<3, 3>(3 * (k + 1), 3 * k) -= h;
  }
  return r;
}

template PolylineResult<2> uniformStrainPolyline<2>(const std::array<Vec3, 2>&, double,
                                                    const LineMaterial&, bool);
template PolylineResult<3> uniformStrainPolyline<3>(const std::array<Vec3, 3>&, double,
                                                    const LineMaterial&, bool);

}  // namespace chute::kernels
