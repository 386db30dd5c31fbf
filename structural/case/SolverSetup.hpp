#pragma once
// The integrator and Newton settings a case's [solver] table asks for: one place for `chute run`
// and the coupling interface.
#include "case/CaseSpec.hpp"
#include "solver/GeneralizedAlpha.hpp"

namespace chute {

NewtonSettings newtonSettings(const SolverSpec& sv, const Model& m);
AlphaScheme alphaScheme(const SolverSpec& sv);

}  // namespace chute
