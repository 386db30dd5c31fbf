#include "kernels/PolylineDiscreteGradient.hpp"

#include <algorithm>

#include "kernels/CableDiscreteGradient.hpp"

namespace chute::kernels {

PolylineDiscreteGradientResult polylineDiscreteGradient(const std::vector<Vec3>& x0,
                                                        const std::vector<Vec3>& x1, double L,
                                                        const LineMaterial& mat, double chi,
                                                        bool withTangent) {
  const int n = static_cast<int>(x0.size());
  PolylineDiscreteGradientResult r;
  const double L2 = L * L;
  std::vector<Vec3> g(n - 1), e1(n - 1);
  std::vector<double> s(n - 1);
  double l0 = 0.0, l1 = 0.0;
  for (int k = 0; k + 1 < n; ++k) {
    const Vec3 a = x0[k + 1] - x0[k], b = x1[k + 1] - x1[k];
    const double na = a.norm(), nb = b.norm();
    l0 += na;
    l1 += nb;
    s[k] = na + nb;
    g[k] = s[k] > 0.0 ? Vec3((a + b) / s[k]) : Vec3::Zero();
    e1[k] = nb > 0.0 ? Vec3(b / nb) : Vec3::Zero();
  }
  r.strain0 = (l0 * l0 - L2) / (2.0 * L2);  // F6
  r.strain1 = (l1 * l1 - L2) / (2.0 * L2);
  const CableEnergyBranches w = cableEnergyBranches(L, mat);
  r.energy0 = w.energy(r.strain0);
  r.energy1 = w.energy(r.strain1);
  const AlgorithmicStress st = cableAlgorithmicStress(r.strain0, r.strain1, w, chi);
  const double q = (l0 + l1) / (2.0 * L2);  // dE / dl along the step
  const double N = st.S * q;
  Eigen::VectorXd D = Eigen::VectorXd::Zero(3 * n), D1 = Eigen::VectorXd::Zero(3 * n);
  for (int k = 0; k + 1 < n; ++k) {
    D.segment<3>(3 * k) -= g[k];
    D.segment<3>(3 * k + 3) += g[k];
    D1.segment<3>(3 * k) -= e1[k];
    D1.segment<3>(3 * k + 3) += e1[k];
  }
  r.force = N * D;
  if (!withTangent) return r;
  // As EM11: dN/dx_{n+1} along D1 (F7's dl/dx at the end), N dD_alg/dx_{n+1} part by part with
  // h_k = I / s_k - g_k e1_k^T / s_k.
  const double dNdl = st.dSdE1 * q * l1 / L2 + st.S / (2.0 * L2);
  r.dForce = dNdl * D * D1.transpose();
  for (int k = 0; k + 1 < n; ++k) {
    if (s[k] <= 0.0) continue;
    const Mat3 h = N * (Mat3::Identity() / s[k] - g[k] * e1[k].transpose() / s[k]);
    r.dForce.block<3, 3>(3 * k, 3 * k) += h;
    r.dForce.block<3, 3>(3 * k + 3, 3 * k + 3) += h;
    r.dForce.block<3, 3>(3 * k, 3 * k + 3) -= h;
    r.dForce.block<3, 3>(3 * k + 3, 3 * k) -= h;
  }
  return r;
}

Vec3 polylinePoint(const std::vector<Vec3>& P, double phi, Eigen::MatrixXd* dX) {
  const int n = static_cast<int>(P.size());
  std::vector<double> l(n - 1);
  std::vector<Vec3> u(n - 1);
  double total = 0.0;
  for (int k = 0; k + 1 < n; ++k) {
    const Vec3 d = P[k + 1] - P[k];
    l[k] = d.norm();
    u[k] = l[k] > 0.0 ? Vec3(d / l[k]) : Vec3::Zero();
    total += l[k];
  }
  const double sigma = std::clamp(phi, 0.0, 1.0) * total;
  // The part holding arc length sigma (the last one for sigma = total).
  int k = 0;
  double A = 0.0;
  while (k + 2 < n && (A + l[k] < sigma || l[k] == 0.0)) A += l[k++];
  const double t = l[k] > 0.0 ? std::clamp((sigma - A) / l[k], 0.0, 1.0) : 0.0;
  const Vec3 X = P[k] + t * (P[k + 1] - P[k]);
  if (!dX) return X;
  // X = P_k + t (P_k+1 - P_k), t = (phi sum_i l_i - sum_{i<k} l_i) / l_k; dl_i = u_i.(dP_i+1 -
  // dP_i).
  dX->setZero(3, 3 * n);
  Eigen::RowVectorXd dt = Eigen::RowVectorXd::Zero(3 * n);
  if (l[k] > 0.0) {
    for (int i = 0; i + 1 < n; ++i) {
      double c = phi;  // d sigma / d l_i
      if (i < k) c -= 1.0;
      if (i == k) c -= t;  // - t dl_k
      dt.segment<3>(3 * i + 3) += (c / l[k]) * u[i].transpose();
      dt.segment<3>(3 * i) -= (c / l[k]) * u[i].transpose();
    }
  }
  dX->block<3, 3>(0, 3 * k) += (1.0 - t) * Mat3::Identity();
  dX->block<3, 3>(0, 3 * k + 3) += t * Mat3::Identity();
  *dX += (P[k + 1] - P[k]) * dt;
  return X;
}

}  // namespace chute::kernels
