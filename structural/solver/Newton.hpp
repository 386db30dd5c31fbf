#pragma once
// Full Newton on the assembled residual with the consistent tangent: the iteration, its
// convergence test (update size, down to the round-off floor of stiff short parts) and the
// handling of kinks crossed by an update (assembly/EventSource.hpp). The integrators supply the
// evaluation point and what follows an update of the positions; Newton knows no time scheme.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "solver/LinearSolver.hpp"
#include "solver/StructuralSystem.hpp"

namespace chute {

struct NewtonSettings {
  int maxIterations = 25;
  // Converged when max |dx| <= tolDisplacement (length units) at the nominal step. A shorter
  // step h tightens it by (h / nominalStep)^2, down to round-off (100 eps x lengthScale):
  // accelerations are dx / (beta h^2), so a fixed position tolerance would let a short step's
  // velocity and acceleration drift.
  double tolDisplacement = 1e-9;
  double nominalStep = 0.0;  // 0: no scaling
  double lengthScale = 1.0;
  // Cut steps to end where a tension-only cable goes slack or taut (EventSource::
  // stepEventFraction). Off: Newton crosses the kink within the step (scenes with hundreds of
  // flapping tapes and lines, where each crossing would cut a step).
  bool slackTautEvents = true;
  // Cut steps to end where a slider reaches a node. Off: Newton hands the slider over at the
  // node inside the step, as in statics (Bossak only: forces at the step's end, where the slider
  // is in its new element). Keeps the step, and with it the numerical damping of unresolved
  // fabric modes (C-9); measured no worse in energy drift (docs/applications/c9.md).
  bool sliderEvents = true;
  // Modified Newton (solver.reuse_tangent): an iteration reuses the tangent factorised earlier
  // in the same step and assembles the residual alone, while each update is at most
  // reuseContraction times the one before; otherwise, and after any discrete change, the tangent
  // is assembled and factorised afresh at the same point and the update redone. The convergence
  // test is unchanged, so the answer moves only within the tolerance. (C-9 slider, 0.3 s: 0.25
  // and 0.15 took the same number of factorisations, 0.5 more.)
  bool reuseTangent = false;
  double reuseContraction = 0.25;
  // solver.linear_solver = "symmetric_part": a system with a non-symmetric tangent (pressure,
  // face drag) is solved with the LDL^T factorisation of its symmetric part (LinearSolver).
  bool symmetricPartSolver = false;
  bool verbose = false;  // print the residual sequence of every iteration
  // The tolerance for a step of length h (see tolDisplacement).
  double toleranceFor(double h) const;
};

struct NewtonReport {
  bool converged = false;
  int iterations = 0;
  std::string failure;                // why not converged
  bool outOfIterations = false;       // the failure: maxIterations updates, all finite
  std::vector<double> residualNorms;  // ||R|| before each update
  std::vector<double> updateNorms;    // max |dx| of each update
  int stateChanges = 0;               // discrete changes (active elements) during the solve
  double eventFraction = 0.0;         // > 0: the step passes an event; retry with this fraction
};

// What an integrator gives Newton: the evaluation point at the current positions, and the
// update of what depends on them (velocities, accelerations) after Newton moved them.
class NewtonProblem {
 public:
  virtual ~NewtonProblem() = default;
  virtual EvalPoint point() = 0;
  virtual void afterUpdate() = 0;
};

class Newton {
 public:
  Newton(StructuralSystem& sys, NewtonSettings settings);

  // crossInPlace: a kink reached by an update is crossed within the solve (statics) instead of
  // ending the step there. stepStart: the positions the step started from, for events located
  // along the step's whole motion (slack / taut); nullptr: none.
  NewtonReport solve(Eigen::VectorXd& x, double tol, NewtonProblem& problem, bool crossInPlace,
                     const Eigen::VectorXd* stepStart);

  const NewtonSettings& settings() const { return settings_; }
  const LinearSolver& linearSolver() const { return linear_; }
  LinearSolver& linearSolver() { return linear_; }

 private:
  StructuralSystem* sys_;
  NewtonSettings settings_;
  LinearSolver linear_;
};

}  // namespace chute
