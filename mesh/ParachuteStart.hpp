#pragma once
// Start configurations of a generated parachute (named groups of ParachuteGenerator.hpp) whose
// reference stays the flat pattern, built so that every element starts at or below its reference
// size: the internal force is zero at t = 0 (cables slack or exact, membranes slack under
// wrinkling, each sliding element's l1 + l2 <= L with its slider on it).
//
// flat:   the canopy as cut; the slider (if any) sliderDrop below the skirt, each line bent
//         through its grommet and the confluence raised until the longest line is lineSlack short.
// folded: the canopy packed into a narrow cone about the axis, vent up: a point at radius rho and
//         angle theta of the pattern goes to (eps rho cos theta, eps rho sin theta,
//         H + c (R - rho)), eps = bundleRadius / R, c < sqrt(1 - eps^2) (lowered until no element
//         stretches); slider and lines as for flat.
// inflated: the canopy on a spherical cap, an approximation of the inflated shape: pattern radius
//         rho -> arc length c rho from the apex along the meridian of a sphere of radius Rs with
//         Rs sin(R / Rs) = inflatedRatio R (the skirt at the projected radius, height H); c = 1
//         (lowered until no element stretches): meridians exact, hoops shorter (wrinkled);
//         lines straight (slackened by lineSlack); the whole start moved rigidly so that the
//         confluence stays at its reference point, the origin.
// packed: the canopy pleated along its gores and S-folded into a bag above the skirt
//         (PackedStart.hpp), runs compressed by c (lowered from 0.98 until no element stretches);
//         slider and lines as for flat (the lines straight below the bag: line stretch).
#include "GmshMesh.hpp"
#include "ParachuteGenerator.hpp"

namespace chute::mesh {

struct StartConfiguration {
  NodeVectors displacement;  // node tag -> start minus reference
  double maxStretch = 0.0;   // largest principal stretch of a canopy triangle (<= 1)
  double axialFactor = 1.0;  // c of the folded / inflated / packed map
};

StartConfiguration parachuteStart(const ParachuteSpec& spec, const GmshMesh& mesh);

}  // namespace chute::mesh
