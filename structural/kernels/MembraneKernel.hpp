#pragma once
// Membrane elements (docs/formulation.md section 5): three-node triangle (CST) and four-node
// quadrilateral (2x2 Gauss), total Lagrangian, plane-stress St Venant-Kirchhoff in each element's
// local reference frame, with an optional tension-field (wrinkling) model
// (kernels/PlaneStressWrinkling.hpp).
#include <Eigen/Core>
#include <array>

#include "kernels/PlaneStressWrinkling.hpp"

namespace chute::kernels {

struct MembraneMaterial {
  double E = 0.0;
  double nu = 0.0;
  double thickness = 0.0;
  double density = 0.0;  // mass per reference volume
  // Strength as a stress resultant (force per unit width, the unit fabric data sheets give);
  // 0: none given. Output only: the `utilisation` cell field (docs/output.md).
  double strength = 0.0;
};

// Reference data of an element: shape-function gradients in the element's local reference
// frame and integration weights (reference area times thickness) at each integration point.
template <int NumNodes>
struct MembraneReference {
  static constexpr int kGauss = NumNodes == 3 ? 1 : 4;
  std::array<Eigen::Matrix<double, NumNodes, 2>, kGauss> dN;  // dN_i / dX_alpha
  std::array<Eigen::Matrix<double, NumNodes, 1>, kGauss> N;   // N_i
  std::array<double, kGauss> weight;                          // dA0 t0
  double area = 0.0;                                          // reference area
};
// prestrain: the reference is the given geometry shrunk by 1 / (1 + prestrain) in its plane.
MembraneReference<3> triangleReference(const std::array<Vec3, 3>& X, double thickness,
                                       double prestrain = 0.0);
MembraneReference<4> quadReference(const std::array<Vec3, 4>& X, double thickness,
                                   double prestrain = 0.0);

template <int NumNodes>
struct MembraneResult {
  static constexpr int kDofs = 3 * NumNodes;
  double energy = 0.0;
  Eigen::Matrix<double, kDofs, 1> force;
  Eigen::Matrix<double, kDofs, kDofs> stiffness;  // set only withTangent
  WrinkleState state = WrinkleState::Taut;  // the most relaxed state of its integration points
  Eigen::Vector2d principalStress = Eigen::Vector2d::Zero();  // of S, averaged over the points
  Eigen::Vector2d principalStrain = Eigen::Vector2d::Zero();  // of E, averaged
  // Principal values of the true (Cauchy) stress resultant, force per unit current width:
  // n = t0 F S F^T / J_A with J_A = sqrt(det C) the area ratio (sigma t = t0 F S F^T / J_A, as
  // the thickness shrinks by lambda_3 = J / J_A). Largest first, averaged over the points.
  Eigen::Vector2d principalResultant = Eigen::Vector2d::Zero();
};

// The principal values of the true stress resultant t0 F S F^T / J_A at a point with
// C = F^T F (2x2) and 2x2 second Piola-Kirchhoff stress S, largest first. The non-zero
// eigenvalues of F S F^T are those of S C, i.e. of the symmetric L^T S L (C = L L^T).
Eigen::Vector2d principalResultant(const Eigen::Matrix2d& C, const Eigen::Matrix2d& S,
                                   double thickness);

// withPrincipals: also the principal values (two 2 x 2 eigen-solves per point, for output only;
// left zero otherwise).
template <int NumNodes>
MembraneResult<NumNodes> membraneForce(const std::array<Vec3, NumNodes>& x,
                                       const MembraneReference<NumNodes>& ref,
                                       const MembraneMaterial& mat, bool wrinkling,
                                       bool withTangent, bool withPrincipals = true);

// The strain energy of membraneForce alone, bit for bit (the same strains and law, without the
// force): the energy balance and the probes ask for it over the whole canopy.
template <int NumNodes>
double membraneEnergy(const std::array<Vec3, NumNodes>& x, const MembraneReference<NumNodes>& ref,
                      const MembraneMaterial& mat, bool wrinkling);

// Consistent mass rho t0 int N_i N_j dA (scalar per node pair; times I3) and its row sums.
template <int NumNodes>
Eigen::Matrix<double, NumNodes, NumNodes> membraneMass(const MembraneReference<NumNodes>& ref,
                                                       double density, bool lumped);

}  // namespace chute::kernels
