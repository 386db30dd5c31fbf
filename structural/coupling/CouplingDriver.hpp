#pragma once
// A small coupling driver: the structure (CouplingInterface) and a flow participant exchange
// data once per time window (explicit, staggered) or until the window's interface pressure
// converges (implicit, sub-iterated, with a checkpoint per window), with constant or Aitken
// under-relaxation of the pressure vector. It plays the part of preCICE's coupling scheme
// (serial-explicit / serial-implicit, constant / aitken acceleration).
#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "coupling/CouplingInterface.hpp"
#include "coupling/QuasiSteadyFlow.hpp"

namespace chute::coupling {

enum class CouplingScheme { Explicit, Implicit };
enum class Relaxation { Constant, Aitken };

struct CouplingSettings {
  CouplingScheme scheme = CouplingScheme::Implicit;
  Relaxation relaxation = Relaxation::Aitken;
  double omega = 0.5;       // constant relaxation factor; Aitken's initial one in every window
  double tolerance = 1e-8;  // relative residual |p~ - p| / |p~| that ends a window
  int maxIterations = 100;  // per window; more is a failure
  double window = 0.0;      // time-window size (0: the case's solver.dt)
  double tEnd = 0.0;        // 0: the case's t_end
};

struct WindowReport {
  double t = 0.0;              // end of the window
  int iterations = 0;          // structural solves of the window (1 for explicit)
  double residual = 0.0;       // final relative residual (explicit: the change over the window)
  std::vector<double> omegas;  // relaxation factors used
  bool accepted = true;        // the window converged: its state is final (output may use it)
};

struct CouplingReport {
  bool converged = true;  // every window converged within maxIterations
  std::string failure;
  std::vector<WindowReport> windows;
  long iterations() const;
  double iterationsPerWindow() const;
};

// The flow participant: face pressures for what the structure wrote at the end of a window.
using FlowParticipant = std::function<Eigen::VectorXd(const InterfaceData&)>;

// What the structure writes (CouplingInterface -> InterfaceData).
InterfaceData writeInterfaceData(const CouplingInterface& s);

// Runs the coupled problem from the structure's current time to settings.tEnd. onWindow, when
// set, is called after each accepted window.
CouplingReport runCoupled(CouplingInterface& structure, const FlowParticipant& flow,
                          const CouplingSettings& settings,
                          const std::function<void(const WindowReport&)>& onWindow = {});

}  // namespace chute::coupling
