#include "SegmentTriangle.hpp"

#include <algorithm>

#include "ExactPredicates.hpp"

namespace chute::mesh {

namespace {

struct P2 {
  double x, y;
};

// The point with coordinate `drop` removed: an exact affine map of the plane of a triangle onto a
// coordinate plane, bijective when the triangle's projection keeps its area.
P2 project(const Vec3& v, int drop) {
  if (drop == 0) return {v.y(), v.z()};
  if (drop == 1) return {v.z(), v.x()};
  return {v.x(), v.y()};
}

int orient(const P2& a, const P2& b, const P2& c) {
  return orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
}

// The coordinate whose removal keeps the triangle's area (its normal has a nonzero component
// there), or -1 for a degenerate triangle.
int projectionAxis(const Vec3& a, const Vec3& b, const Vec3& c) {
  for (int drop : {2, 0, 1})
    if (orient(project(a, drop), project(b, drop), project(c, drop)) != 0) return drop;
  return -1;
}

// r, known to be collinear with p and q, lies on the closed segment pq.
bool onSegment(const P2& p, const P2& q, const P2& r) {
  return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
         r.y <= std::max(p.y, q.y);
}

// Closed segments pq and rs in a plane share a point (degenerate segments included).
bool segmentsMeet(const P2& p, const P2& q, const P2& r, const P2& s) {
  const int d1 = orient(p, q, r), d2 = orient(p, q, s), d3 = orient(r, s, p), d4 = orient(r, s, q);
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;  // a proper crossing
  return (d1 == 0 && onSegment(p, q, r)) || (d2 == 0 && onSegment(p, q, s)) ||
         (d3 == 0 && onSegment(r, s, p)) || (d4 == 0 && onSegment(r, s, q));
}

// p lies in the closed triangle abc (not degenerate): on no strict side of two edges at once.
bool inTriangle(const P2& p, const P2& a, const P2& b, const P2& c) {
  const int o1 = orient(a, b, p), o2 = orient(b, c, p), o3 = orient(c, a, p);
  return !((o1 > 0 || o2 > 0 || o3 > 0) && (o1 < 0 || o2 < 0 || o3 < 0));
}

bool coplanarSegmentMeetsTriangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                                  const Vec3& c) {
  const int drop = projectionAxis(a, b, c);
  if (drop < 0) return false;  // degenerate: excluded by the callers
  const P2 p2 = project(p, drop), q2 = project(q, drop);
  const P2 a2 = project(a, drop), b2 = project(b, drop), c2 = project(c, drop);
  return inTriangle(p2, a2, b2, c2) || inTriangle(q2, a2, b2, c2) || segmentsMeet(p2, q2, a2, b2) ||
         segmentsMeet(p2, q2, b2, c2) || segmentsMeet(p2, q2, c2, a2);
}

bool sameStrictSign(int s1, int s2, int s3) {
  return (s1 > 0 && s2 > 0 && s3 > 0) || (s1 < 0 && s2 < 0 && s3 < 0);
}

}  // namespace

bool isDegenerate(const Vec3& a, const Vec3& b, const Vec3& c) {
  return projectionAxis(a, b, c) < 0;
}

bool segmentMeetsTriangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                          const Vec3& c) {
  const int sp = orient3d(a, b, c, p), sq = orient3d(a, b, c, q);
  if (sp * sq > 0) return false;  // both ends strictly on one side of the plane
  if (sp == 0 && sq == 0) return coplanarSegmentMeetsTriangle(p, q, a, b, c);
  // The segment meets the plane in one point; the line pq passes through the closed triangle
  // when it turns the same way (or not at all) about each edge: no two strict signs differ.
  const int t1 = orient3d(p, q, a, b), t2 = orient3d(p, q, b, c), t3 = orient3d(p, q, c, a);
  return !((t1 > 0 || t2 > 0 || t3 > 0) && (t1 < 0 || t2 < 0 || t3 < 0));
}

bool trianglesMeet(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e,
                   const Vec3& f) {
  // Early outs: one triangle strictly on one side of the other's plane.
  if (sameStrictSign(orient3d(a, b, c, d), orient3d(a, b, c, e), orient3d(a, b, c, f)))
    return false;
  if (sameStrictSign(orient3d(d, e, f, a), orient3d(d, e, f, b), orient3d(d, e, f, c)))
    return false;
  return segmentMeetsTriangle(a, b, d, e, f) || segmentMeetsTriangle(b, c, d, e, f) ||
         segmentMeetsTriangle(c, a, d, e, f) || segmentMeetsTriangle(d, e, a, b, c) ||
         segmentMeetsTriangle(e, f, a, b, c) || segmentMeetsTriangle(f, d, a, b, c);
}

}  // namespace chute::mesh
