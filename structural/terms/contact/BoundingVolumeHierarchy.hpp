#pragma once
// An axis-aligned bounding-box tree over a fixed list of primitives (docs/contact.md CT10):
// built top down by median splits of the boxes' centres along the longest axis (O(n log n)),
// refitted bottom up as the primitives move (O(n), the tree kept), and queried for every leaf
// whose box overlaps a given box (O(log n + hits) for a well-shaped tree). A refit tree grows
// looser as the mesh deforms; quality() measures it so that the owner rebuilds it.
#include <Eigen/Core>
#include <vector>

namespace chute::contact {

struct Aabb {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300);
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-1e300);
  void add(const Eigen::Vector3d& p) { lo = lo.cwiseMin(p), hi = hi.cwiseMax(p); }
  void add(const Aabb& b) { lo = lo.cwiseMin(b.lo), hi = hi.cwiseMax(b.hi); }
  void inflate(double r) { lo.array() -= r, hi.array() += r; }
  bool overlaps(const Aabb& b) const {  // scalar: Eigen's all() took twice as long here
    return lo[0] <= b.hi[0] && b.lo[0] <= hi[0] && lo[1] <= b.hi[1] && b.lo[1] <= hi[1] &&
           lo[2] <= b.hi[2] && b.lo[2] <= hi[2];
  }
  double surfaceArea() const {
    const Eigen::Vector3d d = (hi - lo).cwiseMax(0.0);
    return 2.0 * (d.x() * d.y() + d.y() * d.z() + d.z() * d.x());
  }
};

class BoundingVolumeHierarchy {
 public:
  static constexpr int kLeafSize = 4;

  void build(const std::vector<Aabb>& boxes);
  // The same tree over moved boxes (same count, same order).
  void refit(const std::vector<Aabb>& boxes);
  // Sum of the inner nodes' surface areas over the leaves' (1 for a tree of one leaf): what a
  // query visits per primitive, roughly. Refits that make it much larger than at the build call
  // for a new build.
  double looseness() const;
  double loosenessAtBuild() const { return loosenessAtBuild_; }
  bool empty() const { return nodes_.empty(); }

  // visit(i, j) once for every unordered pair of distinct primitives whose boxes overlap. Each
  // leaf's box is queried against the tree, skipping the subtrees whose primitives all come
  // before the leaf's in the tree's order (their pairs with it were met from their side): one
  // traversal per leaf, not per primitive, and none twice.
  template <class Visit>
  void selfPairs(Visit&& visit) const {
    for (const Node& leaf : nodes_) {
      if (leaf.count == 0) continue;
      const int leafEnd = leaf.first + leaf.count;
      forEachLeafOverlapping(leaf.box, leaf.first, [&](const Node& n) {
        for (int i = leaf.first; i < leafEnd; ++i)
          for (int j = n.first == leaf.first ? i + 1 : n.first; j < n.first + n.count; ++j)
            if (leafBoxes_[i].overlaps(leafBoxes_[j])) visit(order_[i], order_[j]);
      });
    }
  }
  // visit(k) for every primitive k whose box overlaps `box`.
  template <class Visit>
  void query(const Aabb& box, Visit&& visit) const {
    forEachLeafOverlapping(box, 0, [&](const Node& n) {
      for (int i = n.first; i < n.first + n.count; ++i)
        if (leafBoxes_[i].overlaps(box)) visit(order_[i]);
    });
  }

 private:
  struct Node {
    Aabb box;
    int first = 0, count = 0;  // leaves: the primitives order_[first, first + count)
    int left = -1;             // inner nodes: children left and left + 1
    int end = 0;               // every node: its primitives are order_[.., end)
  };
  // leafVisit(n) for every leaf n whose box overlaps `box`, among the subtrees holding a
  // primitive at order_ position `from` or after.
  template <class LeafVisit>
  void forEachLeafOverlapping(const Aabb& box, int from, LeafVisit&& leafVisit) const {
    if (nodes_.empty()) return;
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& n = nodes_[stack[--top]];
      if (n.end <= from || !n.box.overlaps(box)) continue;
      if (n.count > 0) {
        leafVisit(n);
      } else {
        stack[top++] = n.left;
        stack[top++] = n.left + 1;
      }
    }
  }
  void buildNode(int self, int first, int count, int depth);
  std::vector<Node> nodes_;
  std::vector<int> order_;
  std::vector<Aabb> boxes_;
  std::vector<Aabb> leafBoxes_;  // boxes_ in the leaves' order (order_), read by the queries
  double loosenessAtBuild_ = 1.0;
};

}  // namespace chute::contact
