#pragma once
// Material and flight data of a generated parachute case (ParachuteCaseWriter.hpp), with their
// sources, in one unit system: "ft" (ft, slug, s, lbf: the paper's) or "si" (m, kg, s, N). The
// values are stated once in ft units and converted, so both systems describe the same parachute.
//
// Sources (docs/meshing.md, "Materials of a generated case"):
// - canopy fabric: MIL-C-7020 ripstop nylon, 1.1 oz/yd^2 (37.3 g/m^2), the C-9's cloth;
//   E t = 144 lbf/in (E = 4.32e6 psf on t = 4e-4 ft: Zhou, Accorsi & Leonard 2004, the half-scale
//   C-9), close to the cloth's 42 lbf/in strength over its ~30 % elongation at break.
// - suspension line: MIL-C-5040 type II nylon cord, 400 lb breaking strength; E A = 1300 lbf
//   (400 lb near 30 % elongation); 0.0058 lb/ft (section 3e-4 ft^2 at 0.6 slug/ft^3, the C-9
//   cases' cord, docs/applications/c9.md); drag diameter 0.03 ft, the paper's.
// - air: sea level, 1976 US standard atmosphere, 0.0023769 slug/ft^3 (1.225 kg/m^3); g standard.
#include <string>

namespace chute::mesh {

struct ParachuteMaterials {
  std::string units;       // "ft" or "si"
  std::string unitsLabel;  // the case file's `units`
  double fabricE = 0.0, fabricNu = 0.3, fabricThickness = 0.0, fabricDensity = 0.0;
  double cordE = 0.0, cordArea = 0.0, cordDensity = 0.0, cordDragDiameter = 0.0;
  double frameE = 0.0, frameArea = 0.0;  // payload box: stiff massless trusses
  double airDensity = 0.0, gravity = 0.0;
  double defaultPressure = 0.0;  // the half-scale C-9's 0.1 psf (4.79 Pa)
  double defaultSpeed = 0.0;     // at line stretch: 20 m/s
  // The cloth's air permeability: the velocity through it at the test pressure difference.
  double clothPermeability = 0.0, permeabilityTestPressure = 0.0;
  double length = 1.0;  // one ft in these units (for printing sizes)
};

// Throws std::invalid_argument("--units: ...") for anything but "ft" or "si". permeabilityCfm:
// the cloth's air permeability in ft^3/ft^2/min at 0.5 in of water (MIL-C-7020 type I: 80-120).
ParachuteMaterials parachuteMaterials(const std::string& units, double permeabilityCfm = 100.0);

}  // namespace chute::mesh
