#pragma once
// A cluster of two or three identical generated parachutes (ParachuteGenerator.hpp) on risers to
// one payload. Each parachute keeps its own lines, confluence and slider; its axis is tilted
// outwards by beta from the vertical so that the centres of neighbouring canopies, at the height
// of their skirts, are `spacing` apart (by default the projected diameter of an inflated canopy,
// 0.7 D: inflated canopies touch and push each other apart, as a real cluster's do). Canopy i
// (1-based) sits at azimuth 2 pi (i - 1) / n about the vertical through the payload, its
// confluence a riser length from the payload along its tilted axis.
//
// Groups: every group of the single parachute with the suffix _<i> (canopy_1, gore_3_2,
// line_0_1, confluence_2, grommet_1_3, ...), plus risers (1-D, all risers), riser_<i> (1-D) and
// payload (0-D, the common payload point at the origin). The start of each parachute is its own
// (folded, packed, ...) moved rigidly with it.
#include <string>

#include "ParachuteGenerator.hpp"

namespace chute::mesh {

struct ClusterSpec {
  ParachuteSpec parachute;   // one canopy: its payload options are not used
  int canopies = 3;          // 2 or 3
  double spacing = 0.0;      // centre to centre at the skirts (0: 0.7 D)
  double riserLength = 0.0;  // payload to each confluence (0: a third of the line length)
  int riserElements = 4;
  double payloadMass = 0.0;
  void validate() const;  // throws std::invalid_argument naming the option
};

struct GeneratedCluster {
  GmshMesh mesh;
  GeneratedParachute single;  // the parachute of which the cluster is made (its figures)
  double tilt = 0.0;          // beta, radians
  double spacing = 0.0, riserLength = 0.0;
};

GeneratedCluster generateCluster(const ClusterSpec& spec, const std::string& msh);

}  // namespace chute::mesh
