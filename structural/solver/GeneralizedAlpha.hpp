#pragma once
// Implicit generalized-alpha time integration (Chung & Hulbert 1993, docs/formulation.md section 7)
// with full Newton on the residual and the consistent tangent, plus a static mode with load
// stepping. The integrator sees one matrix J = cx K + cv C + ca M assembled from the terms.
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "solver/LinearSolver.hpp"
#include "solver/StructuralSystem.hpp"

namespace chute {

struct DynamicState {
  Eigen::VectorXd x, v, a;  // positions, velocities, accelerations of all dofs
  double t = 0.0;
};

struct NewtonSettings {
  int maxIterations = 25;
  // Converged when max |dx| <= tolDisplacement (length units) at the nominal step. A shorter
  // step h tightens it by (h / nominalStep)^2, down to round-off (100 eps x lengthScale):
  // accelerations are dx / (beta h^2), so a fixed position tolerance would let a short step's
  // velocity and acceleration drift.
  double tolDisplacement = 1e-9;
  double nominalStep = 0.0;  // 0: no scaling
  double lengthScale = 1.0;
  // Cut steps to end where a tension-only cable goes slack or taut (Term::stepEventFraction).
  // Off: Newton crosses the kink within the step (scenes with hundreds of flapping tapes and
  // lines, where each crossing would cut a step).
  bool slackTautEvents = true;
  // Cut steps to end where a slider reaches a node. Off: Newton hands the slider over at the
  // node inside the step, as in statics (Bossak only: forces at the step's end, where the slider
  // is in its new element). Keeps the step, and with it the numerical damping of unresolved
  // fabric modes (C-9); measured no worse in energy drift (docs/applications/c9.md).
  bool sliderEvents = true;
  bool verbose = false;  // print the residual sequence of every iteration
};

// Members of the generalized-alpha family, both second-order accurate with high-frequency
// spectral radius rho_inf:
//  - ChungHulbert (1993): optimal alpha_m, alpha_f; forces at t_{n+1-alpha_f}.
//  - Bossak (Wood, Bossak & Zienkiewicz 1980): alpha_f = 0, every force at t_{n+1}. Massless
//    nodes then end each step in equilibrium and configuration changes (a slider handed over at
//    a node) are consistent at the step's end; with Chung-Hulbert a massless node's end-of-step
//    position is off equilibrium by O(dt^2), undamped for rho_inf = 1.
// rho_inf = 1 gives Newmark's trapezoidal rule with Bossak.
enum class AlphaScheme { Bossak, ChungHulbert };

struct GeneralizedAlphaParams {
  double alphaM, alphaF, beta, gamma;
  static GeneralizedAlphaParams fromRhoInf(double rhoInf, AlphaScheme scheme);
};

struct NewtonReport {
  bool converged = false;
  int iterations = 0;
  std::string failure;                // why not converged
  std::vector<double> residualNorms;  // ||R|| before each update
  std::vector<double> updateNorms;    // max |dx| of each update
  int stateChanges = 0;               // discrete changes (active elements) during the solve
  double eventFraction = 0.0;         // > 0: the step passes an event; retry with this fraction
};

class GeneralizedAlpha {
 public:
  GeneralizedAlpha(StructuralSystem& sys, double rhoInf, AlphaScheme scheme, NewtonSettings newton);

  // Initial state at rest or moving: positions from the model, consistent acceleration
  // M a0 = f_ext - f_int (massless dofs get a0 = 0).
  DynamicState initialState() const;
  void computeInitialAcceleration(DynamicState& s);

  // Advances s by dt. On failure s and every term's history are left as they were.
  NewtonReport step(DynamicState& s, double dt);

  // Static equilibrium under the loads, applied in nSteps increments of the load factor: equal,
  // or growing geometrically from initialFactor to 1 (a flat membrane under pressure stiffens
  // with its deflection: w ~ p^(1/3)).
  NewtonReport solveStatic(DynamicState& s, int nSteps, double initialFactor = 1.0);

  const GeneralizedAlphaParams& params() const { return p_; }
  const LinearSolver& linearSolver() const { return linear_; }
  LinearSolver& linearSolver() { return linear_; }

 private:
  // crossInPlace: a passage is crossed within the solve (static) instead of cutting the step.
  // In dynamics driven sliders are handed over along the way (StructuralSystem::crossDriven).
  // stepStart: the positions the step started from, for events located along the step's whole
  // motion (StructuralSystem::stepEventFraction); nullptr: none.
  template <class MakePoint, class Update>
  NewtonReport newton(Eigen::VectorXd& x, double tol, MakePoint&& makePoint, Update&& onUpdate,
                      bool crossInPlace = false, const Eigen::VectorXd* stepStart = nullptr);

  StructuralSystem* sys_;
  GeneralizedAlphaParams p_;
  NewtonSettings newton_;
  LinearSolver linear_;
};

}  // namespace chute
