#pragma once
// Follower pressure on membrane faces (docs/formulation.md section 6), uniform or interpolated
// from nodal values, with its non-symmetric load stiffness; and a face's area vector.
#include <Eigen/Core>
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
Vec3 areaVector(const std::array<Vec3, NumNodes>& x);
template <int NumNodes>
Eigen::Matrix<double, 3, 3 * NumNodes> areaVectorJacobian(const std::array<Vec3, NumNodes>& x);

}  // namespace chute::kernels
