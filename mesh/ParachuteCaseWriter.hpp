#pragma once
// Writes a case file that flies a generated parachute mesh for seconds unchanged: sourced
// materials (ParachuteMaterials.hpp, ft or SI), the frame of the falling payload (payload held,
// gravity 0, the free-stream wind whose dynamic pressure is the canopy pressure), the pressure
// ramped in, face drag on the canopy and line drag on every line and tape, the robust Bossak
// settings of the C-9 cases (docs/applications/c9.md), probes of skirt radius, slider, line
// forces and energy, a VTU series. Every setting carries a one-line reason in the file.
#include <limits>
#include <string>

#include "ParachuteGenerator.hpp"

namespace chute::mesh {

struct ParachuteCaseOptions {
  std::string commandLine;   // recorded in the file's header
  std::string units = "ft";  // "ft" (ft, slug, s, lbf) or "si" (m, kg, s, N)
  // Canopy pressure; NaN: the units' default (0.1 psf = 4.79 Pa, the half-scale C-9's); 0: none
  // (and no wind).
  double pressure = std::numeric_limits<double>::quiet_NaN();
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
