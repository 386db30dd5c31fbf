#pragma once
// Writes a case file that runs a generated parachute mesh: materials (placeholder nylon values in
// ft, slug, s, lbf), every group mapped to its role, the confluence held, gravity, an optional
// canopy pressure ramp, a short dynamic run with a few probes. A starting point to edit.
#include <string>

#include "ParachuteGenerator.hpp"

namespace chute::mesh {

struct ParachuteCaseOptions {
  std::string commandLine;  // recorded in the file's header
  double pressure = 0.0;    // canopy pressure (0: none), ramped over rampTime
  double rampTime = 0.05;
  double dt = 1e-3, tEnd = 0.02;
};

// msh is referenced relative to the case file's folder. Throws std::runtime_error if the case
// file cannot be written.
void writeParachuteCase(const ParachuteSpec& spec, const GeneratedParachute& generated,
                        const std::string& caseFile, const std::string& msh,
                        const ParachuteCaseOptions& options);

}  // namespace chute::mesh
