#include "kernels/MembraneKernel.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "kernels/MembraneShapeRules.hpp"

namespace chute::kernels {

using shape_rules::Rule3;
using shape_rules::Rule4;

// ---- reference geometry ------------------------------------------------------------------------
namespace {
template <int NumNodes, class Rule>
MembraneReference<NumNodes> buildReference(const std::array<Eigen::Vector2d, NumNodes>& X2,
                                           double thickness) {
  MembraneReference<NumNodes> ref;
  for (int k = 0; k < Rule::n; ++k) {
    const auto dNdXi = Rule::dNdXi(k);
    Eigen::Matrix2d J = Eigen::Matrix2d::Zero();  // J(alpha, beta) = dX_alpha / dxi_beta
    for (int i = 0; i < NumNodes; ++i) J += X2[i] * dNdXi.row(i);
    const double det = J.determinant();
    ref.dN[k] = dNdXi * J.inverse();
    ref.N[k] = Rule::N(k);
    ref.weight[k] = Rule::weight(k) * det * thickness;
    ref.area += Rule::weight(k) * det;
  }
  return ref;
}

// In-plane coordinates of the reference nodes in a frame with normal n.
template <int NumNodes>
std::array<Eigen::Vector2d, NumNodes> localCoordinates(const std::array<Vec3, NumNodes>& X,
                                                       const Vec3& n, double prestrain) {
  Vec3 e1 = X[1] - X[0];
  e1 -= e1.dot(n) * n;
  e1.normalize();
  const Vec3 e2 = n.cross(e1);
  std::array<Eigen::Vector2d, NumNodes> out;
  for (int i = 0; i < NumNodes; ++i) {
    const Vec3 r = X[i] - X[0];
    out[i] = Eigen::Vector2d(r.dot(e1), r.dot(e2)) / (1.0 + prestrain);
  }
  return out;
}
}  // namespace

MembraneReference<3> triangleReference(const std::array<Vec3, 3>& X, double thickness,
                                       double prestrain) {
  const Vec3 n = (X[1] - X[0]).cross(X[2] - X[0]).normalized();
  return buildReference<3, Rule3>(localCoordinates<3>(X, n, prestrain), thickness);
}

MembraneReference<4> quadReference(const std::array<Vec3, 4>& X, double thickness,
                                   double prestrain) {
  const Vec3 n = (X[2] - X[0]).cross(X[3] - X[1]).normalized();
  return buildReference<4, Rule4>(localCoordinates<4>(X, n, prestrain), thickness);
}

// ---- internal force and tangent (total Lagrangian) -----------------------------------------
namespace {
// The deformation gradient F = dx / dX at an integration point with shape-function gradients dN,
// and the Voigt Green strain e = (E11, E22, 2 E12) of C = F^T F. Written out entry by entry in
// the order of the matrix expressions F = sum_i x_i dN_i^T (from zero, node by node) and
// C_ab = (F_0a F_0b + F_1a F_1b) + F_2a F_2b, which they evaluate to the same bits: Eigen forms
// those outer products in memory and reads them back across the stores' boundaries, a stall that
// took about half of the membranes' time (perf, the explicit C-9).
template <int NumNodes>
Vec3 greenStrain(const std::array<Vec3, NumNodes>& x, const Eigen::Matrix<double, NumNodes, 2>& dN,
                 Eigen::Matrix<double, 3, 2>& F) {
  double f[3][2];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 2; ++c) {
      double sum = 0.0;
      for (int i = 0; i < NumNodes; ++i) sum += x[i][r] * dN(i, c);
      f[r][c] = sum;
    }
  F << f[0][0], f[0][1], f[1][0], f[1][1], f[2][0], f[2][1];
  const double c00 = (f[0][0] * f[0][0] + f[1][0] * f[1][0]) + f[2][0] * f[2][0];
  const double c11 = (f[0][1] * f[0][1] + f[1][1] * f[1][1]) + f[2][1] * f[2][1];
  const double c01 = (f[0][0] * f[0][1] + f[1][0] * f[1][1]) + f[2][0] * f[2][1];
  return Vec3(0.5 * (c00 - 1.0), 0.5 * (c11 - 1.0), c01);  // (E11, E22, 2E12)
}
}  // namespace

template <int NumNodes>
double membraneEnergy(const std::array<Vec3, NumNodes>& x, const MembraneReference<NumNodes>& ref,
                      const MembraneMaterial& mat, bool wrinkling) {
  double energy = 0.0;
  for (int k = 0; k < MembraneReference<NumNodes>::kGauss; ++k) {
    Eigen::Matrix<double, 3, 2> F;
    const Vec3 e = greenStrain<NumNodes>(x, ref.dN[k], F);
    energy += ref.weight[k] * planeStressSVK(e, mat.E, mat.nu, wrinkling, false).energy;
  }
  return energy;
}

template <int NumNodes>
MembraneResult<NumNodes> membraneForce(const std::array<Vec3, NumNodes>& x,
                                       const MembraneReference<NumNodes>& ref,
                                       const MembraneMaterial& mat, bool wrinkling,
                                       bool withTangent, bool withPrincipals) {
  constexpr int kDofs = 3 * NumNodes;
  MembraneResult<NumNodes> r;
  r.force.setZero();
  if (withTangent) r.stiffness.setZero();  // residual-only evaluations never read it
  int worst = 0;
  for (int k = 0; k < MembraneReference<NumNodes>::kGauss; ++k) {
    const auto& dN = ref.dN[k];
    Eigen::Matrix<double, 3, 2> F;  // dx / dX
    const Vec3 e = greenStrain<NumNodes>(x, dN, F);
    const PlaneStress ps = planeStressSVK(e, mat.E, mat.nu, wrinkling, withTangent);
    worst = std::max(worst, static_cast<int>(ps.state));
    const double w = ref.weight[k];
    r.energy += w * ps.energy;
    if (!withTangent) {
      // Residual only: B^T S = F S2 dN^T node by node, with S2 the 2x2 stress matrix (the same
      // sum as below without forming B).
      Eigen::Matrix2d S2;
      S2 << ps.stress[0], ps.stress[2], ps.stress[2], ps.stress[1];
      const Eigen::Matrix<double, 3, NumNodes> f = w * (F * S2) * dN.transpose();
      for (int i = 0; i < NumNodes; ++i) r.force.template segment<3>(3 * i) += f.col(i);
    }
    if (withTangent) {
      // B: de = B dx; node i: (dN_i1 F1, dN_i2 F2, dN_i2 F1 + dN_i1 F2).
      Eigen::Matrix<double, 3, kDofs> B;
      for (int i = 0; i < NumNodes; ++i) {
        B.template block<1, 3>(0, 3 * i) = dN(i, 0) * F.col(0).transpose();
        B.template block<1, 3>(1, 3 * i) = dN(i, 1) * F.col(1).transpose();
        B.template block<1, 3>(2, 3 * i) =
            dN(i, 1) * F.col(0).transpose() + dN(i, 0) * F.col(1).transpose();
      }
      r.force.noalias() += w * B.transpose() * ps.stress;
      r.stiffness.noalias() += w * B.transpose() * ps.tangent * B;
      Eigen::Matrix2d S;
      S << ps.stress[0], ps.stress[2], ps.stress[2], ps.stress[1];
      const Eigen::Matrix<double, NumNodes, NumNodes> G = dN * S * dN.transpose();
      for (int i = 0; i < NumNodes; ++i)
        for (int j = 0; j < NumNodes; ++j)
          r.stiffness.template block<3, 3>(3 * i, 3 * j).diagonal().array() += w * G(i, j);
    }
    if (!withPrincipals) continue;
    Eigen::Matrix2d S;
    S << ps.stress[0], ps.stress[2], ps.stress[2], ps.stress[1];
    Eigen::Matrix2d Et;
    Et << e[0], 0.5 * e[2], 0.5 * e[2], e[1];
    const Eigen::Vector2d sv = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(S).eigenvalues();
    const Eigen::Vector2d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(Et).eigenvalues();
    r.principalStress += Eigen::Vector2d(sv[1], sv[0]) / MembraneReference<NumNodes>::kGauss;
    r.principalStrain += Eigen::Vector2d(ev[1], ev[0]) / MembraneReference<NumNodes>::kGauss;
    r.principalResultant += principalResultant(F.transpose() * F, S, mat.thickness) /
                            MembraneReference<NumNodes>::kGauss;
  }
  r.state = static_cast<WrinkleState>(worst);
  return r;
}

Eigen::Vector2d principalResultant(const Eigen::Matrix2d& C, const Eigen::Matrix2d& S,
                                   double thickness) {
  const double detC = C.determinant();
  if (!(detC > 0.0)) return Eigen::Vector2d::Zero();  // a collapsed element carries nothing
  // Cholesky of the 2x2 C by hand: C = L L^T, L lower triangular.
  const double l00 = std::sqrt(C(0, 0));
  const double l10 = C(1, 0) / l00;
  const double l11 = std::sqrt(std::max(C(1, 1) - l10 * l10, 0.0));
  Eigen::Matrix2d L;
  L << l00, 0.0, l10, l11;
  const Eigen::Matrix2d M = L.transpose() * S * L;
  const Eigen::Vector2d v = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(M).eigenvalues();
  return thickness / std::sqrt(detC) * Eigen::Vector2d(v[1], v[0]);
}

template <int NumNodes>
Eigen::Matrix<double, NumNodes, NumNodes> membraneMass(const MembraneReference<NumNodes>& ref,
                                                       double density, bool lumped) {
  Eigen::Matrix<double, NumNodes, NumNodes> M = Eigen::Matrix<double, NumNodes, NumNodes>::Zero();
  if constexpr (NumNodes == 3) {
    // Exact for linear shape functions: rho t A / 12 (1 + delta_ij).
    const double m = density * ref.weight[0];
    M.setConstant(m / 12.0);
    M.diagonal().array() = m / 6.0;
  } else {
    for (int k = 0; k < MembraneReference<NumNodes>::kGauss; ++k)
      M += density * ref.weight[k] * ref.N[k] * ref.N[k].transpose();
  }
  if (lumped) {
    const Eigen::Matrix<double, NumNodes, 1> rows = M.rowwise().sum();
    M.setZero();
    M.diagonal() = rows;
  }
  return M;
}

template MembraneResult<3> membraneForce<3>(const std::array<Vec3, 3>&, const MembraneReference<3>&,
                                            const MembraneMaterial&, bool, bool, bool);
template MembraneResult<4> membraneForce<4>(const std::array<Vec3, 4>&, const MembraneReference<4>&,
                                            const MembraneMaterial&, bool, bool, bool);
template double membraneEnergy<3>(const std::array<Vec3, 3>&, const MembraneReference<3>&,
                                  const MembraneMaterial&, bool);
template double membraneEnergy<4>(const std::array<Vec3, 4>&, const MembraneReference<4>&,
                                  const MembraneMaterial&, bool);
template Eigen::Matrix<double, 3, 3> membraneMass<3>(const MembraneReference<3>&, double, bool);
template Eigen::Matrix<double, 4, 4> membraneMass<4>(const MembraneReference<4>&, double, bool);

}  // namespace chute::kernels
