#pragma once
// Drag on a line element relative to a wind (docs/formulation.md section 6).
#include <Eigen/Core>

namespace chute::kernels {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

// Drag on a line element of diameter d (docs/formulation.md section 6):
// f = -(1/2) rho_air Cd d l |v_n| v_n, v_n the air-relative velocity normal to the element, shared
// equally by the two nodes. Returned as the residual contribution r = -f (per node: half), with
// its derivatives with respect to the nodal positions and velocities.
struct LineDrag {
  Eigen::Matrix<double, 6, 1> residual;
  Eigen::Matrix<double, 6, 6> dPosition;  // set only withTangent
  Eigen::Matrix<double, 6, 6> dVelocity;  // set only withTangent
};
LineDrag lineDrag(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb, const Vec3& wind,
                  double coefficient /* (1/2) rho_air Cd d */, bool withTangent);
// Residual-only lineDrag: the residual each of the two nodes gets, the same operations as
// lineDrag's and so bit for bit each of its halves, without its two tangent matrices (the
// explicit path evaluates it every step on every line element).
Vec3 lineDragNodeResidual(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb,
                          const Vec3& wind, double coefficient);

}  // namespace chute::kernels
