#pragma once
// Membrane elements (docs/formulation.md section 5): three-node triangle (CST) and four-node
// quadrilateral (2x2 Gauss), total Lagrangian, plane-stress St Venant-Kirchhoff in each element's
// local reference frame, with an optional tension-field (wrinkling) model.
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
#include <array>

namespace chute::kernels {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

struct MembraneMaterial {
  double E = 0.0;
  double nu = 0.0;
  double thickness = 0.0;
  double density = 0.0;  // mass per reference volume
};

enum class WrinkleState : int { Taut = 0, Wrinkled = 1, Slack = 2 };

// Relaxed plane-stress response at a Voigt Green strain e = (E11, E22, 2 E12).
struct PlaneStress {
  double energy = 0.0;  // psi per unit reference volume
  Vec3 stress;          // S = dpsi/de (S11, S22, S12)
  Mat3 tangent;         // d2psi/de2
  WrinkleState state = WrinkleState::Taut;
};
PlaneStress planeStressSVK(const Vec3& e, double E, double nu, bool wrinkling);

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
  Eigen::Matrix<double, kDofs, kDofs> stiffness;
  WrinkleState state = WrinkleState::Taut;  // the most relaxed state of its integration points
  Eigen::Vector2d principalStress = Eigen::Vector2d::Zero();  // of S, averaged over the points
  Eigen::Vector2d principalStrain = Eigen::Vector2d::Zero();  // of E, averaged
};

template <int NumNodes>
MembraneResult<NumNodes> membraneForce(const std::array<Vec3, NumNodes>& x,
                                       const MembraneReference<NumNodes>& ref,
                                       const MembraneMaterial& mat, bool wrinkling,
                                       bool withTangent);

// Consistent mass rho t0 int N_i N_j dA (scalar per node pair; times I3) and its row sums.
template <int NumNodes>
Eigen::Matrix<double, NumNodes, NumNodes> membraneMass(const MembraneReference<NumNodes>& ref,
                                                       double density, bool lumped);

// Follower pressure p on the current surface, f_i = p int N_i (x_,1 x x_,2) dxi (outward along
// the element's node-order normal), and its derivative df/dx (non-symmetric load stiffness).
template <int NumNodes>
struct PressureLoad {
  Eigen::Matrix<double, 3 * NumNodes, 1> force;
  Eigen::Matrix<double, 3 * NumNodes, 3 * NumNodes> dForce;
};
template <int NumNodes>
PressureLoad<NumNodes> pressureLoad(const std::array<Vec3, NumNodes>& x, double p,
                                    bool withTangent);

// Follower pressure interpolated from nodal values p_j: f_i = int N_i (sum_j N_j p_j)
// (x_,1 x x_,2) dxi, integrated exactly (triangle: edge-midpoint rule; quad: 2x2 Gauss), and its
// derivative (the pressures are held fixed). Used for pressures a flow solver gives per vertex.
template <int NumNodes>
PressureLoad<NumNodes> pressureLoadNodal(const std::array<Vec3, NumNodes>& x,
                                         const Eigen::Matrix<double, NumNodes, 1>& p,
                                         bool withTangent);

// Area vector of a face, int (x_,1 x x_,2) dxi = |A| n (exact for flat triangles and bilinear
// quads: (1/2) (x1 - x0) x (x2 - x0), (1/2) (x2 - x0) x (x3 - x1)), and its derivative dA/dx.
template <int NumNodes>
Vec3 areaVector(const std::array<Vec3, NumNodes>& x);
template <int NumNodes>
Eigen::Matrix<double, 3, 3 * NumNodes> areaVectorJacobian(const std::array<Vec3, NumNodes>& x);

// Drag on a line element of diameter d (docs/formulation.md section 6):
// f = -(1/2) rho_air Cd d l |v_n| v_n, v_n the air-relative velocity normal to the element, shared
// equally by the two nodes. Returned as the residual contribution r = -f (per node: half), with
// its derivatives with respect to the nodal positions and velocities.
struct LineDrag {
  Eigen::Matrix<double, 6, 1> residual;
  Eigen::Matrix<double, 6, 6> dPosition;
  Eigen::Matrix<double, 6, 6> dVelocity;
};
LineDrag lineDrag(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb, const Vec3& wind,
                  double coefficient /* (1/2) rho_air Cd d */, bool withTangent);

}  // namespace chute::kernels
