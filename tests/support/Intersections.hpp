#pragma once
// An independent count of interpenetrations (no code shared with the contact kernels): pairs of
// triangles without a common node one of whose edges crosses the other, and line segments that
// cross a triangle without sharing a node with it, by orientation predicates (the signs of
// tetrahedron volumes) evaluated in long double. A crossing needs strictly opposite signs: a
// segment touching a triangle to round-off is not counted.
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <vector>

#include "model/Model.hpp"

namespace chute::testing {

using Tri = std::array<int, 3>;
using Seg = std::array<int, 2>;

// Six times the signed volume of tetrahedron (a, b, c, d).
inline long double orient(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                          const Eigen::Vector3d& c, const Eigen::Vector3d& d) {
  const long double bx = b.x() - (long double)a.x(), by = b.y() - (long double)a.y(),
                    bz = b.z() - (long double)a.z();
  const long double cx = c.x() - (long double)a.x(), cy = c.y() - (long double)a.y(),
                    cz = c.z() - (long double)a.z();
  const long double dx = d.x() - (long double)a.x(), dy = d.y() - (long double)a.y(),
                    dz = d.z() - (long double)a.z();
  return bx * (cy * dz - cz * dy) - by * (cx * dz - cz * dx) + bz * (cx * dy - cy * dx);
}

// Whether segment pq crosses triangle abc: p and q strictly on opposite sides of its plane, and
// the line pq strictly inside its three edges.
inline bool segmentCrossesTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                                   const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                   const Eigen::Vector3d& c) {
  const long double sp = orient(a, b, c, p), sq = orient(a, b, c, q);
  if (!((sp > 0 && sq < 0) || (sp < 0 && sq > 0))) return false;
  const long double e1 = orient(p, q, a, b), e2 = orient(p, q, b, c), e3 = orient(p, q, c, a);
  return (e1 > 0 && e2 > 0 && e3 > 0) || (e1 < 0 && e2 < 0 && e3 < 0);
}

struct IntersectionCount {
  long trianglePairs = 0;     // pairs of triangles without a common node that intersect
  long segmentTriangles = 0;  // line segments crossing a triangle they share no node with
};

// The triangles of every membrane element of the model (a quad as its triangles 012 and 023).
inline std::vector<Tri> modelTriangles(const Model& m) {
  std::vector<Tri> t;
  for (const auto& e : m.membranes) {
    t.push_back({e.nodes[0], e.nodes[1], e.nodes[2]});
    if (e.numNodes == 4) t.push_back({e.nodes[0], e.nodes[2], e.nodes[3]});
  }
  return t;
}

inline IntersectionCount countIntersections(const Eigen::VectorXd& x, const std::vector<Tri>& tris,
                                            const std::vector<Seg>& segs) {
  auto at = [&](int n) { return Eigen::Vector3d(x.segment<3>(3 * n)); };
  struct Box {
    Eigen::Vector3d lo, hi;
  };
  auto box = [&](std::initializer_list<int> nodes) {
    Box b{Eigen::Vector3d::Constant(1e300), Eigen::Vector3d::Constant(-1e300)};
    for (int n : nodes) b.lo = b.lo.cwiseMin(at(n)), b.hi = b.hi.cwiseMax(at(n));
    return b;
  };
  auto overlap = [](const Box& a, const Box& b) {
    return (a.lo.array() <= b.hi.array()).all() && (b.lo.array() <= a.hi.array()).all();
  };
  std::vector<Box> tb;
  for (const auto& t : tris) tb.push_back(box({t[0], t[1], t[2]}));
  auto shares = [](const Tri& t, int n) { return t[0] == n || t[1] == n || t[2] == n; };
  IntersectionCount c;
  for (size_t i = 0; i < tris.size(); ++i)
    for (size_t j = i + 1; j < tris.size(); ++j) {
      const Tri &A = tris[i], &B = tris[j];
      if (!overlap(tb[i], tb[j])) continue;
      if (shares(B, A[0]) || shares(B, A[1]) || shares(B, A[2])) continue;
      bool hit = false;
      for (int k = 0; k < 3 && !hit; ++k) {
        hit = segmentCrossesTriangle(at(A[k]), at(A[(k + 1) % 3]), at(B[0]), at(B[1]), at(B[2])) ||
              segmentCrossesTriangle(at(B[k]), at(B[(k + 1) % 3]), at(A[0]), at(A[1]), at(A[2]));
      }
      c.trianglePairs += hit;
    }
  for (const auto& s : segs) {
    const Box sb = box({s[0], s[1]});
    for (size_t j = 0; j < tris.size(); ++j) {
      const Tri& B = tris[j];
      if (!overlap(sb, tb[j]) || shares(B, s[0]) || shares(B, s[1])) continue;
      c.segmentTriangles +=
          segmentCrossesTriangle(at(s[0]), at(s[1]), at(B[0]), at(B[1]), at(B[2]));
    }
  }
  return c;
}

}  // namespace chute::testing
