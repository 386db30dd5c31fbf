#pragma once
// Active three-node sliding cable element (docs/formulation.md sections 2-3): internal force and
// tangent, configuration-dependent mass and gravity, and the slider's reference offset (section
// 4). Pure functions of nodal coordinates and parameters; dof order is node by node, (x, y, z) per
// node.
#include "kernels/LineElementTypes.hpp"
#include "kernels/UniformStrainPolyline.hpp"

namespace chute::kernels {

// Node order (1, 2, 3): cable ends 1 and 2, slider 3. F6-F9.
PolylineResult<3> slidingForce(const Vec3& x1, const Vec3& x2, const Vec3& x3, double L,
                               const LineMaterial& mat, bool withTangent);

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
