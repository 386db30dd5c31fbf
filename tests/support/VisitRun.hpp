#pragma once
// A case's dynamic run stepped as `chute run` steps it (its integrator from the case), without
// output, calling visit(state, system) at the start, every `every` steps and at the end: for
// checks that need the states themselves (the interpenetration counts of the contact tests).
#include <functional>
#include <limits>
#include <memory>

#include "case/CaseSpec.hpp"
#include "case/SolverSetup.hpp"
#include "solver/TimeIntegrator.hpp"
#include "solver/TimeStepper.hpp"

namespace chute::testing {

struct VisitedRun {
  bool reached = false;
  long steps = 0;
  double finalTime = 0.0;
};

inline VisitedRun visitRun(
    const CaseSpec& spec, long every,
    const std::function<void(const StructuralState&, const StructuralSystem&)>& visit) {
  const Model& m = spec.model;
  const SolverSpec& sv = spec.solver;
  StructuralSystem sys(m, sv.search);
  const std::unique_ptr<TimeIntegrator> integrator = makeIntegrator(sys, sv, m);
  TimeStepper stepper(sys, *integrator, sv.dt);
  StructuralState s = stepper.start();
  visit(s, sys);
  long steps = 0;
  const auto result = stepper.advanceTo(
      s, sv.tEnd, [](double) { return std::numeric_limits<double>::infinity(); },
      [&](const StructuralState& st, int) {
        if (++steps % every == 0) visit(st, sys);
        return true;
      });
  if (steps % every != 0) visit(s, sys);
  return {result.outcome == TimeStepper::Outcome::Reached, steps, s.t};
}

}  // namespace chute::testing
