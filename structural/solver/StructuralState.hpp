#pragma once
// The state of a structure between two steps: positions, velocities and accelerations of all
// dofs, the time, and the step control that chooses the next step's length. With the terms'
// histories (StructuralSystem::saveState) it is everything a run needs to go on bit for bit.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "model/History.hpp"

namespace chute {

// What the step-size control carries from step to step (StepController).
struct StepControl {
  double dt = 0.0;         // the length the next step is tried with
  double eventStep = 0.0;  // > 0: the next step ends at an event found inside the last try
  int successesSinceCut = 0;
};

struct StructuralState {
  Eigen::VectorXd x, v, a;  // positions, velocities, accelerations of all dofs
  double t = 0.0;
  StepControl control;
};

// A structure's state with the history of each of its terms, in the system's term order: the
// one snapshot that checkpoints, coupling windows and step rejection use.
struct SystemSnapshot {
  StructuralState state;
  std::vector<std::string> termNames;
  std::vector<History> histories;
};

}  // namespace chute
