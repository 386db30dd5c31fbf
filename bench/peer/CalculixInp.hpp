#pragma once
// Writes the peer problem as a CalculiX (ccx 2.20) input deck: the same nodes (numbered from 1 in
// chute's order), M3D3 membranes with *MEMBRANE SECTION, T3D2 trusses with *SOLID SECTION, the
// same materials (*ELASTIC is St Venant-Kirchhoff under NLGEOM, as chute's kernels), the fixed
// confluence, the follower pressure *DLOAD ramped by an *AMPLITUDE, and one NLGEOM *DYNAMIC, DIRECT
// step of fixed increments dt (HHT with the given alpha) printing the probe displacements.
#include <ostream>

#include "PeerProblem.hpp"

namespace chute::bench {

struct CalculixOptions {
  double alpha = 0.0;  // HHT alpha in [-1/3, 0]; 0 is Newmark's trapezoidal rule
  // Newton tolerances (*CONTROLS, PARAMETERS=FIELD): ccx's defaults are R = 0.005 on the residual
  // and C = 0.01 on the correction, relative; <= 0 keeps them.
  double residualTolerance = 0.0, correctionTolerance = 0.0;
};

// The pressure face label of an M3D3 element whose load acts along its node-order normal.
inline constexpr const char* kCalculixPressureFace = "P1";

void writeCalculixInp(std::ostream& os, const PeerProblem& problem, const PeerParams& params,
                      const CalculixOptions& options);

}  // namespace chute::bench
