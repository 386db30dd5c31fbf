#pragma once
// Writes a case file that flies a generated parachute mesh unchanged: sourced materials
// (ParachuteMaterials.hpp, ft or SI) and, by default, free flight from line stretch (gravity,
// the payload free, everything moving down at the deployment speed, the standard atmosphere at
// an altitude, the canopy loaded by the airflow relative to it: docs/flight.md), or held in a
// steady wind (the wind tunnel), or the legacy frame of the falling payload with a constant
// canopy pressure (--pressure); line drag on every line and tape; explicit integration; probes
// of the opening force, the canopy's flow figures, line forces, skirt radius, slider and energy;
// a VTU series. Every setting carries a one-line reason in the file.
#include <limits>
#include <string>

#include "ParachuteGenerator.hpp"

namespace chute::mesh {

struct ParachuteCaseOptions {
  std::string commandLine;   // recorded in the file's header
  std::string units = "ft";  // "ft" (ft, slug, s, lbf) or "si" (m, kg, s, N)
  // Legacy: a constant canopy pressure (the frame of the falling payload); NaN: the airflow's
  // loads instead (docs/flight.md).
  double pressure = std::numeric_limits<double>::quiet_NaN();
  // The system's speed at line stretch (downward), or the wind's when held; NaN: 20 m/s.
  double speed = std::numeric_limits<double>::quiet_NaN();
  double altitude = 0.0;  // of the standard atmosphere, in the case's length unit
  bool held = false;      // the payload held in a steady wind (infinite mass)
  // The cloth's air permeability, ft^3/ft^2/min at 0.5 in of water (0: impermeable).
  double clothPermeability = 100.0;
  double rampTime = 0.1;
  double dt = 2e-3, tEnd = 2.0;
  double probeInterval = 0.01, vtuInterval = 0.05;  // vtuInterval 0: no series
};

// Throws std::invalid_argument naming the option (--pressure, --dt, ...) of a bad value.
void checkParachuteCaseOptions(const ParachuteCaseOptions& options);

// msh is referenced relative to the case file's folder. Throws std::invalid_argument for bad
// options (naming them) and std::runtime_error if the case file cannot be written.
void writeParachuteCase(const ParachuteSpec& spec, const GeneratedParachute& generated,
                        const std::string& caseFile, const std::string& msh,
                        const ParachuteCaseOptions& options);

}  // namespace chute::mesh
