#include "terms/contact/BoundingVolumeHierarchy.hpp"

#include <algorithm>
#include <numeric>

namespace chute::contact {

void BoundingVolumeHierarchy::build(const std::vector<Aabb>& boxes) {
  boxes_ = boxes;
  nodes_.clear();
  order_.resize(boxes.size());
  std::iota(order_.begin(), order_.end(), 0);
  if (boxes.empty()) return;
  nodes_.reserve(2 * (boxes.size() / kLeafSize + 1));
  nodes_.emplace_back();
  buildNode(0, 0, static_cast<int>(boxes.size()), 0);
  leafBoxes_.resize(boxes_.size());
  for (size_t i = 0; i < order_.size(); ++i) leafBoxes_[i] = boxes_[order_[i]];
  loosenessAtBuild_ = looseness();
}

// Node 0 is the root; a node's two children are stored next to each other, after it, and their
// subtrees after them: every node's index is above its parent's. Depth is bounded by the median
// split (log2 n + 1); the query's stack holds 128.
void BoundingVolumeHierarchy::buildNode(int self, int first, int count, int depth) {
  Aabb box, centres;
  for (int i = first; i < first + count; ++i) {
    box.add(boxes_[order_[i]]);
    centres.add(0.5 * (boxes_[order_[i]].lo + boxes_[order_[i]].hi));
  }
  nodes_[self].box = box;
  nodes_[self].end = first + count;
  if (count <= kLeafSize || depth >= 60) {
    nodes_[self].first = first, nodes_[self].count = count;
    return;
  }
  int axis = 0;
  (centres.hi - centres.lo).maxCoeff(&axis);
  const int half = count / 2;
  // Ties broken by index, so that the tree depends on the boxes alone.
  std::nth_element(order_.begin() + first, order_.begin() + first + half,
                   order_.begin() + first + count, [&](int a, int b) {
                     const double ca = boxes_[a].lo[axis] + boxes_[a].hi[axis];
                     const double cb = boxes_[b].lo[axis] + boxes_[b].hi[axis];
                     return ca < cb || (ca == cb && a < b);
                   });
  const int left = static_cast<int>(nodes_.size());
  nodes_[self].left = left;
  nodes_.emplace_back();
  nodes_.emplace_back();
  buildNode(left, first, half, depth + 1);
  buildNode(left + 1, first + half, count - half, depth + 1);
}

void BoundingVolumeHierarchy::refit(const std::vector<Aabb>& boxes) {
  boxes_ = boxes;
  for (size_t i = 0; i < order_.size(); ++i) leafBoxes_[i] = boxes_[order_[i]];
  // Children are stored after their parent: one pass from the back refits every node.
  for (int k = static_cast<int>(nodes_.size()) - 1; k >= 0; --k) {
    Node& n = nodes_[k];
    Aabb b;
    if (n.count > 0) {
      for (int i = n.first; i < n.first + n.count; ++i) b.add(leafBoxes_[i]);
    } else {
      b.add(nodes_[n.left].box);
      b.add(nodes_[n.left + 1].box);
    }
    n.box = b;
  }
}

double BoundingVolumeHierarchy::looseness() const {
  double inner = 0.0, leaves = 0.0;
  for (const auto& n : nodes_) (n.count > 0 ? leaves : inner) += n.box.surfaceArea();
  return leaves > 0.0 ? 1.0 + inner / leaves : 1.0;
}

}  // namespace chute::contact
