#pragma once
// The energy-momentum scheme (docs/formulation.md section 10, EM1-EM8): the midpoint-type
// two-point scheme
//   (x_{n+1} - x_n) / dt = (v_n + v_{n+1}) / 2,
//   M (v_{n+1} - v_n) / dt + f_int^alg(x_n, x_{n+1}) = f_ext(x_mid, v_mid, t_{n+1/2}),
// with the strain-energy terms' discrete gradients (Simo & Tarnow 1992, Gonzalez 2000). Needs
// nothing beyond (x, v) of the state: a = (v_{n+1} - v_n) / dt is kept for output only. Fourth
// order by Yoshida's symmetric composition of three steps (EM14).
#include "solver/ImplicitIntegrator.hpp"

namespace chute {

class EnergyMomentum final : public ImplicitIntegrator {
 public:
  // chi: the energy-decaying parameter (EM8; 0: conserving); order: 2, or 4 by the symmetric
  // composition of three steps (EM14).
  EnergyMomentum(StructuralSystem& sys, NewtonSettings newton, double dtNominal, double dtMin,
                 double chi, int order);
  IntegratorKind kind() const override { return IntegratorKind::EnergyMomentum; }

  NewtonReport tryStep(StructuralState& s, double dt) override;

 private:
  // One second-order step of length dt (EM1-EM2).
  NewtonReport midpointStep(StructuralState& s, double dt);
  double chi_;
  int order_;
};

}  // namespace chute
