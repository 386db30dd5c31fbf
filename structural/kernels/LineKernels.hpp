#pragma once
// Two-node cable (docs/formulation.md section 1) and active three-node sliding cable element
// (sections 2-3): internal force and tangent, mass and gravity. Pure functions of nodal
// coordinates and parameters; dof order is node by node, (x, y, z) per node.
#include <Eigen/Core>

#include "kernels/UniformStrainPolyline.hpp"

namespace chute::kernels {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec9 = Eigen::Matrix<double, 9, 1>;
using Mat9 = Eigen::Matrix<double, 9, 9>;

enum class MassKind { Lumped, Consistent };

// ---- two-node cable / truss ------------------------------------------------------------------
// F1-F3: nodes (a, b).
PolylineResult<2> cableForce(const Vec3& xa, const Vec3& xb, double L, const LineMaterial& mat,
                             bool withTangent);
// F4: constant mass matrix.
Mat6 cableMass(double L, const LineMaterial& mat, MassKind kind);
// F5: constant gravity load (rho A0 L / 2) g on each node.
Vec6 cableGravity(double L, const LineMaterial& mat, const Vec3& g);

// Slack / taut switch of a tension-only cable (the kink of its energy at zero strain, where the
// stiffness jumps from E A / L to nothing). Given the relative position d = x_b - x_a at the
// step's start and its change delta over the step, returns the fraction of delta at which
// |d + f delta| = L, or 1 if the motion does not cross it. A start or an end within
// kSlackTautBand L of the switch is on it, not across it (RG4, kernels/Regularisations.hpp).
double slackTautCrossing(const Vec3& d, const Vec3& delta, double L);

// ---- active sliding element -------------------------------------------------------------------
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
