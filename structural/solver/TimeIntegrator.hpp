#pragma once
// One family of time integrators (docs/architecture.md): each scheme is a class that knows its
// own step, its step choice and its retries; the TimeStepper (solver/TimeStepper.hpp) holds one
// and drives it the same way whatever it is, for `chute run`, its restart, `chute couple` and
// the C API alike. The schemes know no kind of term: what they ask of the terms goes through
// StructuralSystem (assembly, mass, stable-step bounds, events).
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "solver/EquilibriumPoint.hpp"
#include "solver/IntegratorKind.hpp"
#include "solver/LinearSolver.hpp"
#include "solver/StructuralState.hpp"
#include "solver/StructuralSystem.hpp"

namespace chute {

// Counters of the steps taken so far (summary.json; saved with checkpoints).
struct StepCounters {
  long steps = 0, rejectedSteps = 0, eventRetries = 0, newtonIterations = 0;
  int maxNewtonInStep = 0;
  double newtonPerStep() const {
    return steps > 0 ? static_cast<double>(newtonIterations) / static_cast<double>(steps) : 0.0;
  }
};

// One step as an integrator took it: accepted, or the failure that ends the run.
struct StepResult {
  bool accepted = true;
  std::string failure;       // why the run cannot go on (s is then the last good state)
  bool reachesStop = false;  // the step ends on the stop it was given
  int newtonIterations = 0;  // of the accepted try (0: explicit)
};

// What an explicit scheme reports of its steps (summary.json): least and largest step taken, the
// node that limited the least, (t, step) whenever the step changed by more than 5 % since the
// last entry, and the mass added by mass scaling per part.
struct StableStepRecord {
  double least = 0.0, largest = 0.0;
  int limitingNode = -1;
  std::vector<std::pair<double, double>> history;
  std::vector<std::pair<std::string, double>> addedMass;
  double totalAddedMass = 0.0;
  // EX8: the nodes mass scaling gave mass to, and each part's mass without it (the added mass is
  // read against it).
  double targetStep = 0.0;  // mass scaling's target (given, or from the quantile)
  int scaledNodes = 0;
  std::vector<std::pair<std::string, double>> partMass;
  // The free nodes' own stable steps 2 sqrt(m_i / S_i) at the start (EX5, no safety, no damping,
  // no mass scaling): the least and the 1 %, 10 % and 50 % quantiles. The step is set by the
  // least; a target_dt up to the 1 % quantile scales at most 1 % of the nodes.
  std::array<double, 4> nodalSteps{};
};

// The step an explicit scheme would take from a state, and why (how long a run will take, asked
// before it starts: docs/limits.md).
struct StepEstimate {
  double dt = 0.0;        // the step taken: safety x the damped stable step (EX5, EX7), <= dt
  double undamped = 0.0;  // 2 / omega_max at the limiting node, no safety, no damping
  int limitingNode = -1;
};

class TimeIntegrator {
 public:
  virtual ~TimeIntegrator() = default;
  virtual IntegratorKind kind() const = 0;
  std::string_view name() const { return integratorName(kind()); }

  // The step control a run starts with.
  virtual StepControl initialControl() const = 0;
  // The acceleration at s, from M a = f_ext - f_int with the scheme's mass (consistent or
  // lumped): a run's start, and just after a cut.
  virtual void computeAcceleration(StructuralState& s) = 0;
  // Takes one step from s towards `stop` (ending on it when it reaches it): the scheme chooses
  // its length, retries as it does (events, failed solves), advances s and commits the terms'
  // histories. counters: the run's (read for the step count, updated with retries and Newton
  // iterations). A failure leaves s the last good state.
  virtual StepResult step(StructuralState& s, double stop, StepCounters& counters) = 0;
  // Where the equations of the step that ended in s hold (TI5): s itself unless the scheme
  // evaluates its forces inside the step.
  virtual EquilibriumPoint equilibrium(const StructuralState& s) const {
    return EquilibriumPoint{s.x, s.v, s.a, s.t};
  }

  // An implicit scheme's linear solver (nullptr: none, an explicit scheme).
  virtual LinearSolver* linearSolver() { return nullptr; }
  const LinearSolver* linearSolver() const {
    return const_cast<TimeIntegrator*>(this)->linearSolver();
  }
  // Whether the case's solver.dt is the step taken (an implicit scheme) rather than a cap on a
  // stable step (an explicit one): output times closer than dt then shorten the steps.
  virtual bool takesNominalStep() const { return true; }
  // Steps between two evaluations of the energy balance (EB1): explicit steps are 10-100x
  // shorter than implicit ones and a balance costs as much as a step.
  virtual long balanceStride() const { return 1; }
  // Whether the equations hold at the steps' ends (an explicit scheme): the energy balance then
  // takes a window's work from the forces at both its ends (EB1, trapezoidal).
  virtual bool equationsAtStepEnds() const { return false; }
  // An explicit scheme's record of its stable steps (nullptr: none).
  virtual const StableStepRecord* stableSteps() const { return nullptr; }
  // The step an explicit scheme would take from s (nullopt: an implicit scheme, whose step is the
  // case's dt).
  virtual std::optional<StepEstimate> estimateStep(const StructuralState&) { return std::nullopt; }
};

}  // namespace chute
