#pragma once
// Energy, internal force and tangent of a cable whose strain is uniform along a polyline path.
//
// Both line elements of docs/formulation.md are this kernel with a different path:
//   two-node cable (F1-F3):         path (a, b)
//   active sliding element (F6-F9): path (1, 3, 2), i.e. end 1 -> slider -> end 2
// The current length is l = sum_k |x_{k+1} - x_k|, the Green-Lagrange strain
// eps = (l^2 - L^2) / (2 L^2) (F1, F6), the strain energy W = (E A0 L / 2) eps^2, whose gradient
// is the internal force f = (E A0 / L) eps l D with D = dl/dx (F2, F8), and whose Hessian is
// K = (E A0 / L) [ (eps + l^2/L^2) D (x) D + eps l G ] with G = d^2 l / dx^2 (F3, F9).
//
// Cables are tension-only: for eps <= 0 the element carries nothing unless a compression
// stiffness ratio is given (docs/formulation.md section 1).
//
// The slider on an end node (F8-F9 singular as l_i -> 0): a part's length |d| is a cone in the
// relative position d, with no direction at its apex and lateral stiffness N / l_i -> infinity.
// Within a radius r = kApexFraction L of the apex (RG1, kernels/Regularisations.hpp) the part
// length is taken as the C1 quadratic
// (|d|^2 + r^2) / (2 r): exact for |d| >= r, at most r/2 too long inside, with a bounded,
// isotropic stiffness N / r at the apex. Force and tangent remain the exact derivatives of the
// element's energy everywhere, so Newton keeps a consistent tangent through node crossings.
#include <Eigen/Core>
#include <array>

#include "kernels/Regularisations.hpp"

namespace chute::kernels {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

struct LineMaterial {
  double E = 0.0;                          // Young's modulus
  double area = 0.0;                       // reference cross-section A0
  double density = 0.0;                    // mass per reference volume
  bool tensionOnly = true;                 // cable (true) or truss (false)
  double compressionStiffnessRatio = 0.0;  // E_c / E used when eps < 0 for a cable
};

// Length of a part with relative position d, its gradient and Hessian, regularised at the apex.
// withHessian = false leaves the Hessian unset (residual-only evaluations: it is what costs).
struct PartLength {
  double length;
  Vec3 gradient;
  Mat3 hessian;  // set only withHessian
};
PartLength partLength(const Vec3& d, double apexRadius, bool withHessian = true);
// partLength's length and gradient alone (the residual-only kernels': the same operations).
inline double partLengthAndGradient(const Vec3& d, double apexRadius, Vec3& gradient) {
  const double n = d.norm();
  if (n >= apexRadius) {
    gradient = d / n;
    return n;
  }
  gradient = d / apexRadius;
  return (n * n + apexRadius * apexRadius) / (2.0 * apexRadius);
}
// partLength's length alone.
inline double partLengthOnly(const Vec3& d, double apexRadius) {
  const double n = d.norm();
  return n >= apexRadius ? n : (n * n + apexRadius * apexRadius) / (2.0 * apexRadius);
}
// F1 / F6: the Green-Lagrange strain of a length l over the reference length L.
inline double uniformStrain(double l, double L) {
  const double L2 = L * L;
  return (l * l - L2) / (2.0 * L2);
}
// The modulus that strain sees: E; a tension-only line's compression ratio times E below zero
// strain, and nothing at exactly zero strain (taken as slack: no force and no stiffness).
inline double strainModulus(double strain, const LineMaterial& mat) {
  if (strain < 0.0 && mat.tensionOnly) return mat.E * mat.compressionStiffnessRatio;
  if (strain == 0.0 && mat.tensionOnly) return 0.0;
  return mat.E;
}

template <int NumNodes>
struct PolylineResult {
  static constexpr int kDofs = 3 * NumNodes;
  double length = 0.0;      // current length l
  double strain = 0.0;      // Green-Lagrange strain eps
  double axialForce = 0.0;  // N = E A0 eps l / L (second Piola-Kirchhoff force times stretch)
  double energy = 0.0;      // W = E A0 L eps^2 / 2
  std::array<double, NumNodes - 1> segmentLength{};  // (regularised) part lengths
  std::array<Vec3, NumNodes - 1> segmentGradient{};  // d length_k / d x_{k+1}
  Eigen::Matrix<double, kDofs, 1> dLength;           // D = dl/dx
  Eigen::Matrix<double, kDofs, 1> force;             // internal force f = dW/dx
  Eigen::Matrix<double, kDofs, kDofs> stiffness;     // K = d^2W/dx^2, set only withTangent
};

// x: node coordinates in path order. L: reference length. withTangent: compute stiffness.
template <int NumNodes>
PolylineResult<NumNodes> uniformStrainPolyline(const std::array<Vec3, NumNodes>& x, double L,
                                               const LineMaterial& mat, bool withTangent);

extern template PolylineResult<2> uniformStrainPolyline<2>(const std::array<Vec3, 2>&, double,
                                                           const LineMaterial&, bool);
extern template PolylineResult<3> uniformStrainPolyline<3>(const std::array<Vec3, 3>&, double,
                                                           const LineMaterial&, bool);

}  // namespace chute::kernels
