#pragma once
// The one loop that advances a structure in time, for `chute run` (and its restart), `chute
// couple` and the coupling interface alike: it owns the step control, lands steps on stops (the
// caller's output times, the model's cut events, the target time), retries a step that passes an
// event so it ends there, takes the acceleration after a cut, and on a failed try restores the
// state the step started from (StructuralSystem::saveState / loadState) and halves the step.
#include <functional>
#include <string>

#include "solver/GeneralizedAlpha.hpp"
#include "solver/StepController.hpp"
#include "solver/StructuralState.hpp"

namespace chute {

// Counters of the steps taken so far (summary.json; saved with checkpoints).
struct StepCounters {
  long steps = 0, rejectedSteps = 0, eventRetries = 0, newtonIterations = 0;
  int maxNewtonInStep = 0;
  double newtonPerStep() const {
    return steps > 0 ? static_cast<double>(newtonIterations) / static_cast<double>(steps) : 0.0;
  }
};

class CentralDifference;

class TimeStepper {
 public:
  TimeStepper(StructuralSystem& sys, GeneralizedAlpha& integrator, double dtNominal, double dtMin);
  // Steps with explicit central differences instead (solver/CentralDifference.hpp): each step is
  // the stable step at the step's start (at most dtNominal), cut to land on stops; the initial
  // acceleration and that after a cut are the lumped-mass ones; an unstable (non-finite) step
  // ends the run as BelowMinimum rather than being halved. GeneralizedAlpha still gives the
  // initial state.
  void useExplicit(CentralDifference& cd) { explicit_ = &cd; }

  // The state a run starts from: the model's positions and prescribed velocities, the
  // consistent acceleration (after a cut at the start time, without the cut set), committed.
  StructuralState start();

  // What a checkpoint holds of the stepping, and going on from it bit for bit: the snapshot
  // (StructuralSystem::saveState), the counters, and whether the linear solver had fallen back
  // from Cholesky to LU. resume() throws HistoryError (nothing changed) for a bad snapshot.
  struct Saved {
    SystemSnapshot snapshot;
    StepCounters counters;
    bool linearSolverLU = false;
  };
  Saved save(const StructuralState& s) const;
  StructuralState resume(const Saved& saved);

  enum class Outcome {
    Reached,      // s.t is tStop
    Stopped,      // afterStep asked to stop (a signal)
    BelowMinimum  // a step failed with dt at its minimum: s is the last good state
  };
  struct Result {
    Outcome outcome = Outcome::Reached;
    std::string reason;  // for BelowMinimum
  };
  // Advances s to tStop. nextStop(t): the caller's next stop after t (infinity: none).
  // afterStep(s, newtonIterations) after each accepted step; returning false stops the run there.
  Result advanceTo(StructuralState& s, double tStop, const std::function<double(double)>& nextStop,
                   const std::function<bool(const StructuralState&, int)>& afterStep);

  // Whether t is the end time tEnd within the loop's tolerance.
  bool reached(double t, double tEnd) const { return t >= tEnd - 1e-12 * control_.nominal(); }

  StepCounters& counters() { return counters_; }
  const StepCounters& counters() const { return counters_; }
  GeneralizedAlpha& integrator() { return *integrator_; }

 private:
  // A set cut at t (LineSet::cutAt) loads the step that ends at t; the acceleration just after
  // it is that of the structure without it (M a = f_ext - f_int there), as at a start.
  void accelerationAfterCut(StructuralState& s);

  StructuralSystem* sys_;
  GeneralizedAlpha* integrator_;
  CentralDifference* explicit_ = nullptr;
  StepController control_;
  StepCounters counters_;
};

}  // namespace chute
