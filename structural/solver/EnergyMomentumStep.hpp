#pragma once
// One step of the energy-momentum scheme (docs/formulation.md section 10, EM1-EM8): the
// midpoint-type two-point scheme
//   (x_{n+1} - x_n) / dt = (v_n + v_{n+1}) / 2,
//   M (v_{n+1} - v_n) / dt + f_int^alg(x_n, x_{n+1}) = f_ext(x_mid, v_mid, t_{n+1/2}),
// with the strain-energy terms' discrete gradients (Simo & Tarnow 1992, Gonzalez 2000). Needs
// nothing beyond (x, v) of the state: a = (v_{n+1} - v_n) / dt is kept for output only.
#include "solver/Newton.hpp"
#include "solver/StructuralState.hpp"
#include "solver/StructuralSystem.hpp"

namespace chute {

// Advances s by dt and commits the terms' histories; on failure s is left as it was and the
// terms' trial changes are reverted. chi: the energy-decaying parameter (EM8, 0: conserving).
NewtonReport energyMomentumStep(StructuralSystem& sys, Newton& newton, double chi,
                                StructuralState& s, double dt);

}  // namespace chute
