#pragma once
// An independent check that a structure does not pass through itself: counts the pairs of
// non-adjacent triangles (sharing no vertex) that meet, and the line segments (2-node line cells:
// lines, tapes, risers) that meet a triangle they share no vertex with. It uses no contact code:
// exact segment-triangle tests (SegmentTriangle.hpp) behind its own broad phase, a bounding-box
// tree over the triangles (built in O(n log n), each query O(log n + candidates)).
//
// "Meet" means the closed elements share a point, so touching counts: a count of 0 says every
// pair of non-adjacent elements is disjoint. Adjacency is by topology (a shared vertex index),
// never by distance. Quadrilaterals enter as two triangles (0, 1, 2) and (0, 2, 3), adjacent to
// each other. Degenerate triangles (no area) are skipped and counted apart.
#include <array>
#include <utility>
#include <vector>

#include "model/Model.hpp"

namespace chute::mesh {

struct IntersectionMesh {
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles;  // indices into points
  std::vector<std::array<int, 2>> segments;
  // A quadrilateral as its two triangles.
  void addQuad(int a, int b, int c, int d) {
    triangles.push_back({a, b, c});
    triangles.push_back({a, c, d});
  }
};

struct IntersectionCounts {
  long trianglePairs = 0;        // non-adjacent triangles that meet (each pair once)
  long segmentTriangle = 0;      // segments meeting a triangle they share no vertex with
  long degenerateTriangles = 0;  // skipped: no area
  long candidatePairs = 0;       // box-overlapping non-adjacent pairs tested exactly
  std::vector<std::pair<int, int>> triangleHits;  // (triangle, triangle), first < second
  std::vector<std::pair<int, int>> segmentHits;   // (segment, triangle)
  long total() const { return trianglePairs + segmentTriangle; }
};

// Throws std::invalid_argument for an index out of range.
IntersectionCounts countIntersections(const IntersectionMesh& mesh);

// The same count by testing every pair (O(n^2)): the reference for the broad phase's tests.
IntersectionCounts countIntersectionsBruteForce(const IntersectionMesh& mesh);

}  // namespace chute::mesh
