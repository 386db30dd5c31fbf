#pragma once
// Active three-node sliding cable element (docs/formulation.md sections 2-3): internal force and
// tangent, configuration-dependent mass and gravity, and the slider's reference offset (section
// 4). Pure functions of nodal coordinates and parameters; dof order is node by node, (x, y, z) per
// node.
#include "kernels/LineElementTypes.hpp"
#include "kernels/Regularisations.hpp"
#include "kernels/UniformStrainPolyline.hpp"

namespace chute::kernels {

// Node order (1, 2, 3): cable ends 1 and 2, slider 3. F6-F9.
PolylineResult<3> slidingForce(const Vec3& x1, const Vec3& x2, const Vec3& x3, double L,
                               const LineMaterial& mat, bool withTangent);

// Residual-only slidingForce: its force, the same operations as uniformStrainPolyline<3>'s
// residual on the path (1, slider, 2) (D starts from zero vectors, l = 0 + l_1 + l_2), so bit for
// bit, without its result's 9 x 9 stiffness and the copies of the result (the explicit step
// evaluates it for every active sliding element at every step). Inline for the same reason as
// cableForceOnly.
inline Vec9 slidingForceOnly(const Vec3& x1, const Vec3& x2, const Vec3& x3, double L,
                             const LineMaterial& mat) {
  const double apex = kApexFraction * L;
  Vec3 g1, g2;
  double length = 0.0;
  length += partLengthAndGradient(x3 - x1, apex, g1);                            // node 1 -> slider
  length += partLengthAndGradient(x2 - x3, apex, g2);                            // slider -> node 2
  const double strain = uniformStrain(length, L);                                // F6
  const double N = strainModulus(strain, mat) * mat.area / L * strain * length;  // F8
  Vec9 f;
  for (int k = 0; k < 3; ++k) {
    f[k] = N * (0.0 - g1[k]);                // node 1
    f[3 + k] = N * (0.0 + g2[k]);            // node 2
    f[6 + k] = N * ((0.0 + g1[k]) - g2[k]);  // the slider
  }
  return f;
}

// Configuration-dependent inertia force f = M(x) a (F10) and its derivative with respect to x at
// fixed a (the M' a term of a consistent Newton tangent).
struct SlidingInertia {
  Vec9 force;   // M(x) a
  Mat9 mass;    // M(x)
  Mat9 dForce;  // d(M(x) a)/dx
};
SlidingInertia slidingInertia(const Vec3& x1, const Vec3& x2, const Vec3& x3, const Vec9& a,
                              double L, const LineMaterial& mat, MassKind kind);
// Its force M(x) a alone, bit for bit: lumped, M(x) is diagonal (m r1 / 2, m r2 / 2, m / 2 per
// node, F10) and applied without forming M(x), dM/dx or the split ratios' gradients; consistent,
// slidingInertia's own product. The explicit path's lumped mass (EX2) asks for it at every step.
Vec9 slidingInertiaForce(const Vec3& x1, const Vec3& x2, const Vec3& x3, const Vec9& a, double L,
                         const LineMaterial& mat, MassKind kind);

// F11: gravity on the active element and its derivative with respect to x.
struct SlidingGravity {
  Vec9 force;
  Mat9 dForce;
};
SlidingGravity slidingGravity(const Vec3& x1, const Vec3& x2, const Vec3& x3, double L,
                              const LineMaterial& mat, const Vec3& g);

// Reference length on the slider's node-1 side: uniform strain means the slider divides L in the
// ratio l1 : l2 (docs/formulation.md section 4). Used by the material-coordinate tracker.
double sliderReferenceOffset(const Vec3& x1, const Vec3& x2, const Vec3& x3, double L);

}  // namespace chute::kernels
