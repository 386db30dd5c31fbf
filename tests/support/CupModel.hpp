#pragma once
// A cup of membrane open at the bottom, for the tests of the membrane terms: a regular polygon's
// roof at z = height, fanned from its centre into triangles, on walls of quads down to z = 0,
// element by element in turn (roof triangle, wall quad, ...), outward normals (the node order's).
// One membrane material and set; no constraint, mass or load yet.
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "model/Model.hpp"

namespace chute::testing {

inline Model openCup(int sides, double radius, double height,
                     const kernels::MembraneMaterial& material) {
  Model m;
  m.membraneMaterials.push_back(material);
  m.membraneSets.push_back({"cup"});
  const int top = m.addNode(Vec3(0, 0, height));
  std::vector<int> upper, lower;
  for (int k = 0; k < sides; ++k) {
    const double a = 2 * std::numbers::pi * k / sides;
    upper.push_back(m.addNode(Vec3(radius * std::cos(a), radius * std::sin(a), height)));
    lower.push_back(m.addNode(Vec3(radius * std::cos(a), radius * std::sin(a), 0.0)));
  }
  auto element = [&](std::array<int, 4> nodes, int n) {
    MembraneElement e;
    e.nodes = nodes;
    e.numNodes = n;
    e.material = 0;
    e.set = 0;
    m.membranes.push_back(e);
  };
  for (int k = 0; k < sides; ++k) {
    const int j = (k + 1) % sides;
    element({top, upper[k], upper[j], -1}, 3);             // roof, normal up
    element({lower[k], lower[j], upper[j], upper[k]}, 4);  // wall, normal out
  }
  m.u0.assign(m.numNodes(), Vec3::Zero());
  m.pointMass.assign(m.numNodes(), 0.0);
  m.constraint.assign(m.numNodes(), NodeConstraint{});
  return m;
}

}  // namespace chute::testing
