#pragma once
// Two-node cable / truss element (docs/formulation.md section 1): internal force and tangent, mass
// and gravity, and the location of a tension-only cable's slack / taut switch (RG4). Pure
// functions of nodal coordinates and parameters; dof order is node by node, (x, y, z) per node.
#include "kernels/LineElementTypes.hpp"
#include "kernels/Regularisations.hpp"
#include "kernels/UniformStrainPolyline.hpp"

namespace chute::kernels {

// F1-F3: nodes (a, b).
PolylineResult<2> cableForce(const Vec3& xa, const Vec3& xb, double L, const LineMaterial& mat,
                             bool withTangent);
// Residual-only cableForce: its force, the same operations as uniformStrainPolyline<2>'s
// residual (D = (0 - g, 0 + g) from a zero vector, l = 0 + l_part is exact), so bit for bit,
// without its result's 6 x 6 stiffness, the call to partLength and the copies of the result
// through cableForce (the explicit path evaluates it every step on every line element). Inline:
// called across files, the nodes' positions went through memory to the call.
inline Eigen::Matrix<double, 6, 1> cableForceOnly(const Vec3& xa, const Vec3& xb, double L,
                                                  const LineMaterial& mat) {
  Vec3 g;
  const double length = partLengthAndGradient(xb - xa, kApexFraction * L, g);
  const double strain = uniformStrain(length, L);  // F1
  const double EAoverL = strainModulus(strain, mat) * mat.area / L;
  const double N = EAoverL * strain * length;  // F2
  Eigen::Matrix<double, 6, 1> f;
  for (int k = 0; k < 3; ++k) {
    f[k] = N * (0.0 - g[k]);
    f[3 + k] = N * (0.0 + g[k]);
  }
  return f;
}
// cableForce's strain energy alone (F1-F2), with the same operations as uniformStrainPolyline<2>
// (l = 0 + l_part is exact), so bit for bit: the energy balance asks for it for every line
// element, where the whole kernel's force, its result's copies and the call to partLength made
// the lines' energy cost more than the membranes' (the C-9 slider case).
inline double cableStrainEnergyOnly(const Vec3& xa, const Vec3& xb, double L,
                                    const LineMaterial& mat) {
  const double strain = uniformStrain(partLengthOnly(xb - xa, kApexFraction * L), L);  // F1
  return 0.5 * strainModulus(strain, mat) * mat.area * L * strain * strain;
}
// F4: constant mass matrix.
Mat6 cableMass(double L, const LineMaterial& mat, MassKind kind);
// F4's inertia M a without forming M: lumped, (m / 2) a_i; consistent, (m / 3) a_i + (m / 6) a_j
// with j the other node's same component. Bit for bit cableMass(L, mat, kind) * a: each row of M
// has at most two nonzeros, whose sum does not depend on the order of the additions. The explicit
// path's lumped mass (EX2) asks for it for every line element at every step: inline.
inline Vec6 cableMassTimes(double L, const LineMaterial& mat, MassKind kind, const Vec6& a) {
  const double m = mat.density * mat.area * L;  // the entries of cableMass, to the bit
  Vec6 r;
  if (kind == MassKind::Lumped) {
    const double half = 0.5 * m;
    for (int i = 0; i < 6; ++i) r[i] = half * a[i];
  } else {
    const double diag = m / 3.0, off = m / 6.0;
    for (int i = 0; i < 6; ++i) r[i] = diag * a[i] + off * a[(i + 3) % 6];
  }
  return r;
}
// F5: constant gravity load (rho A0 L / 2) g on each node.
Vec6 cableGravity(double L, const LineMaterial& mat, const Vec3& g);

// Slack / taut switch of a tension-only cable (the kink of its energy at zero strain, where the
// stiffness jumps from E A / L to nothing). Given the relative position d = x_b - x_a at the
// step's start and its change delta over the step, returns the fraction of delta at which
// |d + f delta| = L, or 1 if the motion does not cross it. A start or an end within
// kSlackTautBand L of the switch is on it, not across it (RG4, kernels/Regularisations.hpp).
double slackTautCrossing(const Vec3& d, const Vec3& delta, double L);

}  // namespace chute::kernels
