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

// Residual-only faceDrag: the residual r = -f / N that every node of the face gets (FD1), the same
// operations as faceDrag's residual and so bit for bit each of its node segments, without its
// two tangent matrices (the explicit path evaluates it every step on every canopy face).
template <int NumNodes>
Eigen::Vector3d faceDragNodeResidual(const std::array<Eigen::Vector3d, NumNodes>& x,
                                     const std::array<Eigen::Vector3d, NumNodes>& v,
                                     const Eigen::Vector3d& wind, double coefficient,
                                     bool steadySubtracted);

}  // namespace chute::kernels
