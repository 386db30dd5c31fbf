#pragma once
// A run's checkpoint on disk, so that `chute run --restart FILE` continues it bit for bit: the
// system snapshot (state, step control, every term's history: StructuralSystem::saveState),
// the step counters, and what the output had written when it was taken. CBOR keeps every double
// exact. Format 2 carries a checksum over its payload; every field is validated on reading, and
// the snapshot again by StructuralSystem::loadState, before anything of a run is touched.
// Written atomically (a temporary file renamed over the old one, never written through a link).
#include <cstdint>
#include <map>
#include <string>

#include "model/Model.hpp"
#include "solver/StructuralState.hpp"
#include "solver/TimeStepper.hpp"

namespace chute {

// What a run's output had written when the checkpoint was taken (app/RunOutput.hpp).
struct OutputMark {
  long probeRows = 0, vtuFrames = 0;
  long probeClockIndex = 1, vtuClockIndex = 1;
  double vtuLast = 0.0;
  double energyInitial = 0.0, energyMaxDrift = 0.0, kineticMax = 0.0;
};

struct Checkpoint {
  std::string caseName;
  std::uint64_t modelHash = 0;  // of the model's nodes, elements and constraints
  // Every key of the case the run was started with, as text (CaseSpec::settings): a restart
  // must give the same, but for the keys docs/cli.md allows to change (solver.t_end): another
  // dt, load or output interval would not continue the run, so it is refused, not ignored.
  std::map<std::string, std::string> settings;
  TimeStepper::Saved stepping;  // the system snapshot, the counters, the linear solver's kind
  OutputMark output;
};

std::uint64_t modelHash(const Model& m);

// Throws OutputError naming the file on any failure (a full disk, the directory removed).
void writeCheckpoint(const std::string& path, const Checkpoint& c);
// Throws std::runtime_error naming the file and the field for anything that is not a whole,
// unaltered checkpoint of this format with values in range.
Checkpoint readCheckpoint(const std::string& path);

}  // namespace chute
