#include "ParachuteMaterials.hpp"

#include <stdexcept>

namespace chute::mesh {

ParachuteMaterials parachuteMaterials(const std::string& units, double permeabilityCfm) {
  // Exact conversion factors (NIST SP 811): 1 ft = 0.3048 m, 1 lbf = 4.4482216152605 N,
  // 1 slug = 1 lbf s^2 / ft.
  constexpr double ft = 0.3048, lbf = 4.4482216152605, slug = lbf / ft;
  constexpr double oz = 0.028349523125, yd = 0.9144;  // kg, m
  // 1.1 oz/yd^2 in slug/ft^2.
  constexpr double fabricAreal = 1.1 * oz / (yd * yd) / slug * (ft * ft);
  ParachuteMaterials m;
  m.units = units;
  m.fabricE = 4.32e6;  // psf
  m.fabricThickness = 4.0e-4;
  m.fabricDensity = fabricAreal / m.fabricThickness;
  m.cordE = 4.32e6;
  m.cordArea = 3.0e-4;
  m.cordDensity = 0.6;
  m.cordDragDiameter = 0.03;
  m.frameE = 1.0e9;
  m.frameArea = 1.0e-3;
  m.airDensity = 0.0023769;
  m.gravity = 9.80665 / ft;
  m.defaultPressure = 0.1;
  m.defaultSpeed = 20.0 / ft;
  // ft^3/ft^2/min is ft/min; 0.5 in of water (1 inH2O = 249.0889 Pa, NIST SP 811) in psf.
  m.clothPermeability = permeabilityCfm / 60.0;
  m.permeabilityTestPressure = 0.5 * 249.0889 / (lbf / (ft * ft));
  if (units == "ft") {
    m.unitsLabel = "ft, slug, s, lbf";
    return m;
  }
  if (units != "si") throw std::invalid_argument("--units: expected ft or si");
  const double pressure = lbf / (ft * ft), density = slug / (ft * ft * ft);
  m.unitsLabel = "m, kg, s, N";
  m.length = ft;
  m.fabricE *= pressure;
  m.fabricThickness *= ft;
  m.fabricDensity *= density;
  m.cordE *= pressure;
  m.cordArea *= ft * ft;
  m.cordDensity *= density;
  m.cordDragDiameter *= ft;
  m.frameE *= pressure;
  m.frameArea *= ft * ft;
  m.airDensity = 1.225;  // the standard atmosphere's sea-level value (0.0023769 slug/ft^3)
  m.gravity = 9.80665;
  m.defaultPressure *= pressure;
  m.defaultSpeed = 20.0;
  m.clothPermeability *= ft;
  m.permeabilityTestPressure *= pressure;
  return m;
}

}  // namespace chute::mesh
