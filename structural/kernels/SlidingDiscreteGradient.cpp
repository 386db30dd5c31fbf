#include "kernels/SlidingDiscreteGradient.hpp"

#include "kernels/CableDiscreteGradient.hpp"

namespace chute::kernels {

SlidingDiscreteGradientResult slidingDiscreteGradient(const std::array<Vec3, 3>& x0,
                                                      const std::array<Vec3, 3>& x1, double L,
                                                      const LineMaterial& mat, double chi,
                                                      bool withTangent) {
  SlidingDiscreteGradientResult r;
  const double L2 = L * L;
  Vec3 g[2], e1[2];
  double s[2];
  double l0 = 0.0, l1 = 0.0;
  for (int i = 0; i < 2; ++i) {
    const Vec3 a = x0[2] - x0[i], b = x1[2] - x1[i];
    const double na = a.norm(), nb = b.norm();
    l0 += na;
    l1 += nb;
    s[i] = na + nb;
    g[i] = s[i] > 0.0 ? Vec3((a + b) / s[i]) : Vec3::Zero();
    e1[i] = nb > 0.0 ? Vec3(b / nb) : Vec3::Zero();
  }
  r.strain0 = (l0 * l0 - L2) / (2.0 * L2);  // F6
  r.strain1 = (l1 * l1 - L2) / (2.0 * L2);
  const CableEnergyBranches w = cableEnergyBranches(L, mat);
  r.energy0 = w.energy(r.strain0);
  r.energy1 = w.energy(r.strain1);
  const AlgorithmicStress st = cableAlgorithmicStress(r.strain0, r.strain1, w, chi);
  const double q = (l0 + l1) / (2.0 * L2);  // dE / dl along the step
  const double N = st.S * q;
  Vec9 D;
  D << -g[0], -g[1], g[0] + g[1];
  r.force = N * D;
  r.dForce.setZero();
  if (!withTangent) return r;
  // dN/dx_{n+1} = (dS/dE_{n+1} q l_{n+1} / L^2 + S / (2 L^2)) D(x_{n+1}), D = F7's dl/dx.
  Vec9 D1;
  D1 << -e1[0], -e1[1], e1[0] + e1[1];
  const double dNdl = st.dSdE1 * q * l1 / L2 + st.S / (2.0 * L2);
  r.dForce.noalias() = dNdl * D * D1.transpose();
  // N dD_alg/dx_{n+1}: h_i = dg_i / dd_i = I / s_i - (d_i,n + d_i,n+1) e_i^T / s_i^2, placed as
  // F9's G (part i between end node i and the slider).
  for (int i = 0; i < 2; ++i) {
    if (s[i] <= 0.0) continue;
    const Mat3 h = N * (Mat3::Identity() / s[i] - g[i] * e1[i].transpose() / s[i]);
    r.dForce.block<3, 3>(3 * i, 3 * i) += h;
    r.dForce.block<3, 3>(6, 6) += h;
    r.dForce.block<3, 3>(3 * i, 6) -= h;
    r.dForce.block<3, 3>(6, 3 * i) -= h;
  }
  return r;
}

}  // namespace chute::kernels
