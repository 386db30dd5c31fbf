#pragma once
// What a run writes while it goes: probe rows (probes.csv), VTU frames (the .pvd series), on
// their clocks (every N steps or at multiples of an interval, where the stepping stops), and the
// energy figures of the rows. On a restart the output is first cut back to what it held when
// the checkpoint was taken (OutputMark), whatever was written after it, so a restarted run's
// output is the uninterrupted run's. Rows go to disk and are not kept (unless asked: tests),
// the comparison with the case's reference is made row by row, and the output of a run that stops
// unstable is cut back to its last good state (lastGoodRow).
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "FlightFigures.hpp"
#include "Probes.hpp"
#include "VtuSeries.hpp"
#include "app/CheckpointFile.hpp"
#include "app/ReferenceTracker.hpp"
#include "app/RunCase.hpp"
#include "solver/EnergyMonitor.hpp"

namespace chute {

// When output is due: every N steps, or at multiples of an interval (the stepping stops there).
struct OutputClock {
  bool on = true;
  int every = 1;
  double interval = 0.0;
  long index = 1;
  double nextTime() const {
    return on && interval > 0 ? static_cast<double>(index) * interval
                              : std::numeric_limits<double>::infinity();
  }
  bool due(double t, long steps, double dt);
};

class RunOutput {
 public:
  // outDir empty: nothing is written (rows are then kept in r). resume: cut the output in outDir
  // back to this mark and go on from it (throws, before changing anything, if the output there
  // is not the checkpointed run's; a refused restart leaves outDir as it was). keepRows: also
  // keep every row in r.times / r.rows (tests). Throws if another run is writing into outDir.
  RunOutput(const CaseSpec& spec, StructuralSystem& sys, const std::string& outDir,
            const OutputMark* resume, RunResult& r, bool keepRows = false);
  ~RunOutput();

  // Where the equations of the step that ended in a state hold (the integrator's
  // equilibrium(), solver/EquilibriumPoint.hpp): forces and energies are written there. Unset:
  // the state itself.
  void setEquilibrium(std::function<EquilibriumPoint(const StructuralState&)> f) {
    equilibrium_ = std::move(f);
  }
  // The energy balance whose figures the energy_balance probes write (none: NaN), and which
  // tells a good row from a suspect one (lastGoodRow).
  void setEnergyMonitor(const EnergyMonitor* m) { monitor_ = m; }

  // The next output time after t (infinity: none), where the stepping must stop.
  double nextStop() const { return std::min(probeClock_.nextTime(), vtuClock_.nextTime()); }
  // After an accepted step: rows and frames that are due (and both at the last step).
  void afterStep(const StructuralState& s, long steps, bool last);
  // Whether afterStep at (t, steps) writes a probe row (the last step always does).
  bool recordsAt(double t, long steps) const;
  // The state a run starts from, and the last good state of a run that stops early.
  void record(const StructuralState& s);
  void frame(const StructuralState& s);
  void lastGoodState(const StructuralState& s);
  // The output of a run whose last states are not to be trusted (the energy balance out of its
  // bound, an explicit step that blew up) cut back to the last row written while the balance
  // held: rows and frames after it are removed. Returns that row's time.
  double cutBackToLastGoodRow();
  // The output as it stands is that of a good state (a run's start, after its first row and
  // frame): afterStep marks the rows written while the balance holds itself.
  void markLastGood() { lastGood_ = position(); }

  OutputMark mark() const;
  void flush();  // every frame given so far is on disk
  int vtuFrames() const { return vtu_ ? vtu_->frames() : 0; }
  long probeRows() const { return rows_; }
  double backgroundSeconds() const { return vtu_ ? vtu_->backgroundSeconds() : 0.0; }
  const ProbeSet& probes() const { return probes_; }
  // The comparison with the case's reference over the rows written (nullopt: no reference).
  std::optional<ReferenceError> reference() const {
    return reference_ ? std::optional<ReferenceError>(reference_->result()) : std::nullopt;
  }
  // The series the flight figures are made from (FlightFigures.hpp), collected as the rows are
  // written; nullptr when the case has no canopy probe with a force probe.
  const FlightSeries* flightSeries() const { return flight_ ? &flight_->series() : nullptr; }
  // What is whole on disk, for the message of a failed write: "probes.csv is whole up to t = X
  // (N rows); the .pvd lists M whole frames, up to t = Y".
  std::string wholeSoFar() const;

 private:
  void addRow(double t, std::vector<double> values);
  // Everything the output can be cut back to.
  struct Position {
    CsvWriter::Mark csv;
    long rows = 0;
    double lastRowTime = std::numeric_limits<double>::quiet_NaN();
    int frames = 0;
    double vtuLast = -std::numeric_limits<double>::infinity();
    double energyInitial = 0.0, energyMaxDrift = 0.0, kineticMax = 0.0;
    std::optional<ReferenceTracker> reference;
  };
  Position position() const;

  const CaseSpec* spec_;
  StructuralSystem* sys_;
  RunResult* r_;
  std::string dir_;
  int lockFd_ = -1;  // held while the run writes outDir: a second run there is refused
  bool keepRows_;
  long rows_ = 0;
  double lastRowTime_ = std::numeric_limits<double>::quiet_NaN();
  ProbeSet probes_;
  std::optional<ReferenceTracker> reference_;
  // The flight figures' columns of every row written, not whole rows: rows are not kept (a case
  // with a canopy probe keeping them all would hold every column of every probe, however many,
  // for a whole run), and the figures need seven numbers a row.
  std::optional<FlightSeriesCollector> flight_;
  std::unique_ptr<CsvWriter> csv_;
  std::unique_ptr<VtuSeries> vtu_;
  FrameFields fields_;
  bool inertia_;
  double vtuLast_ = -std::numeric_limits<double>::infinity();
  OutputClock probeClock_, vtuClock_;
  std::optional<Position> lastGood_;  // after the last row written while the balance held
  bool rowWrittenThisStep_ = false;
  std::function<EquilibriumPoint(const StructuralState&)> equilibrium_;
  const EnergyMonitor* monitor_ = nullptr;
  EquilibriumPoint equilibriumOf(const StructuralState& s) const {
    return equilibrium_ ? equilibrium_(s) : EquilibriumPoint{s.x, s.v, s.a, s.t};
  }
};

}  // namespace chute
