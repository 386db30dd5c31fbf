#pragma once
// Shared by the membrane-side terms (MembraneTerm, PressureTerm): gathers of an element's nodes
// and the expansion of a scalar node-pair matrix to 3 x 3 blocks. Internal to terms/.
#include <array>

#include "model/Model.hpp"

namespace chute::membrane_assembly {

using kernels::Vec3;

template <int N>
std::array<Vec3, N> gatherNodes(const Eigen::VectorXd& x, const MembraneElement& e) {
  std::array<Vec3, N> out;
  for (int i = 0; i < N; ++i) out[i] = x.segment<3>(3 * e.nodes[i]);
  return out;
}
template <int N>
std::array<int, N> nodeIds(const MembraneElement& e) {
  std::array<int, N> ids;
  for (int i = 0; i < N; ++i) ids[i] = e.nodes[i];
  return ids;
}
// N x N scalar matrix times I3.
template <int N>
Eigen::Matrix<double, 3 * N, 3 * N> expand(const Eigen::Matrix<double, N, N>& M) {
  Eigen::Matrix<double, 3 * N, 3 * N> out = Eigen::Matrix<double, 3 * N, 3 * N>::Zero();
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j)
      out.template block<3, 3>(3 * i, 3 * j).diagonal().setConstant(M(i, j));
  return out;
}
}  // namespace chute::membrane_assembly
