#pragma once
// The explicit step's evaluation, with the loads its element passes take (P2, FL13, CB1), against
// every term evaluated apart at the same state: the largest differences of the residual and of
// the loads the energy balance keeps, each over its largest entry, and the work each evaluation
// counted.
#include <gtest/gtest.h>

#include <limits>

#include "solver/StructuralSystem.hpp"

namespace chute::testing {

struct FusedAgainstApart {
  double residual = std::numeric_limits<double>::infinity();
  double loads = std::numeric_limits<double>::infinity();
  WorkCounters before, fused, apart;  // sys.work() before, after the fused and the apart residual
};

inline FusedAgainstApart fusedAgainstApart(StructuralSystem& sys, const Eigen::VectorXd& x,
                                           const Eigen::VectorXd& v, double t) {
  FusedAgainstApart g;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(x.size());
  g.before = sys.work();
  sys.captureStepLoads(true);
  sys.assemble(EvalPoint::explicitForces(x, v, zero, t, 1e-4), false);
  sys.captureStepLoads(false);
  g.fused = sys.work();
  const Eigen::VectorXd fused = sys.residual();
  const Eigen::VectorXd* loads = sys.stepLoadsAt(t);
  if (!loads) {
    ADD_FAILURE() << "the explicit step kept no loads at t = " << t;
    return g;
  }
  const Eigen::VectorXd kept = *loads;
  const EvalPoint state = EvalPoint::state(x, v, zero, t);
  const Eigen::VectorXd separate = sys.gatherEquations(sys.residualOverAllDofs(state, true));
  g.apart = sys.work();
  const Eigen::VectorXd separateLoads = sys.residualOverAllDofs(state, false);
  g.residual = (fused - separate).cwiseAbs().maxCoeff() / separate.cwiseAbs().maxCoeff();
  g.loads = (kept - separateLoads).cwiseAbs().maxCoeff() / separateLoads.cwiseAbs().maxCoeff();
  return g;
}

}  // namespace chute::testing
