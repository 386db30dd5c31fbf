#pragma once
// Runs a case: time stepping with step rejection, probes, the comparison with the case's
// reference, summary.json. Used by `chute run` and by the case tests.
#include <array>
#include <limits>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "FlightFigures.hpp"
#include "app/ReferenceTracker.hpp"
#include "assembly/WorkCounters.hpp"
#include "case/CaseSpec.hpp"
#include "solver/Timings.hpp"

namespace chute {

struct RunOptions {
  std::string outDir;     // empty: write nothing (the rows are then kept in RunResult)
  bool progress = false;  // a status line on a terminal, progress lines in a log (app/Progress)
  // Keep every probe row in RunResult::times / rows as well as on disk (tests): a run writing to
  // outDir otherwise holds none of them, whatever its length.
  bool keepRows = false;
  bool verboseNewton = false;
  long checkpointEvery = 0;    // steps between checkpoints (outDir/checkpoint.cbor); 0: none
  std::string restartFile;     // continue from this checkpoint
  bool handleSignals = false;  // SIGINT / SIGTERM: checkpoint, stop, leave valid output

  static RunOptions writingTo(std::string dir) {
    RunOptions o;
    o.outDir = std::move(dir);
    return o;
  }
};

// What an explicit run (solver.integrator = "central_difference") reports in summary.json.
struct ExplicitRunInfo {
  double leastStep = 0.0, largestStep = 0.0;
  std::string limitingNode;                               // the node that limited the least step
  std::vector<std::pair<double, double>> stepHistory;     // (t, stable step), on 5 % changes
  std::vector<std::pair<std::string, double>> addedMass;  // mass scaling, per part
  double totalAddedMass = 0.0;
  double targetStep = 0.0;  // mass scaling's, as given or from mass_scaling_quantile
  int scaledNodes = 0;      // nodes mass scaling gave mass to
  std::vector<std::pair<std::string, double>> partMass;  // of the scaled parts, without it
  std::array<double, 4> nodalSteps{};  // least, 1 %, 10 %, 50 % of the nodes' own stable steps
};

// How a run ended (summary.json "status"; docs/exit-codes.md).
enum class RunStatus {
  Completed,    // reached t_end (or the static load)
  Diverged,     // a step failed and could not be retried: the last good state is written
  Unstable,     // the energy balance grew past its tolerance: the last good state is written
  Interrupted,  // a signal: a checkpoint and valid output are written
};
std::string_view runStatusName(RunStatus s);
std::ostream& operator<<(std::ostream& out, RunStatus s);  // its name (test messages)

// What a run with fabric contact ([contact]) reports in summary.json (docs/contact.md CT13).
struct ContactRunInfo {
  double thickness = 0.0;
  long builds = 0, treeBuilds = 0, candidates = 0, largestActive = 0;
  double closest = 1.0, largestApproachPerStep = 0.0, largestApproachEnergy = 0.0;
};

struct RunResult {
  RunStatus status = RunStatus::Completed;
  std::string reason;
  long steps = 0, rejectedSteps = 0, eventRetries = 0, newtonIterations = 0;
  int maxNewtonInStep = 0;
  double finalTime = 0.0, wallTime = 0.0, referenceTime = 0.0;
  Timings timings;
  WorkCounters work;  // kernel evaluations per kind of term, searches, output
  std::string linearSolver;
  int equations = 0;
  long nonZeros = 0, symbolicAnalyses = 0;
  long concurrentAssemblies = 0, serialAssemblies = 0;  // two-part assembly (docs/performance.md)
  std::vector<long> handovers;                          // per sliding group
  int vtuFrames = 0;
  long checkpoints = 0;
  double energyInitial = 0.0, energyMaxDrift = 0.0, kineticMax = 0.0;
  // The energy balance (solver/EnergyMonitor.hpp) of a dynamic run: its largest value, its
  // scale, and the work of loads and supports (NaN for statics).
  double balanceMax = std::numeric_limits<double>::quiet_NaN(),
         balanceScale = std::numeric_limits<double>::quiet_NaN(),
         externalWork = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::string> columns;
  long probeRows = 0;  // rows written (probes.csv)
  // The rows themselves, only when RunOptions::keepRows or nothing is written.
  std::vector<double> times;
  std::vector<std::vector<double>> rows;
  std::optional<ReferenceError> reference;
  std::optional<ExplicitRunInfo> explicitRun;
  std::optional<FlightFigures> flight;  // a canopy with a force probe (docs/flight.md)
  std::optional<ContactRunInfo> contact;
  // An output interval shorter than solver.dt caps every implicit step (steps land on output
  // times): the cap (NaN: none) and a note saying so, on stderr and in summary.json.
  double outputStepCap = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::string> notes;
  double newtonPerStep() const { return steps ? double(newtonIterations) / steps : 0.0; }
};

RunResult runCase(const CaseSpec& spec, const RunOptions& options);

// Writes summary.json for a run.
void writeSummary(const std::string& path, const CaseSpec& spec, const RunResult& r);

}  // namespace chute
