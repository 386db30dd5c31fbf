#pragma once
// Aerodynamic drag on a membrane face (docs/formulation.md FD1): the air resists the
// fabric's motion normal to itself. With n the current unit normal, a = |a| n the face's area
// vector (kernels::areaVector), v the face velocity (mean of the nodal velocities) and w the wind,
// the normal relative velocity u = (v - w) . n gives the drag force on the face
//   f = -(1/2) rho_air Cd (|u| u - s |u0| u0) a,   u0 = -w . n,
// shared equally by the nodes (one-point rule, lumped like the follower pressure). s = 1
// ("steady subtracted") removes the drag of the fabric at rest in the wind, for scenes whose
// prescribed pressure already carries that steady load: what is left is the air's resistance to
// the fabric's own motion (linearised: rho_air Cd |w . n| u per unit area). s = 0 is the plain
// quadratic drag. f does not depend on the node order: n -> -n flips u and u0 as well.
// Returned as the residual r = -f with its exact derivatives with respect to the nodal positions
// and velocities (the integrator combines them as cx dr/dx + cv dr/dv).
#include <Eigen/Core>
#include <array>
#include <cmath>

#include "kernels/PressureKernel.hpp"

namespace chute::kernels {

template <int NumNodes>
struct FaceDrag {
  static constexpr int kDofs = 3 * NumNodes;
  Eigen::Matrix<double, kDofs, 1> residual;
  Eigen::Matrix<double, kDofs, kDofs> dPosition;  // set only withTangent
  Eigen::Matrix<double, kDofs, kDofs> dVelocity;  // set only withTangent
};

template <int NumNodes>
FaceDrag<NumNodes> faceDrag(const std::array<Eigen::Vector3d, NumNodes>& x,
                            const std::array<Eigen::Vector3d, NumNodes>& v,
                            const Eigen::Vector3d& wind, double coefficient /* (1/2) rho_air Cd */,
                            bool steadySubtracted, bool withTangent);

namespace detail {
// What residual and tangents share (FD1): the area vector a = |a| n and |a|^2, the face's
// velocity relative to the wind rel, and g = |u| u - s |u0| u0 with u = rel . n, u0 = -w . n.
// none: a degenerate face or no drag, which carries nothing.
struct FaceFlow {
  bool none = true;
  Eigen::Vector3d a, rel;
  double aa = 0.0, s = 0.0, g = 0.0;
};

// g from the unnormalised area vector: u |a| = rel . a and u0 |a| = -w . a, so g = (|rel . a|
// rel . a - s |w . a| (-w . a)) / |a|^2: no square root and one division on the residual's path
// (the unit normal took a root and a division the rest waited on). The tangent makes |a|, n, u
// and u0 from these.
template <int NumNodes>
FaceFlow faceFlow(const std::array<Eigen::Vector3d, NumNodes>& x,
                  const std::array<Eigen::Vector3d, NumNodes>& v, const Eigen::Vector3d& wind,
                  double coefficient, bool steadySubtracted) {
  FaceFlow f;
  f.a = areaVector<NumNodes>(x);
  f.aa = f.a.squaredNorm();
  if (f.aa == 0.0 || coefficient == 0.0) return f;
  f.none = false;
  Eigen::Vector3d vFace = Eigen::Vector3d::Zero();
  for (const auto& vi : v) vFace += vi;
  f.rel = (1.0 / NumNodes) * vFace - wind;
  f.s = steadySubtracted ? 1.0 : 0.0;
  const double ua = f.rel.dot(f.a), u0a = -wind.dot(f.a);
  f.g = (std::abs(ua) * ua - f.s * std::abs(u0a) * u0a) / f.aa;  // |u| u - s |u0| u0
  return f;
}
}  // namespace detail

// Residual-only faceDrag: the residual r = -f / N that every node of the face gets (FD1), the same
// operations as faceDrag's residual and so bit for bit each of its node segments, without its
// two tangent matrices (the explicit path evaluates it every step on every canopy face). Inline:
// called across files, the face's nodes went through memory and were read back across the
// stores' boundaries, a stall that cost more than the arithmetic (perf, the explicit C-9).
template <int NumNodes>
Eigen::Vector3d faceDragNodeResidual(const std::array<Eigen::Vector3d, NumNodes>& x,
                                     const std::array<Eigen::Vector3d, NumNodes>& v,
                                     const Eigen::Vector3d& wind, double coefficient,
                                     bool steadySubtracted) {
  const detail::FaceFlow f = detail::faceFlow<NumNodes>(x, v, wind, coefficient, steadySubtracted);
  if (f.none) return Eigen::Vector3d::Zero();
  const double share = coefficient / NumNodes;  // per node
  return share * f.g * f.a;
}

}  // namespace chute::kernels
