#pragma once
// A flat circular canopy with its suspension lines, optional slider and payload, built with the
// gmsh API. Reference geometry (the stress-free state): the flat cutting pattern in the plane
// z = H at radius R = diameter / 2 about the z axis, the lines straight from the skirt to the
// confluence at the origin (H = sqrt(L^2 - R^2)), the slider a flat square centred on the axis.
// The start configuration (ParachuteStart.hpp) is written into the .msh as the NodeData view
// "initial_displacement"; a packed start also meshes the gores with hoop circles at its creases.
//
// Physical groups (0-, 1-, 2-D):
//   canopy, gore_<k> (2-D, k = 0..gores-1); radial_seams, skirt_band, vent_band (1-D, gore edges);
//   line_<j>, lines (1-D, j = 0..gores-1, from skirt point j to the confluence);
//   skirt_points, skirt_<j>, confluence, apex (0-D; apex only without a vent);
//   slider (2-D), slider_edges (1-D), grommet_<k>, grommets (0-D, k = 0..3);
//   risers (1-D), payload_box (1-D trusses), payload (0-D: the payload point or box corners).
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "GmshMesh.hpp"

namespace chute::mesh {

// The least size of any feature of a generated parachute (vent, canopy ring, slider, riser,
// box edge, bundle radius, slider drop, height of the canopy over the confluence), relative to
// the diameter, and the least positive payload mass (docs/limits.md).
inline constexpr double kLeastFeature = 1e-3;
inline constexpr double kLeastMass = 1e-6;

// The limits of the run a generated case goes to (0: no case is written, nothing checked).
struct CaseLimits {
  std::size_t maxNodes = 0, maxElements = 0, maxEquations = 0;
};

struct ParachuteSpec {
  int gores = 0;              // gores and suspension lines (>= 4)
  double diameter = 0.0;      // nominal (flat) diameter D
  double ventDiameter = 0.0;  // 0: no vent (gores meet at the apex)
  double lineLength = 0.0;    // skirt to confluence, > D / 2
  int lineElements = 8;
  double elementSize = 0.0;  // canopy mesh size
  int meshAlgorithm = 6;     // gmsh Mesh.Algorithm (6 Frontal-Delaunay, 5 Delaunay, 1 MeshAdapt)
  double maxElements = 2e6;  // limit on the estimated element count (docs/limits.md)
  double sliderSide = 0.0;   // 0: no slider; else a square of this side, a grommet at each corner
  int sliderDivisions = 1;   // quads along each slider edge
  double payloadMass = 0.0;  // 0: no payload
  std::array<double, 3> payloadBox{0.0, 0.0, 0.0};  // > 0: a box of trusses, mass at its corners
  double riserLength = 0.0;  // confluence to the payload point (box: to each top corner)
  int riserElements = 1;
  std::string start = "flat";  // start configuration: "flat", "folded", "inflated" or "packed"
  double inflatedRatio = 0.7;  // inflated: projected (skirt) diameter / D
  double bundleRadius = 0.0;   // folded: radius of the packed canopy at the skirt (0: D / 40)
  double sliderDrop = 0.0;     // slider below the skirt at the start (0: line length / 20)
  double lineSlack = 0.005;    // the longest line starts this fraction shorter than its length
  double packLength = 0.0;     // packed (PackedStart.hpp): bag length (0: D / 12)
  double packDiameter = 0.0;   // packed: bag diameter (0: D / 25)
  double packGap = 0.0;        // packed: least gap between layers (0: D / 8500, ~1 mm on a C-9)
  CaseLimits caseLimits;       // a case is written: the mesh must fit the run's default limits

  bool hasSlider() const { return sliderSide > 0.0; }
  bool hasBox() const { return payloadBox[0] > 0.0; }
  // Throws std::invalid_argument naming the offending option (--gores, --diameter, ...).
  void validate() const;
  void checkFinite() const;  // part of validate(): lengths and masses finite, at most 1e6
  void checkLimits() const;  // part of validate(): sizes within docs/limits.md
};

struct GeneratedParachute {
  GmshMesh mesh;  // reference geometry and groups (views: the start, unless flat and plain)
  double canopyArea = 0.0, flatArea = 0.0;  // meshed and analytic pi (R^2 - r^2)
  double maxLineLengthError = 0.0;          // max |meshed length - L| over the lines
  std::size_t triangles = 0;
  double meshSeconds = 0.0;      // gmsh geometry + 2-D meshing
  double maxStartStretch = 0.0;  // largest principal stretch of a canopy element at the start
  std::array<int, 4> linesPerGrommet{0, 0, 0, 0};
};

// Builds and meshes the parachute; writes `msh` (format 4.1) when not empty.
GeneratedParachute generateParachute(const ParachuteSpec& spec, const std::string& msh);

// Which grommet (0..3) line j of n runs through: the lines in four consecutive groups.
inline int grommetOfLine(int j, int n) {
  return 4 * j / n;
}

}  // namespace chute::mesh
