#pragma once
// The packed start of a generated parachute (ParachuteStart.hpp, start "packed"): the canopy as it
// leaves its deployment bag. Two steps of real packing (TM 10-1670-293-23&P, T-10C/D: "folding
// the gores", "longfolding the canopy", then S-folding it into the bag) become one map of the flat
// pattern, which stays the reference:
//  1. pleated along its gores: each cross-section at pattern radius rho (a hoop of the canopy)
//     becomes the same flattened star polygon, gore k the polygon's edge k, its seams alternately
//     at the outer and inner vertices (half-width V across the pack, half-thickness U through
//     it); so the gores lie in layers (pleats) stacked through the thickness;
//  2. S-folded along its length: the pleated strip runs up and down the bag in `runs` straight
//     runs side by side, `pitch` = 2 U + gap apart, joined by short crossings at the bag's ends;
//     each turn is two 90-degree creases on hoop lines of the mesh (the generator meshes the
//     gores with circles at foldRadii), each layer mitred at the crease (offset u at a crease goes
//     to u (n_in + n_out)), so no element straddles a crease.
// Stress-free: a hoop's polygon is no longer than the hoop (scaled down near the vent or apex
// where it would be), runs are compressed along their length by the factor c < 1 and crossings
// get more cloth than their outermost layer needs; the start's largest stretch is measured on the
// triangles (<= 1). Free of intersections: in a run every layer (u, v) is a straight line along
// the run, distinct layers disjoint; in a crossing the layer at u stays in the plane at distance u
// from the crease line; gores are disjoint cones of the star polygon (star-shaped about its
// centre), so non-adjacent triangles are disjoint (and layers at least `gap` apart away from the
// pleats' folds and the vent). The skirt is the mouth of the bag, in the plane of the reference
// skirt (z = H); the lines run straight from it to the confluence below (the instant of line
// stretch in a lines-first deployment).
#include <array>
#include <vector>

#include "ParachuteGenerator.hpp"

namespace chute::mesh {

struct PackLayout {
  double R = 0.0, H = 0.0, ventRadius = 0.0;  // the pattern: skirt radius, height, vent radius
  double length = 0.0, diameter = 0.0, gap = 0.0;
  int gores = 0, runs = 1;
  double pitch = 0.0, halfThickness = 0.0, halfWidth = 0.0;  // U, V
  double runCloth = 0.0, crossingCloth = 0.0;  // pattern length of a run and of a crossing
  double firstRunExtra = 0.0;                  // the first run starts lower: at the bag's mouth
  std::vector<double> foldRadii;               // pattern radii of the creases, descending
  std::vector<std::array<double, 2>> polygon;  // the star: (u, v) of seam k
  double maxEdge = 0.0;                        // longest polygon edge
  double minSeparation = 0.0;                  // least distance between non-adjacent polygon edges
  double hoopFactor = 0.95;  // polygon edge <= hoopFactor x the gore's width at that radius
};

// Throws std::invalid_argument naming the option (--pack-length, --pack-diameter, --pack-gap) when
// the canopy cannot be packed so.
PackLayout packLayout(const ParachuteSpec& spec);

// The packed position of the pattern point X; runs compressed by c (<= 1 for no stretch).
Vec3 packedPoint(const PackLayout& layout, const Vec3& X, double c);

}  // namespace chute::mesh
