#pragma once
// Dof-vector types of the two-node (6 dofs) and three-node (9 dofs) line elements and the kind of
// their mass matrices; dof order is node by node, (x, y, z) per node.
#include <Eigen/Core>

namespace chute::kernels {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec9 = Eigen::Matrix<double, 9, 1>;
using Mat9 = Eigen::Matrix<double, 9, 9>;

enum class MassKind { Lumped, Consistent };

}  // namespace chute::kernels
