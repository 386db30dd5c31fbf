#pragma once
// The complete state of a dynamic run between two steps, so that `chute run --restart FILE`
// continues it bit for bit: positions, velocities, accelerations, the step-size control, the
// sliding groups' committed active elements, the output clocks and the run's counters. Written
// atomically (a temporary file renamed over the old one) in CBOR, which keeps every double exact.
#include <cstdint>
#include <string>
#include <vector>

#include "model/Model.hpp"
#include "solver/GeneralizedAlpha.hpp"

namespace chute {

struct Checkpoint {
  std::string caseName;
  std::uint64_t modelHash = 0;  // of the model's nodes, elements and constraints
  DynamicState state;
  // Step control.
  double dt = 0.0, eventStep = 0.0;
  int successesSinceCut = 0;
  bool linearSolverLU = false;  // Cholesky had fallen back to LU
  // Output clocks and what was written.
  long probeClockIndex = 1, vtuClockIndex = 1;
  double vtuLast = 0.0;
  // Sliding groups: committed active element per slider, and hand-overs so far.
  std::vector<std::vector<int>> active;
  std::vector<long> handovers;
  // Committed split of each slider's active element (docs/friction.md; used by sliders with
  // friction, derived from x for the others). Absent in older checkpoints: uniform splits.
  std::vector<std::vector<double>> splits;
  // Counters of the run so far.
  long steps = 0, rejectedSteps = 0, eventRetries = 0, newtonIterations = 0;
  int maxNewtonInStep = 0;
  double energyInitial = 0.0, energyMaxDrift = 0.0, kineticMax = 0.0;
};

std::uint64_t modelHash(const Model& m);

// Throws std::runtime_error naming the file on any failure.
void writeCheckpoint(const std::string& path, const Checkpoint& c);
Checkpoint readCheckpoint(const std::string& path);

}  // namespace chute
