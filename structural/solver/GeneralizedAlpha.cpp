#include "solver/GeneralizedAlpha.hpp"

#include <Eigen/UmfPackSupport>
#include <cmath>

#include "solver/EnergyMomentumStep.hpp"
#include "terms/SlidingGroupTerm.hpp"

namespace chute {

GeneralizedAlphaParams GeneralizedAlphaParams::fromRhoInf(double rho, AlphaScheme scheme) {
  // Second-order accurate, unconditionally stable for linear problems, high-frequency spectral
  // radius rho_inf (Chung & Hulbert 1993, eqs. 25-27 with their alpha_m, alpha_f signs).
  GeneralizedAlphaParams p;
  if (scheme == AlphaScheme::ChungHulbert) {
    p.alphaM = (2.0 * rho - 1.0) / (rho + 1.0);
    p.alphaF = rho / (rho + 1.0);
  } else {
    p.alphaM = (rho - 1.0) / (rho + 1.0);
    p.alphaF = 0.0;
  }
  p.gamma = 0.5 - p.alphaM + p.alphaF;
  p.beta = 0.25 * (1.0 - p.alphaM + p.alphaF) * (1.0 - p.alphaM + p.alphaF);
  return p;
}

GeneralizedAlpha::GeneralizedAlpha(StructuralSystem& sys, double rhoInf, AlphaScheme scheme,
                                   NewtonSettings newton, double emDissipation, int emOrder)
    : sys_(&sys),
      p_(GeneralizedAlphaParams::fromRhoInf(rhoInf, scheme)),
      newton_(sys, newton),
      scheme_(scheme),
      emOrder_(emOrder),
      emDissipation_(emDissipation) {
  // The discrete gradient's tangent is not symmetric (EM5): LU from the start.
  if (scheme == AlphaScheme::EnergyMomentum) newton_.linearSolver().useLU();
  // EM12: massless chains are condensed to one polyline each (terms/SlidingGroupTerm.hpp).
  for (auto* g : sys.slidingGroups()) g->condenseChain(scheme == AlphaScheme::EnergyMomentum);
  eq_.atEnd = p_.alphaF == 0.0;
}

StructuralState GeneralizedAlpha::initialState() const {
  const Model& m = sys_->model();
  StructuralState s;
  const int n = 3 * m.numNodes();
  s.x.resize(n);
  for (int i = 0; i < m.numNodes(); ++i) s.x.segment<3>(3 * i) = m.X[i] + m.u0[i];
  s.v.setZero(n);
  s.a.setZero(n);
  for (int d = 0; d < n; ++d)
    if (sys_->dofs().eqOfDof(d) < 0) s.v[d] = m.constraint[d / 3].speed(d % 3, 0.0);
  return s;
}

void GeneralizedAlpha::computeInitialAcceleration(StructuralState& s) {
  if (sys_->numEquations() == 0) return;
  sys_->updateState(s.x);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(s.x.size());
  EvalPoint pt{s.x, s.v, zero, s.t, 0.0, 0.0, 1.0, true};
  sys_->assemble(pt, true);  // residual f_int - f_ext, matrix M
  SparseMatrix M = sys_->matrix();
  Eigen::VectorXd rhs = -sys_->residual();
  // Massless dofs have no inertia row: pin their initial acceleration to zero.
  for (int e = 0; e < M.cols(); ++e) {
    bool empty = true;
    for (SparseMatrix::InnerIterator it(M, e); it; ++it)
      if (it.value() != 0.0) empty = false;
    if (empty) {
      M.coeffRef(e, e) = 1.0;
      rhs[e] = 0.0;
    }
  }
  Eigen::UmfPackLU<SparseMatrix> lu;
  lu.compute(M);
  Eigen::VectorXd a0 = lu.solve(rhs);
  if (lu.info() == Eigen::Success && a0.allFinite()) sys_->addToDofs(a0, s.a);
}

namespace {
// One step's unknowns and their evaluation point: Newmark's update of velocity and acceleration
// from the trial positions, prescribed dofs on their path, and the alpha-blended point where the
// forces are evaluated.
class StepProblem final : public NewtonProblem {
 public:
  StepProblem(const StructuralSystem& sys, const GeneralizedAlphaParams& p,
              const StructuralState& old, StructuralState& n, double dt)
      : sys_(sys), p_(p), old_(old), n_(n), dt_(dt) {}

  // Constrained dofs follow their prescribed motion (fixed: where they started).
  void prescribe() { sys_.prescribeMotion(n_); }
  void afterUpdate() override {
    const double dt = dt_;
    n_.a = (n_.x - old_.x - dt * old_.v - dt * dt * (0.5 - p_.beta) * old_.a) / (p_.beta * dt * dt);
    n_.v = old_.v + dt * ((1.0 - p_.gamma) * old_.a + p_.gamma * n_.a);
    prescribe();
  }
  EvalPoint point() override {
    x_ = (1.0 - p_.alphaF) * n_.x + p_.alphaF * old_.x;
    v_ = (1.0 - p_.alphaF) * n_.v + p_.alphaF * old_.v;
    a_ = (1.0 - p_.alphaM) * n_.a + p_.alphaM * old_.a;
    return EvalPoint{x_,
                     v_,
                     a_,
                     forceTime(),
                     1.0 - p_.alphaF,
                     (1.0 - p_.alphaF) * p_.gamma / (p_.beta * dt_),
                     (1.0 - p_.alphaM) / (p_.beta * dt_ * dt_),
                     true,
                     1.0,
                     dt_};
  }
  double forceTime() const { return old_.t + (1.0 - p_.alphaF) * dt_; }

 private:
  const StructuralSystem& sys_;
  const GeneralizedAlphaParams& p_;
  const StructuralState& old_;
  StructuralState& n_;
  double dt_;
  Eigen::VectorXd x_, v_, a_;
};
}  // namespace

NewtonReport GeneralizedAlpha::step(StructuralState& s, double dt) {
  if (scheme_ == AlphaScheme::EnergyMomentum && emOrder_ == 4) {
    // EM14: Yoshida's triple jump, steps g1 dt, g2 dt, g1 dt with 2 g1 + g2 = 1 and
    // 2 g1^3 + g2^3 = 0, g1 = 1 / (2 - 2^(1/3)): the composition of a symmetric second-order
    // method is fourth-order and symmetric, and keeps what every step keeps (energy, momenta).
    // A failed part fails the step (the stepper restores its start and halves it).
    const double g1 = 1.0 / (2.0 - std::cbrt(2.0)), g2 = 1.0 - 2.0 * g1;
    NewtonReport total;
    total.converged = true;
    const double t0 = s.t;
    for (const double g : {g1, g2, g1}) {
      const NewtonReport part = energyMomentumStep(*sys_, newton_, emDissipation_, s, g * dt);
      total.iterations += part.iterations;
      total.stateChanges += part.stateChanges;
      total.residualNorms.insert(total.residualNorms.end(), part.residualNorms.begin(),
                                 part.residualNorms.end());
      total.updateNorms.insert(total.updateNorms.end(), part.updateNorms.begin(),
                               part.updateNorms.end());
      if (!part.converged) {
        total.converged = false;
        total.failure = part.failure;
        total.outOfIterations = part.outOfIterations;
        return total;
      }
    }
    s.t = t0 + dt;  // the parts' times add up to dt only to round-off
    return total;
  }
  if (scheme_ == AlphaScheme::EnergyMomentum)
    return energyMomentumStep(*sys_, newton_, emDissipation_, s, dt);
  const StructuralState old = s;
  StructuralState n = s;
  // Predictor: positions stay where they are (the first Newton update is then a consistent
  // linearised step from the last converged state). Predicting positions from Newmark's
  // velocity would move a heavy slider while the massless rope nodes around it, whose Newmark
  // velocities carry no information, stay behind: a stiff rope then starts a step with a large
  // spurious stretch.
  n.x = old.x;
  n.t = old.t + dt;
  StepProblem problem(*sys_, p_, old, n, dt);
  problem.prescribe();
  problem.afterUpdate();
  // The prescribed motion's jump may carry a driven slider past nodes: it starts Newton in the
  // element it has reached.
  if (sys_->drivesKinks() && sys_->crossDriven(old.x, n.x) > 0) problem.afterUpdate();
  NewtonReport rep =
      newton_.solve(n.x, newton_.settings().toleranceFor(dt), problem, false, &old.x);
  if (rep.converged) {
    sys_->commit(CommitPoint{n.x, n.t, dt, problem.forceTime()});
    if (!eq_.atEnd) {  // the alpha-point of the converged step (eq. TI5)
      eq_.x = (1.0 - p_.alphaF) * n.x + p_.alphaF * old.x;
      eq_.v = (1.0 - p_.alphaF) * n.v + p_.alphaF * old.v;
      eq_.a = (1.0 - p_.alphaM) * n.a + p_.alphaM * old.a;
      eq_.t = problem.forceTime();
      eq_.tEnd = n.t;
    }
    s = n;
  } else {
    sys_->revert();
  }
  return rep;
}

}  // namespace chute
