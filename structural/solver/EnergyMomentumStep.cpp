#include "solver/EnergyMomentumStep.hpp"

namespace chute {

namespace {
// The unknowns x_{n+1}; velocities from EM1, the evaluation point at the midpoint (EM2).
class EnergyMomentumProblem final : public NewtonProblem {
 public:
  EnergyMomentumProblem(const StructuralSystem& sys, const StructuralState& old, StructuralState& n,
                        double dt, double chi)
      : sys_(sys), old_(old), n_(n), dt_(dt), chi_(chi) {}

  // Constrained dofs follow their prescribed motion (fixed: where they started).
  void prescribe() { sys_.prescribeMotion(n_); }
  void afterUpdate() override {
    // EM1: v_{n+1} = 2 (x_{n+1} - x_n) / dt - v_n; a = (v_{n+1} - v_n) / dt, the step's mean
    // acceleration (the inertia force of EM2).
    n_.v = (2.0 / dt_) * (n_.x - old_.x) - old_.v;
    n_.a = (n_.v - old_.v) / dt_;
    prescribe();
  }
  EvalPoint point() override {
    x_ = 0.5 * (old_.x + n_.x);
    v_ = 0.5 * (old_.v + n_.v);
    a_ = (n_.v - old_.v) / dt_;
    // d x_mid / d x_{n+1} = 1/2, d v_mid / d x_{n+1} = 1/dt, d a / d x_{n+1} = 2/dt^2.
    EvalPoint p{x_, v_, a_, forceTime(), 0.5, 1.0 / dt_, 2.0 / (dt_ * dt_), true, 1.0, dt_};
    p.xStart = &old_.x;
    p.emDissipation = chi_;
    return p;
  }
  double forceTime() const { return old_.t + 0.5 * dt_; }

 private:
  const StructuralSystem& sys_;
  const StructuralState& old_;
  StructuralState& n_;
  double dt_, chi_;
  Eigen::VectorXd x_, v_, a_;
};
}  // namespace

NewtonReport energyMomentumStep(StructuralSystem& sys, Newton& newton, double chi,
                                StructuralState& s, double dt) {
  const StructuralState old = s;
  StructuralState n = s;
  // Predictor: positions stay where they are (as for generalized-alpha, GeneralizedAlpha.cpp).
  n.x = old.x;
  n.t = old.t + dt;
  EnergyMomentumProblem problem(sys, old, n, dt, chi);
  problem.prescribe();
  problem.afterUpdate();
  if (sys.drivesKinks() && sys.crossDriven(old.x, n.x) > 0) problem.afterUpdate();
  NewtonReport rep = newton.solve(n.x, newton.settings().toleranceFor(dt), problem, false, &old.x);
  if (rep.converged) {
    sys.commit(CommitPoint{n.x, n.t, dt, problem.forceTime()});
    s = n;
  } else {
    sys.revert();
  }
  return rep;
}

}  // namespace chute
