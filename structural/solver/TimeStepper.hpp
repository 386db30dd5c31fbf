#pragma once
// The one loop that advances a structure in time, for `chute run` (and its restart), `chute
// couple` and the coupling interface alike, whatever the integrator (solver/TimeIntegrator.hpp):
// it lands steps on stops (the caller's output times, the model's cut events, the target time),
// takes the acceleration after a cut, counts the steps and calls the caller after each. How a
// step is chosen, retried or refused is the integrator's.
#include <functional>
#include <string>

#include "solver/StructuralState.hpp"
#include "solver/TimeIntegrator.hpp"

namespace chute {

class TimeStepper {
 public:
  // dtNominal: the case's dt (the tolerance of "reached").
  TimeStepper(StructuralSystem& sys, TimeIntegrator& integrator, double dtNominal);

  // The state a run starts from: the model's positions and prescribed velocities, the
  // integrator's acceleration (after a cut at the start time, without the cut set), committed.
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
    BelowMinimum  // a step failed and cannot be retried: s is the last good state
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
  bool reached(double t, double tEnd) const { return t >= tEnd - 1e-12 * dtNominal_; }

  StepCounters& counters() { return counters_; }
  const StepCounters& counters() const { return counters_; }
  TimeIntegrator& integrator() { return *integrator_; }
  const TimeIntegrator& integrator() const { return *integrator_; }

 private:
  // A set cut at t (LineSet::cutAt) loads the step that ends at t; the acceleration just after
  // it is that of the structure without it (M a = f_ext - f_int there), as at a start.
  void accelerationAfterCut(StructuralState& s);

  StructuralSystem* sys_;
  TimeIntegrator* integrator_;
  double dtNominal_;
  StepCounters counters_;
};

}  // namespace chute
