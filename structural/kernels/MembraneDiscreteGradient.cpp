#include "kernels/MembraneDiscreteGradient.hpp"

#include <Eigen/Dense>

namespace chute::kernels {

GonzalezStress gonzalezStress(const Vec3& e0, const Vec3& e1, double E, double nu, bool wrinkling,
                              double chi) {
  GonzalezStress g;
  const Vec3 de = e1 - e0, em = 0.5 * (e0 + e1);
  const PlaneStress pm = planeStressSVK(em, E, nu, wrinkling);
  g.S = pm.stress;
  g.dSdE1 = 0.5 * pm.tangent;
  const double dd = de.squaredNorm();
  const double scale = std::max(e0.norm(), e1.norm());
  const PlaneStress p0 = planeStressSVK(e0, E, nu, wrinkling);
  const PlaneStress p1 = planeStressSVK(e1, E, nu, wrinkling);
  if (dd > 0.0 && dd > 1e-14 * scale * scale) {
    // EM9: c = psi_1 - psi_0 - dpsi(e_m) . de, S_alg = dpsi(e_m) + c de / |de|^2.
    const double c = p1.energy - p0.energy - pm.stress.dot(de);
    g.S += (c / dd) * de;
    const Vec3 dc = p1.stress - pm.stress - 0.5 * pm.tangent * de;  // dc / de_1
    g.dSdE1 +=
        de * dc.transpose() / dd + (c / dd) * (Mat3::Identity() - 2.0 * de * de.transpose() / dd);
  }
  if (chi > 0.0 && !(p0.state == WrinkleState::Slack && p1.state == WrinkleState::Slack)) {
    // EM10: dissipates chi de^T D de / 2 >= 0 per step and unit reference volume.
    const double k = E / (1.0 - nu * nu);
    Mat3 D;
    D << k, k * nu, 0, k * nu, k, 0, 0, 0, k * (1.0 - nu) / 2.0;
    g.S += 0.5 * chi * D * de;
    g.dSdE1 += 0.5 * chi * D;
  }
  return g;
}

namespace {
template <int NumNodes>
Eigen::Matrix<double, 3, 2> deformationGradient(const std::array<Vec3, NumNodes>& x,
                                                const Eigen::Matrix<double, NumNodes, 2>& dN) {
  Eigen::Matrix<double, 3, 2> F = Eigen::Matrix<double, 3, 2>::Zero();
  for (int i = 0; i < NumNodes; ++i) F += x[i] * dN.row(i);
  return F;
}
Vec3 greenStrain(const Eigen::Matrix<double, 3, 2>& F) {
  const Eigen::Matrix2d C = F.transpose() * F;
  return Vec3(0.5 * (C(0, 0) - 1.0), 0.5 * (C(1, 1) - 1.0), C(0, 1));
}
// de = B(F) dx (as in MembraneKernel.cpp).
template <int NumNodes>
Eigen::Matrix<double, 3, 3 * NumNodes> strainOperator(
    const Eigen::Matrix<double, 3, 2>& F, const Eigen::Matrix<double, NumNodes, 2>& dN) {
  Eigen::Matrix<double, 3, 3 * NumNodes> B;
  for (int i = 0; i < NumNodes; ++i) {
    B.template block<1, 3>(0, 3 * i) = dN(i, 0) * F.col(0).transpose();
    B.template block<1, 3>(1, 3 * i) = dN(i, 1) * F.col(1).transpose();
    B.template block<1, 3>(2, 3 * i) =
        dN(i, 1) * F.col(0).transpose() + dN(i, 0) * F.col(1).transpose();
  }
  return B;
}
}  // namespace

template <int NumNodes>
MembraneDiscreteGradientResult<NumNodes> membraneDiscreteGradient(
    const std::array<Vec3, NumNodes>& x0, const std::array<Vec3, NumNodes>& x1,
    const MembraneReference<NumNodes>& ref, const MembraneMaterial& mat, bool wrinkling, double chi,
    bool withTangent) {
  MembraneDiscreteGradientResult<NumNodes> r;
  r.force.setZero();
  r.dForce.setZero();
  int worst = 0;
  for (int k = 0; k < MembraneReference<NumNodes>::kGauss; ++k) {
    const auto& dN = ref.dN[k];
    const auto Fstart = deformationGradient<NumNodes>(x0, dN);
    const auto Fend = deformationGradient<NumNodes>(x1, dN);
    const Eigen::Matrix<double, 3, 2> Fm = 0.5 * (Fstart + Fend);
    const Vec3 e0 = greenStrain(Fstart), e1 = greenStrain(Fend);
    const GonzalezStress g = gonzalezStress(e0, e1, mat.E, mat.nu, wrinkling, chi);
    const PlaneStress p0 = planeStressSVK(e0, mat.E, mat.nu, wrinkling);
    const PlaneStress p1 = planeStressSVK(e1, mat.E, mat.nu, wrinkling);
    worst = std::max(worst, static_cast<int>(p1.state));
    const auto Bm = strainOperator<NumNodes>(Fm, dN);
    const double w = ref.weight[k];
    r.energy0 += w * p0.energy;
    r.energy1 += w * p1.energy;
    r.force.noalias() += w * Bm.transpose() * g.S;  // EM10
    if (withTangent) {
      // d/dx_{n+1} [B(F_mid)^T S_alg] = B(F_mid)^T dS/de_1 B(F_{n+1}) + (1/2) G(S_alg).
      const auto B1 = strainOperator<NumNodes>(Fend, dN);
      r.dForce.noalias() += w * Bm.transpose() * g.dSdE1 * B1;
      Eigen::Matrix2d S;
      S << g.S[0], g.S[2], g.S[2], g.S[1];
      const Eigen::Matrix<double, NumNodes, NumNodes> G = dN * S * dN.transpose();
      for (int i = 0; i < NumNodes; ++i)
        for (int j = 0; j < NumNodes; ++j)
          r.dForce.template block<3, 3>(3 * i, 3 * j).diagonal().array() += 0.5 * w * G(i, j);
    }
    Eigen::Matrix2d S1, Et;
    S1 << p1.stress[0], p1.stress[2], p1.stress[2], p1.stress[1];
    Et << e1[0], 0.5 * e1[2], 0.5 * e1[2], e1[1];
    const Eigen::Vector2d sv = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(S1).eigenvalues();
    const Eigen::Vector2d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(Et).eigenvalues();
    r.principalStress += Eigen::Vector2d(sv[1], sv[0]) / MembraneReference<NumNodes>::kGauss;
    r.principalStrain += Eigen::Vector2d(ev[1], ev[0]) / MembraneReference<NumNodes>::kGauss;
  }
  r.state = static_cast<WrinkleState>(worst);
  return r;
}

template MembraneDiscreteGradientResult<3> membraneDiscreteGradient<3>(const std::array<Vec3, 3>&,
                                                                       const std::array<Vec3, 3>&,
                                                                       const MembraneReference<3>&,
                                                                       const MembraneMaterial&,
                                                                       bool, double, bool);
template MembraneDiscreteGradientResult<4> membraneDiscreteGradient<4>(const std::array<Vec3, 4>&,
                                                                       const std::array<Vec3, 4>&,
                                                                       const MembraneReference<4>&,
                                                                       const MembraneMaterial&,
                                                                       bool, double, bool);

}  // namespace chute::kernels
