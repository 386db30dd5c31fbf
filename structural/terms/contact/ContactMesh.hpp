#pragma once
// The primitives of fabric contact (docs/contact.md CT11): the triangles, edges and vertices of
// the membrane sets that take part (a quadrilateral counts as two triangles and its diagonal as
// an edge), and the line elements of the line sets that take part (cables, and sliding-chain
// elements, which bend at the slider on them: chain node -> slider -> chain node). Which pairs of
// them may touch is decided here, by topology: a point never meets a triangle it is a corner of,
// two segments never meet when they share a node, and lines never meet lines.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "model/Model.hpp"

namespace chute {
class SlidingGroupState;
}

namespace chute::contact {

struct LineElement {
  int a = -1, b = -1;
  int group = -1;    // >= 0: element `element` of sliding group `group` (a slider may be on it)
  int element = -1;  // index in the group's chain
};

class ContactMesh {
 public:
  ContactMesh(const Model& m, const ContactDef& def);

  const std::vector<int>& points() const { return points_; }  // fabric vertices and line nodes
  const std::vector<std::array<int, 3>>& triangles() const { return triangles_; }
  const std::vector<std::array<int, 2>>& edges() const { return edges_; }  // fabric, a < b
  const std::vector<LineElement>& lines() const { return lines_; }
  // Every node of a primitive (sorted, each once): what the broad phase's skin watches.
  const std::vector<int>& nodes() const { return nodes_; }
  // Whether a node has a free dof (a pair of fixed primitives needs no force).
  bool free(int node) const { return free_[node] != 0; }

  // The slider node on each line element (lines() order) in `groups`' trial state, or -1
  // (cables, inactive elements); where two sliders share an element, the first one's, as
  // SlidingGroupState::sliderOfElement gives. groups: one state per sliding group of the model,
  // in order. A pass over the sliders' active elements, not a search per element.
  void slidersOn(const std::vector<const SlidingGroupState*>& groups,
                 std::vector<int>& sliders) const;

  // Topology (CT11): shared nodes.
  static bool incident(int point, const std::array<int, 3>& t) {
    return point == t[0] || point == t[1] || point == t[2];
  }
  static bool adjacent(const std::array<int, 2>& e, const std::array<int, 2>& f) {
    return e[0] == f[0] || e[0] == f[1] || e[1] == f[0] || e[1] == f[1];
  }

 private:
  std::vector<int> points_;
  std::vector<std::array<int, 3>> triangles_;
  std::vector<std::array<int, 2>> edges_;
  std::vector<LineElement> lines_;
  std::vector<std::vector<int>> lineOfElement_;  // per sliding group and chain element (-1: none)
  std::vector<int> nodes_;
  std::vector<char> free_;
};

}  // namespace chute::contact
