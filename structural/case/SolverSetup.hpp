#pragma once
// The integrator and Newton settings a case's [solver] table asks for: the one factory of time
// integrators, for `chute run` (and its restart), `chute couple` and the C API alike.
#include <memory>

#include "case/CaseSpec.hpp"
#include "solver/Newton.hpp"
#include "solver/TimeIntegrator.hpp"

namespace chute {

NewtonSettings newtonSettings(const SolverSpec& sv, const Model& m);

// The integrator solver.integrator names, with the case's settings, stepping sys (a dynamic
// case). verboseNewton: print every Newton iteration's residuals. Throws MasslessNodesError
// (solver/CentralDifference.hpp) for central differences on a model with a free massless node.
std::unique_ptr<TimeIntegrator> makeIntegrator(StructuralSystem& sys, const SolverSpec& sv,
                                               const Model& m, bool verboseNewton = false);

}  // namespace chute
