#pragma once
// Exact signs of the 2-D and 3-D orientation determinants of points with double coordinates, for
// the intersection check (IntersectionCheck.hpp), which must decide touching and coplanar cases
// exactly rather than by a tolerance.
//
// Each predicate first evaluates the determinant in double precision with a forward error bound
// (a multiple of the machine epsilon times the permanent, the same expression with absolute
// values): when |det| exceeds the bound its sign is certain. Otherwise the determinant is
// recomputed exactly as a floating-point expansion (a sum of non-overlapping doubles, built with
// Knuth's two-sum and the fused multiply-add two-product; Shewchuk, "Adaptive precision
// floating-point arithmetic and fast robust geometric predicates", Discrete Comput. Geom. 18,
// 1997), whose sign is that of its largest component.
//
// Assumption: no product underflows (coordinates and their nonzero differences larger than about
// 1e-100 in magnitude, and no coordinate beyond 1e100): then the answers are exact. Parachute
// meshes are many orders of magnitude inside this range.
#include "model/Model.hpp"

namespace chute::mesh {

// Sign (+1, 0, -1) of det [b - a, c - a] for 2-D points: +1 when a, b, c turn counter-clockwise.
int orient2d(double ax, double ay, double bx, double by, double cx, double cy);

// Sign (+1, 0, -1) of det [a - d; b - d; c - d]: 0 when the four points are coplanar; +1 when d
// lies below the plane of a, b, c oriented counter-clockwise seen from above (Shewchuk's sign).
int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// How many calls fell back to exact arithmetic since the program started (this thread), for the
// tests and the cost figures.
long exactFallbacks();

}  // namespace chute::mesh
