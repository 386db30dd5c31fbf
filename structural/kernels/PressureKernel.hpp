#pragma once
// Follower pressure on membrane faces (docs/formulation.md section 6), uniform or interpolated
// from nodal values, with its non-symmetric load stiffness; and a face's area vector.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>

namespace chute::kernels {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

// Follower pressure p on the current surface, f_i = p int N_i (x_,1 x x_,2) dxi (outward along
// the element's node-order normal), and its derivative df/dx (non-symmetric load stiffness).
template <int NumNodes>
struct PressureLoad {
  Eigen::Matrix<double, 3 * NumNodes, 1> force;
  Eigen::Matrix<double, 3 * NumNodes, 3 * NumNodes> dForce;  // set only withTangent
};
template <int NumNodes>
PressureLoad<NumNodes> pressureLoad(const std::array<Vec3, NumNodes>& x, double p,
                                    bool withTangent);

// Residual-only pressureLoad<3> (P1): a flat triangle under a uniform pressure p loads each of its
// three nodes with the same force w N_i (x_,xi x x_,eta), the one-point rule's w = p / 2 and
// N_i = 1/3: p A / 3 with A the area vector. The same operations as pressureLoad<3>, so bit for bit
// each of its three force segments, without its generic quadrature loop and 9 x 9 tangent (the
// explicit path evaluates it every step on every canopy face).
inline Vec3 trianglePressureForce(const std::array<Vec3, 3>& x, double p) {
  return ((0.5 * p) * (1.0 / 3.0)) * (x[1] - x[0]).cross(x[2] - x[0]);
}

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
Vec3 areaVector(const std::array<Vec3, NumNodes>& x) {
  if constexpr (NumNodes == 3) {
    return 0.5 * (x[1] - x[0]).cross(x[2] - x[0]);
  } else {
    return 0.5 * (x[2] - x[0]).cross(x[3] - x[1]);
  }
}
template <int NumNodes>
Eigen::Matrix<double, 3, 3 * NumNodes> areaVectorJacobian(const std::array<Vec3, NumNodes>& x);

}  // namespace chute::kernels
