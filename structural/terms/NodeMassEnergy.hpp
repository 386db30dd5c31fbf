#pragma once
// A lumped mass's kinetic and gravity energy node by node (M4): each node with mass once, its
// mass the sum of its elements' shares, where a pass over the elements formed a product per
// element (the membranes' cost more than their forces' pass). MembraneTerm's triangles and
// CableTerm's cables keep their nodes' masses so.
#include <Eigen/Core>
#include <cstddef>
#include <utility>
#include <vector>

#include "assembly/Term.hpp"

namespace chute {

// (node, mass), in node order.
using NodeMasses = std::vector<std::pair<int, double>>;

// The nodes with has[n] set and their masses mass[n].
inline NodeMasses nodesWithMass(const std::vector<double>& mass, const std::vector<char>& has) {
  NodeMasses out;
  for (size_t n = 0; n < mass.size(); ++n)
    if (has[n]) out.emplace_back(static_cast<int>(n), mass[n]);
  return out;
}

// (1/2) sum m_i |v_i|^2 to e.kinetic and -sum m_i g . x_i to e.gravity over nodes [begin, end).
inline void addNodeMassEnergy(const NodeMasses& nodes, size_t begin, size_t end,
                              const Eigen::Vector3d& g, const Eigen::VectorXd& x,
                              const Eigen::VectorXd& v, EnergyBreakdown& e) {
  double kinetic = 0.0, gravity = 0.0;
  for (size_t i = begin; i < end; ++i) {
    const auto& [node, mass] = nodes[i];
    kinetic += mass * v.segment<3>(3 * node).squaredNorm();
    gravity += mass * g.dot(x.segment<3>(3 * node));
  }
  e.kinetic += 0.5 * kinetic;
  e.gravity -= gravity;
}

}  // namespace chute
