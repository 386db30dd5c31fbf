#include "IntersectionCheck.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include "SegmentTriangle.hpp"

namespace chute::mesh {

namespace {

struct Box {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = Vec3::Constant(-std::numeric_limits<double>::infinity());
  void grow(const Vec3& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  void grow(const Box& b) {
    lo = lo.cwiseMin(b.lo);
    hi = hi.cwiseMax(b.hi);
  }
  // Closed boxes: touching boxes overlap (touching elements meet). Coordinates are compared as
  // they are, so no pair the exact test would find is lost.
  bool overlaps(const Box& b) const {
    return (lo.array() <= b.hi.array()).all() && (b.lo.array() <= hi.array()).all();
  }
};

// A bounding-box tree over the triangles: nodes split at the median of the longest axis of their
// centroids' box, leaves of at most kLeaf triangles; depth about log2(n / kLeaf).
class BoxTree {
 public:
  explicit BoxTree(const std::vector<Box>& boxes) : boxes_(boxes), order_(boxes.size()) {
    std::iota(order_.begin(), order_.end(), 0);
    if (!boxes.empty()) build(0, static_cast<int>(order_.size()));
  }
  // Calls f(i) for every triangle i whose box overlaps q.
  template <class F>
  void query(const Box& q, F&& f) const {
    if (nodes_.empty()) return;
    std::vector<int> stack = {0};
    while (!stack.empty()) {
      const Node& n = nodes_[stack.back()];
      stack.pop_back();
      if (!n.box.overlaps(q)) continue;
      if (n.left < 0) {
        for (int k = n.begin; k < n.end; ++k)
          if (boxes_[order_[k]].overlaps(q)) f(order_[k]);
      } else {
        stack.push_back(n.left);
        stack.push_back(n.right);
      }
    }
  }

 private:
  static constexpr int kLeaf = 4;
  struct Node {
    Box box;
    int left = -1, right = -1;  // children; -1 for a leaf
    int begin = 0, end = 0;     // a leaf's triangles: order_[begin, end)
  };
  int build(int begin, int end) {
    const int id = static_cast<int>(nodes_.size());
    nodes_.push_back({});
    Box box, centres;
    for (int k = begin; k < end; ++k) {
      box.grow(boxes_[order_[k]]);
      centres.grow(0.5 * (boxes_[order_[k]].lo + boxes_[order_[k]].hi));
    }
    nodes_[id].box = box;
    nodes_[id].begin = begin;
    nodes_[id].end = end;
    if (end - begin <= kLeaf) return id;
    int axis = 0;
    (centres.hi - centres.lo).maxCoeff(&axis);
    const int mid = (begin + end) / 2;
    std::nth_element(
        order_.begin() + begin, order_.begin() + mid, order_.begin() + end, [&](int a, int b) {
          return boxes_[a].lo[axis] + boxes_[a].hi[axis] < boxes_[b].lo[axis] + boxes_[b].hi[axis];
        });
    const int left = build(begin, mid);
    const int right = build(mid, end);
    nodes_[id].left = left;
    nodes_[id].right = right;
    return id;
  }
  const std::vector<Box>& boxes_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
};

void checkIndices(const IntersectionMesh& m) {
  const int n = static_cast<int>(m.points.size());
  for (const auto& t : m.triangles)
    for (int i : t)
      if (i < 0 || i >= n)
        throw std::invalid_argument("intersection check: triangle vertex " + std::to_string(i) +
                                    " out of range (" + std::to_string(n) + " points)");
  for (const auto& s : m.segments)
    for (int i : s)
      if (i < 0 || i >= n)
        throw std::invalid_argument("intersection check: segment vertex " + std::to_string(i) +
                                    " out of range (" + std::to_string(n) + " points)");
}

bool share(const std::array<int, 3>& t, int i) {
  return t[0] == i || t[1] == i || t[2] == i;
}

bool adjacent(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  return share(b, a[0]) || share(b, a[1]) || share(b, a[2]);
}

bool adjacent(const std::array<int, 2>& s, const std::array<int, 3>& t) {
  return share(t, s[0]) || share(t, s[1]);
}

// Counts with `candidates(box, f)` calling f for the triangles to test against a box (each
// triangle pair once: j > i).
template <class Candidates>
IntersectionCounts count(const IntersectionMesh& m, const std::vector<char>& degenerate,
                         Candidates&& candidates) {
  IntersectionCounts out;
  const auto& P = m.points;
  for (char d : degenerate) out.degenerateTriangles += d;
  for (int i = 0; i < static_cast<int>(m.triangles.size()); ++i) {
    if (degenerate[i]) continue;
    const auto& t = m.triangles[i];
    Box b;
    for (int v : t) b.grow(P[v]);
    candidates(b, [&](int j) {
      if (j <= i || degenerate[j]) return;
      const auto& u = m.triangles[j];
      if (adjacent(t, u)) return;
      ++out.candidatePairs;
      if (trianglesMeet(P[t[0]], P[t[1]], P[t[2]], P[u[0]], P[u[1]], P[u[2]])) {
        ++out.trianglePairs;
        out.triangleHits.emplace_back(i, j);
      }
    });
  }
  for (int s = 0; s < static_cast<int>(m.segments.size()); ++s) {
    const auto& e = m.segments[s];
    Box b;
    b.grow(P[e[0]]);
    b.grow(P[e[1]]);
    candidates(b, [&](int j) {
      if (degenerate[j]) return;
      const auto& u = m.triangles[j];
      if (adjacent(e, u)) return;
      ++out.candidatePairs;
      if (segmentMeetsTriangle(P[e[0]], P[e[1]], P[u[0]], P[u[1]], P[u[2]])) {
        ++out.segmentTriangle;
        out.segmentHits.emplace_back(s, j);
      }
    });
  }
  std::sort(out.triangleHits.begin(), out.triangleHits.end());
  std::sort(out.segmentHits.begin(), out.segmentHits.end());
  return out;
}

std::vector<char> degenerateTriangles(const IntersectionMesh& m) {
  std::vector<char> d(m.triangles.size());
  for (size_t i = 0; i < m.triangles.size(); ++i) {
    const auto& t = m.triangles[i];
    d[i] = isDegenerate(m.points[t[0]], m.points[t[1]], m.points[t[2]]);
  }
  return d;
}

}  // namespace

IntersectionCounts countIntersections(const IntersectionMesh& m) {
  checkIndices(m);
  const auto degenerate = degenerateTriangles(m);
  std::vector<Box> boxes(m.triangles.size());
  for (size_t i = 0; i < m.triangles.size(); ++i)
    for (int v : m.triangles[i]) boxes[i].grow(m.points[v]);
  const BoxTree tree(boxes);
  return count(m, degenerate, [&](const Box& b, auto&& f) { tree.query(b, f); });
}

IntersectionCounts countIntersectionsBruteForce(const IntersectionMesh& m) {
  checkIndices(m);
  const auto degenerate = degenerateTriangles(m);
  const int n = static_cast<int>(m.triangles.size());
  return count(m, degenerate, [&](const Box&, auto&& f) {
    for (int j = 0; j < n; ++j) f(j);
  });
}

}  // namespace chute::mesh
