#pragma once
// Energy-momentum (discrete-gradient) internal force of a membrane element between the step's
// start x_n and end x_{n+1} (docs/formulation.md section 10, EM9-EM10). At each integration
// point the Green strain e (Voigt: E11, E22, 2 E12) is quadratic in x, so
// e_{n+1} - e_n = B(F_mid) (x_{n+1} - x_n) exactly (F_mid = (F_n + F_{n+1}) / 2), and
//   f_alg = sum_k w_k B(F_mid)^T S_alg,k
// with Gonzalez's (2000) discrete gradient of the strain energy psi(e),
//   S_alg = dpsi(e_mid) + [psi(e_{n+1}) - psi(e_n) - dpsi(e_mid) . de] de / |de|^2,
// exact for any psi: the correction vanishes for the quadratic St Venant-Kirchhoff energy (taut)
// and carries the non-quadratic tension-field energy (wrinkled, slack). Then
// W(x_{n+1}) - W(x_n) = f_alg . (x_{n+1} - x_n) and f_alg conserves momenta (objective B).
#include "kernels/MembraneKernel.hpp"

namespace chute::kernels {

template <int NumNodes>
struct MembraneDiscreteGradientResult {
  static constexpr int kDofs = 3 * NumNodes;
  double energy0 = 0.0, energy1 = 0.0;  // W(x_n), W(x_{n+1})
  Eigen::Matrix<double, kDofs, 1> force;
  Eigen::Matrix<double, kDofs, kDofs> dForce;                 // d f_alg / d x_{n+1} (not symmetric)
  WrinkleState state = WrinkleState::Taut;                    // at x_{n+1}, as MembraneResult
  Eigen::Vector2d principalStress = Eigen::Vector2d::Zero();  // of S(e_{n+1}), averaged
  Eigen::Vector2d principalStrain = Eigen::Vector2d::Zero();  // of e_{n+1}, averaged
};

// chi >= 0: the energy-decaying part (EM8 for membranes, EM10): S_alg += chi D de / 2, D the
// taut plane-stress stiffness, left out where the point is slack at both ends.
template <int NumNodes>
MembraneDiscreteGradientResult<NumNodes> membraneDiscreteGradient(
    const std::array<Vec3, NumNodes>& x0, const std::array<Vec3, NumNodes>& x1,
    const MembraneReference<NumNodes>& ref, const MembraneMaterial& mat, bool wrinkling, double chi,
    bool withTangent);

// Gonzalez's discrete gradient of psi between Voigt strains e0 and e1 (EM9) and its derivative
// with respect to e1. Where |e1 - e0| is below 1e-7 of the strains the correction term (of order
// |de|^2 relative) is left out: its quotient would be round-off.
struct GonzalezStress {
  Vec3 S;
  Mat3 dSdE1;
};
GonzalezStress gonzalezStress(const Vec3& e0, const Vec3& e1, double E, double nu, bool wrinkling,
                              double chi);

}  // namespace chute::kernels
