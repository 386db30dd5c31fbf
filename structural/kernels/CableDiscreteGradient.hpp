#pragma once
// Energy-momentum (discrete-gradient) internal force of a two-node cable / truss element between
// two configurations x_n and x_{n+1} (docs/formulation.md section 10, EM3-EM5). Pure functions of
// the nodal coordinates at the step's start and end; dof order node by node, (x, y, z) per node.
//
// The Green strain E = (|d|^2 - L^2) / (2 L^2), d = x_b - x_a, is quadratic in x, so
// E_{n+1} - E_n = B(x_mid) (x_{n+1} - x_n) exactly, B = dE/dx. With the algorithmic stress
// S_alg = (W(E_{n+1}) - W(E_n)) / (E_{n+1} - E_n) (Gonzalez 2000) the force f = S_alg B(x_mid)
// satisfies W(x_{n+1}) - W(x_n) = f . (x_{n+1} - x_n) for any W(E), the tension-only kink
// included (EM4), and is parallel to the midpoint chord (momentum, EM6).
#include "kernels/LineElementTypes.hpp"
#include "kernels/UniformStrainPolyline.hpp"

namespace chute::kernels {

// The strain energy W(E) = c(E) E^2 / 2 of one element, c = E A0 L (c E_c / E in compression for a
// cable with a compression ratio, 0 for a slack cable): its two branches.
struct CableEnergyBranches {
  double tension = 0.0;      // c for E > 0
  double compression = 0.0;  // c for E < 0
  double at(double strain) const { return strain > 0.0 ? tension : compression; }
  double energy(double strain) const { return 0.5 * at(strain) * strain * strain; }
};
CableEnergyBranches cableEnergyBranches(double L, const LineMaterial& mat);

// EM4 / EM8: S_alg(E_n, E_{n+1}) and its derivative with respect to E_{n+1}, plus the
// energy-decaying part chi c (E_{n+1} - E_n) / 2 (c the stiffer branch touched by the step).
struct AlgorithmicStress {
  double S = 0.0;
  double dSdE1 = 0.0;
};
AlgorithmicStress cableAlgorithmicStress(double E0, double E1, const CableEnergyBranches& w,
                                         double chi);

struct CableDiscreteGradientResult {
  double strain0 = 0.0, strain1 = 0.0;  // E_n, E_{n+1}
  double energy0 = 0.0, energy1 = 0.0;  // W(E_n), W(E_{n+1})
  double stress = 0.0;                  // S_alg (per E: force = S_alg B(x_mid))
  Vec6 force;                           // EM5: f_alg = S_alg B(x_mid)
  Mat6 dForce;                          // d f_alg / d x_{n+1} (not symmetric)
};

// EM5: nodes (a, b) at the step's start (xa0, xb0) and end (xa1, xb1); chi >= 0 the
// energy-decaying parameter (0: energy conserving).
CableDiscreteGradientResult cableDiscreteGradient(const Vec3& xa0, const Vec3& xb0, const Vec3& xa1,
                                                  const Vec3& xb1, double L,
                                                  const LineMaterial& mat, double chi,
                                                  bool withTangent);

}  // namespace chute::kernels
