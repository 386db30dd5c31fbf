#pragma once
// Implicit generalized-alpha time integration (Chung & Hulbert 1993, docs/formulation.md
// section 7): the coefficients, the predictor, the Newmark update formulas and the evaluation
// point. The nonlinear solve is Newton's (solver/Newton.hpp); step control, events and retries
// are ImplicitIntegrator's. The integrator sees one matrix J = cx K + cv C + ca M.
#include <Eigen/Core>

#include "solver/ImplicitIntegrator.hpp"

namespace chute {

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

class GeneralizedAlpha final : public ImplicitIntegrator {
 public:
  GeneralizedAlpha(StructuralSystem& sys, double rhoInf, AlphaScheme scheme, NewtonSettings newton,
                   double dtNominal, double dtMin);

  IntegratorKind kind() const override {
    return scheme_ == AlphaScheme::Bossak ? IntegratorKind::Bossak
                                          : IntegratorKind::GeneralizedAlpha;
  }
  // Where the equations of the step that ended in s hold (EquilibriumPoint.hpp): s itself for
  // Bossak, the alpha-point for Chung-Hulbert (a state no step of this integrator ended in: s).
  EquilibriumPoint equilibrium(const StructuralState& s) const override { return eq_.of(s); }

  const GeneralizedAlphaParams& params() const { return p_; }

  NewtonReport tryStep(StructuralState& s, double dt) override;

 private:
  GeneralizedAlphaParams p_;
  AlphaScheme scheme_;
  KeptEquilibrium eq_;
};

}  // namespace chute
