#pragma once
// Plane-stress St Venant-Kirchhoff law of the membranes (docs/formulation.md section 5) with the
// optional tension-field (wrinkling) model.
//
// Wrinkling is the relaxed strain energy of the plane-stress St Venant-Kirchhoff material
// (Pipkin's tension field), in the principal Green strains E1 >= E2:
//   taut      (E2 + nu E1 > 0, both principal stresses positive):
//             psi = Ebar/(2(1 - nu^2)) (E1^2 + 2 nu E1 E2 + E2^2)
//   wrinkled  (E1 > 0 >= E2 + nu E1, uniaxial tension):  psi = Ebar E1^2 / 2
//   slack     (E1 <= 0):                                 psi = 0
// The wrinkled energy is the taut one minimised over E2 (E2 = -nu E1), so the energy is C1 across
// the state changes; stress and tangent are its exact first and second derivatives.
#include <Eigen/Core>

namespace chute::kernels {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

enum class WrinkleState : int { Taut = 0, Wrinkled = 1, Slack = 2 };

// Relaxed plane-stress response at a Voigt Green strain e = (E11, E22, 2 E12).
// withTangent = false leaves the tangent unset (residual-only evaluations, the explicit path):
// energy, stress and state are bit for bit those with the tangent.
struct PlaneStress {
  double energy = 0.0;  // psi per unit reference volume
  Vec3 stress;          // S = dpsi/de (S11, S22, S12)
  Mat3 tangent;         // d2psi/de2, set only withTangent
  WrinkleState state = WrinkleState::Taut;
};
PlaneStress planeStressSVK(const Vec3& e, double E, double nu, bool wrinkling,
                           bool withTangent = true);

}  // namespace chute::kernels
