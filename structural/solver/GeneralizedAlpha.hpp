#pragma once
// Implicit generalized-alpha time integration (Chung & Hulbert 1993, docs/formulation.md
// section 7): the coefficients, the predictor, the Newmark update formulas and the evaluation
// point. The nonlinear solve is Newton's (solver/Newton.hpp); the choice of steps, events and
// retries is the TimeStepper's. The integrator sees one matrix J = cx K + cv C + ca M.
#include <Eigen/Core>

#include "solver/EquilibriumPoint.hpp"
#include "solver/Newton.hpp"
#include "solver/StructuralState.hpp"
#include "solver/StructuralSystem.hpp"

namespace chute {

// Members of the generalized-alpha family, both second-order accurate with high-frequency
// spectral radius rho_inf:
//  - ChungHulbert (1993): optimal alpha_m, alpha_f; forces at t_{n+1-alpha_f}.
//  - Bossak (Wood, Bossak & Zienkiewicz 1980): alpha_f = 0, every force at t_{n+1}. Massless
//    nodes then end each step in equilibrium and configuration changes (a slider handed over at
//    a node) are consistent at the step's end; with Chung-Hulbert a massless node's end-of-step
//    position is off equilibrium by O(dt^2), undamped for rho_inf = 1.
// rho_inf = 1 gives Newmark's trapezoidal rule with Bossak.
// EnergyMomentum is not of the family: the midpoint-type scheme with discrete gradients
// (solver/EnergyMomentumStep.hpp, docs/formulation.md section 10); rho_inf is not used.
enum class AlphaScheme { Bossak, ChungHulbert, EnergyMomentum };

struct GeneralizedAlphaParams {
  double alphaM, alphaF, beta, gamma;
  static GeneralizedAlphaParams fromRhoInf(double rhoInf, AlphaScheme scheme);
};

class GeneralizedAlpha {
 public:
  // emDissipation: the energy-decaying parameter chi of EnergyMomentum (EM8; 0: conserving);
  // emOrder: 2, or 4 by the symmetric composition of three EnergyMomentum steps (EM14).
  GeneralizedAlpha(StructuralSystem& sys, double rhoInf, AlphaScheme scheme, NewtonSettings newton,
                   double emDissipation = 0.0, int emOrder = 2);

  // Initial state at rest or moving: positions from the model, prescribed velocities.
  StructuralState initialState() const;
  // Consistent acceleration M a = f_ext - f_int at s (massless dofs get a = 0).
  void computeInitialAcceleration(StructuralState& s);

  // Advances s by dt and commits the terms' histories. On failure s is left as it was and the
  // terms' trial changes are reverted.
  NewtonReport step(StructuralState& s, double dt);

  // Where the equations of the step that ended in s hold (EquilibriumPoint.hpp): s itself for
  // Bossak, the alpha-point for Chung-Hulbert (a state no step of this integrator ended in: s).
  EquilibriumPoint equilibrium(const StructuralState& s) const { return eq_.of(s); }

  const GeneralizedAlphaParams& params() const { return p_; }
  Newton& newton() { return newton_; }
  const LinearSolver& linearSolver() const { return newton_.linearSolver(); }
  LinearSolver& linearSolver() { return newton_.linearSolver(); }

 private:
  StructuralSystem* sys_;
  GeneralizedAlphaParams p_;
  Newton newton_;
  AlphaScheme scheme_;
  int emOrder_ = 2;
  double emDissipation_;
  KeptEquilibrium eq_;
};

}  // namespace chute
