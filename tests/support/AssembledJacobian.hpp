#pragma once
// A whole system's assembled Jacobian against central differences of its residual, at a moving
// state with the integrator's coefficients (cx, cv, ca): every term of a scene checked together
// (the canopy, face-drag and coupling tests).
#include <Eigen/Core>
#include <cmath>

#include "solver/StructuralSystem.hpp"
#include "support/FiniteDifference.hpp"

namespace chute::testing {

struct MovingState {
  Eigen::VectorXd x, v, a;
};

// The reference positions stretched by `stretch` and bent out of plane by up to `bend`, moving
// with velocities up to `speed` and accelerations up to `accel` (smooth, varied per dof).
inline MovingState movingState(const Model& m, double stretch, double bend, double speed,
                               double accel) {
  const int n = 3 * m.numNodes();
  MovingState s{Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::VectorXd(n)};
  for (int k = 0; k < n; ++k) {
    s.x[k] = stretch * m.X[k / 3][k % 3] + (k % 3 == 2 ? bend * std::sin(1.3 * k) : 0.0);
    s.v[k] = speed * std::cos(0.7 * k);
    s.a[k] = accel * std::sin(1.0 + k);
  }
  return s;
}

// Relative error of the assembled Jacobian (divided by cx: d residual / d x along the
// integrator's path, velocities and accelerations following x) against central differences.
inline double assembledJacobianError(StructuralSystem& sys, const MovingState& s, double cx = 0.8,
                                     double cv = 30.0, double ca = 4000.0, double h = 1e-7) {
  sys.updateState(s.x);
  auto residual = [&](const Eigen::VectorXd& xeq) -> Eigen::VectorXd {
    Eigen::VectorXd y = s.x;
    for (int d = 0, e = 0; d < y.size(); ++d)
      if (sys.dofs().eqOfDof(d) >= 0) y[d] = xeq[e++];
    const Eigen::VectorXd vy = s.v + (cv / cx) * (y - s.x), ay = s.a + (ca / cx) * (y - s.x);
    sys.assemble(EvalPoint::implicitStep(y, vy, ay, 0.5, {cx, cv, ca}, 0.0), false);
    return sys.residual();
  };
  sys.assemble(EvalPoint::implicitStep(s.x, s.v, s.a, 0.5, {cx, cv, ca}, 0.0), true);
  const Eigen::MatrixXd J = Eigen::MatrixXd(sys.matrix()) / cx;
  return relativeError(J, fdJacobian(residual, sys.gatherEquations(s.x), h));
}

}  // namespace chute::testing
