#pragma once
// Exact intersection tests of closed segments and closed triangles in 3-D, decided by the signs of
// orientation determinants alone (ExactPredicates.hpp), so touching and coplanar configurations
// are classified exactly, without a tolerance:
//  - a segment meets a triangle when they share at least one point: crossing, touching at a
//    vertex or an edge, or lying in its plane and overlapping it (checked in the coordinate plane
//    onto which the triangle projects without degenerating; dropping a coordinate is exact);
//  - two triangles meet when an edge of one meets the other (for crossing, touching and coplanar
//    overlapping or nested triangles alike: the boundary of their intersection lies on an edge).
// A degenerate triangle (collinear or coincident vertices, so no plane) is reported by
// isDegenerate and must not be passed to the tests: it has no area to cross.
#include "model/Model.hpp"

namespace chute::mesh {

bool isDegenerate(const Vec3& a, const Vec3& b, const Vec3& c);

// Does the closed segment pq meet the closed triangle abc (not degenerate)?
bool segmentMeetsTriangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                          const Vec3& c);

// Do the closed triangles abc and def (neither degenerate) share a point?
bool trianglesMeet(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e,
                   const Vec3& f);

}  // namespace chute::mesh
