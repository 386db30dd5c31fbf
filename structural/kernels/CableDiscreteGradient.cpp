#include "kernels/CableDiscreteGradient.hpp"

#include <algorithm>

namespace chute::kernels {

CableEnergyBranches cableEnergyBranches(double L, const LineMaterial& mat) {
  CableEnergyBranches w;
  w.tension = mat.E * mat.area * L;
  w.compression = mat.tensionOnly ? w.tension * mat.compressionStiffnessRatio : w.tension;
  return w;
}

AlgorithmicStress cableAlgorithmicStress(double E0, double E1, const CableEnergyBranches& w,
                                         double chi) {
  AlgorithmicStress s;
  if ((E0 >= 0.0 && E1 >= 0.0) || (E0 <= 0.0 && E1 <= 0.0)) {
    // One quadratic branch (a zero end belongs to either: W(0) = 0 on both). The difference
    // quotient of c E^2 / 2 is c (E_n + E_{n+1}) / 2 exactly: no cancellation as E_{n+1} -> E_n.
    const double c = (E0 > 0.0 || E1 > 0.0) ? w.tension : w.compression;
    s.S = 0.5 * c * (E0 + E1);
    s.dSdE1 = 0.5 * c;
  } else {
    // Across the kink: E_n and E_{n+1} have strictly opposite signs, |E_{n+1} - E_n| is at least
    // either of them and the quotient is well conditioned (EM4).
    const double dE = E1 - E0;
    s.S = (w.energy(E1) - w.energy(E0)) / dE;
    s.dSdE1 = (w.at(E1) * E1 - s.S) / dE;
  }
  if (chi > 0.0) {  // EM8: dissipates chi c (E_{n+1} - E_n)^2 / 2 per step, never adds energy
    const double c = std::max(w.at(E0), w.at(E1));
    s.S += 0.5 * chi * c * (E1 - E0);
    s.dSdE1 += 0.5 * chi * c;
  }
  return s;
}

CableDiscreteGradientResult cableDiscreteGradient(const Vec3& xa0, const Vec3& xb0, const Vec3& xa1,
                                                  const Vec3& xb1, double L,
                                                  const LineMaterial& mat, double chi,
                                                  bool withTangent) {
  CableDiscreteGradientResult r;
  const double L2 = L * L;
  const Vec3 d0 = xb0 - xa0, d1 = xb1 - xa1, dm = 0.5 * (d0 + d1);
  r.strain0 = (d0.squaredNorm() - L2) / (2.0 * L2);  // EM3 (F1 without the apex rounding)
  r.strain1 = (d1.squaredNorm() - L2) / (2.0 * L2);
  const CableEnergyBranches w = cableEnergyBranches(L, mat);
  r.energy0 = w.energy(r.strain0);
  r.energy1 = w.energy(r.strain1);
  const AlgorithmicStress s = cableAlgorithmicStress(r.strain0, r.strain1, w, chi);
  r.stress = s.S;
  // B(x_mid) = dE/dx at the midpoint = [-d_m; d_m] / L^2 (EM3).
  Vec6 bm;
  bm << -dm / L2, dm / L2;
  r.force = s.S * bm;
  r.dForce.setZero();
  if (!withTangent) return r;
  Vec6 b1;
  b1 << -d1 / L2, d1 / L2;
  // d f / d x_{n+1} = dS/dE_{n+1} B(x_mid) B(x_{n+1})^T + S dB(x_mid)/dx_{n+1}, the latter
  // (1 / (2 L^2)) [I -I; -I I].
  r.dForce.noalias() = s.dSdE1 * bm * b1.transpose();
  const Mat3 g = (0.5 * s.S / L2) * Mat3::Identity();
  r.dForce.block<3, 3>(0, 0) += g;
  r.dForce.block<3, 3>(3, 3) += g;
  r.dForce.block<3, 3>(0, 3) -= g;
  r.dForce.block<3, 3>(3, 0) -= g;
  return r;
}

}  // namespace chute::kernels
