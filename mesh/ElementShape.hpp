#pragma once
// Whether a membrane or line element can be used, from its node positions alone: distinct nodes,
// a length or an area, and (quadrilaterals) convex corners about the normal the membrane kernel
// uses (the cross product of the diagonals, docs/formulation.md M1). One check for every way an
// element reaches a model: a .msh import (MshReader) and a case's explicit elements.
#include <cstddef>
#include <string>

#include "model/Model.hpp"

namespace chute::mesh {

struct ShapeProblem {
  std::string why;  // empty: the element is usable; "%" stands for the node it is about
  int node = -1;    // that node, local (0-based), or -1
  explicit operator bool() const { return !why.empty(); }
  // The reason with the node named (e.g. "node 'c' appears twice").
  std::string text(const std::string& nodeName) const;
};

// x[0..n-1]: the positions of an element of n = 2 (line), 3 (triangle) or 4 (quadrilateral)
// nodes, ids[0..n-1] their node ids or tags (a repeated id is a repeated node). Tolerances are
// relative to the element's longest edge, so the check does not depend on the unit of length.
ShapeProblem elementShapeProblem(const Vec3* x, const std::size_t* ids, int n);

}  // namespace chute::mesh
