#include "solver/GeneralizedAlpha.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

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
                                   NewtonSettings newton)
    : sys_(&sys),
      p_(GeneralizedAlphaParams::fromRhoInf(rhoInf, scheme)),
      newton_(newton),
      linear_(sys.symmetric(), sys.timings()) {}

DynamicState GeneralizedAlpha::initialState() const {
  const Model& m = sys_->model();
  DynamicState s;
  const int n = 3 * m.numNodes();
  s.x.resize(n);
  for (int i = 0; i < m.numNodes(); ++i) s.x.segment<3>(3 * i) = m.X[i] + m.u0[i];
  s.v.setZero(n);
  s.a.setZero(n);
  for (int d = 0; d < n; ++d)
    if (sys_->dofs().eqOfDof(d) < 0) s.v[d] = m.constraint[d / 3].speed(d % 3, 0.0);
  return s;
}

void GeneralizedAlpha::computeInitialAcceleration(DynamicState& s) {
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

template <class MakePoint, class Update>
NewtonReport GeneralizedAlpha::newton(Eigen::VectorXd& x, double tol, MakePoint&& makePoint,
                                      Update&& onUpdate, bool crossInPlace,
                                      const Eigen::VectorXd* stepStart) {
  NewtonReport rep;
  const int neq = sys_->numEquations();
  const bool driven = !crossInPlace && sys_->drivesKinks();
  Eigen::VectorXd dxEq(neq), dx(x.size()), before, motion;
  int lastChanges = 0;
  for (int it = 0; it < newton_.maxIterations; ++it) {
    lastChanges = sys_->updateState(x);
    rep.stateChanges += lastChanges;
    auto pt = makePoint();
    sys_->assemble(pt.point(), true);
    const Eigen::VectorXd& R = sys_->residual();
    const double rn = R.norm();
    rep.residualNorms.push_back(rn);
    if (!std::isfinite(rn)) {
      rep.failure = "non-finite residual";
      return rep;
    }
    if (!linear_.factorize(sys_->matrix())) {
      rep.failure = "singular tangent";
      return rep;
    }
    if (!linear_.solve(-R, dxEq)) {
      rep.failure = "linear solve failed";
      return rep;
    }
    dx.setZero();
    sys_->addToDofs(dxEq, dx);
    const double un = dx.lpNorm<Eigen::Infinity>();
    rep.updateNorms.push_back(un);
    rep.iterations = it + 1;
    if (!std::isfinite(un)) {
      rep.failure = "non-finite update";
      return rep;
    }
    const double passage = sys_->passageFraction(x, dx);
    if (newton_.verbose)
      std::fprintf(stderr, "    newton %2d  |R| = %.3e  |dx| = %.3e  changes %d%s\n", it, rn, un,
                   lastChanges, passage < 1.0 ? "  passes an event" : "");
    if (passage < 1.0 && (crossInPlace || !newton_.sliderEvents)) {
      x += passage * dx;  // to where slider and node meet, then across
      sys_->crossNow(x);
      onUpdate();
      continue;
    }
    // Slack / taut switches: along the whole motion from the step's start to this trial end
    // (the fraction of the step where it passes one, positions being linear in time to first
    // order).
    double stepEvent = 1.0;
    if (stepStart && newton_.slackTautEvents) {
      motion = x + dx - *stepStart;
      stepEvent = sys_->stepEventFraction(*stepStart, motion);
    }
    if (passage < 1.0 || stepEvent < 1.0) {
      // The first update is the linearised step: its passage fraction estimates the event time.
      rep.failure = "an event (a slider at a node, a cable slack / taut) within the step";
      const double sliders = passage < 1.0 ? (it == 0 ? passage : 0.5) : 1.0;
      rep.eventFraction = std::max(std::min(sliders, stepEvent), 1e-12);
      return rep;
    }
    if (driven) before = x;
    x += dx;
    onUpdate();
    // A driven slider carried past a node by this update is handed over there.
    const bool crossed = driven && sys_->crossDriven(before, x) > 0;
    if (crossed) onUpdate();
    // Not below what round-off lets the assembled forces resolve (a stiff short part, FR16).
    if (lastChanges == 0 && !crossed && un <= std::max(tol, sys_->displacementFloor())) {
      if (sys_->onConverged(x)) onUpdate();  // moved by a negligible amount onto an event
      rep.converged = true;
      return rep;
    }
  }
  rep.failure = "no convergence in " + std::to_string(newton_.maxIterations) + " iterations";
  return rep;
}

namespace {
// An evaluation point owning the blended vectors it refers to.
struct OwnedPoint {
  Eigen::VectorXd x, v, a;
  double t, cx, cv, ca;
  bool inertia;
  double loadFactor;
  double dt = 0.0;
  EvalPoint point() const { return EvalPoint{x, v, a, t, cx, cv, ca, inertia, loadFactor, dt}; }
};
}  // namespace

NewtonReport GeneralizedAlpha::step(DynamicState& s, double dt) {
  const auto& p = p_;
  const DynamicState old = s;
  DynamicState n = s;
  // Predictor: positions stay where they are (the first Newton update is then a consistent
  // linearised step from the last converged state). Predicting positions from Newmark's
  // velocity would move a heavy slider while the massless rope nodes around it, whose Newmark
  // velocities carry no information, stay behind: a stiff rope then starts a step with a large
  // spurious stretch.
  n.x = old.x;
  n.t = old.t + dt;
  // Constrained dofs follow their prescribed motion (fixed: where they started).
  const Model& model = sys_->model();
  auto prescribe = [&] {
    for (int d = 0; d < sys_->dofs().numDofs(); ++d) {
      if (sys_->dofs().eqOfDof(d) >= 0) continue;
      const auto& c = model.constraint[d / 3];
      n.x[d] = c.position(model.X[d / 3][d % 3] + model.u0[d / 3][d % 3], d % 3, n.t);
      n.v[d] = c.speed(d % 3, n.t);
      n.a[d] = c.acceleration(d % 3, n.t);
    }
  };
  prescribe();
  auto newmark = [&] {
    n.a = (n.x - old.x - dt * old.v - dt * dt * (0.5 - p.beta) * old.a) / (p.beta * dt * dt);
    n.v = old.v + dt * ((1.0 - p.gamma) * old.a + p.gamma * n.a);
    prescribe();
  };
  auto makePoint = [&] {
    return OwnedPoint{(1.0 - p.alphaF) * n.x + p.alphaF * old.x,
                      (1.0 - p.alphaF) * n.v + p.alphaF * old.v,
                      (1.0 - p.alphaM) * n.a + p.alphaM * old.a,
                      old.t + (1.0 - p.alphaF) * dt,
                      1.0 - p.alphaF,
                      (1.0 - p.alphaF) * p.gamma / (p.beta * dt),
                      (1.0 - p.alphaM) / (p.beta * dt * dt),
                      true,
                      1.0,
                      dt};
  };
  newmark();
  // The prescribed motion's jump may carry a driven slider past nodes: it starts Newton in the
  // element it has reached.
  if (sys_->drivesKinks() && sys_->crossDriven(old.x, n.x) > 0) newmark();
  double tol = newton_.tolDisplacement;
  if (newton_.nominalStep > 0.0 && dt < newton_.nominalStep) {
    const double ratio = dt / newton_.nominalStep;
    tol = std::max(tol * ratio * ratio, 100.0 * 2.22e-16 * newton_.lengthScale);
  }
  NewtonReport rep = newton(n.x, tol, makePoint, newmark, false, &old.x);
  if (rep.converged) {
    sys_->commit(n.x);
    s = n;
  } else {
    sys_->revert();
  }
  return rep;
}

NewtonReport GeneralizedAlpha::solveStatic(DynamicState& s, int nSteps, double initialFactor) {
  // Load stepping in the load factor; a slider reaching a node is handed over within the solve
  // (no step straddles it in statics), failed increments are halved.
  NewtonReport total;
  Eigen::VectorXd x = s.x;
  double lambda = 0.0, increment = 1.0 / nSteps;
  const bool geometric = initialFactor < 1.0 && nSteps > 1;
  const double growth = geometric ? std::pow(1.0 / initialFactor, 1.0 / (nSteps - 1)) : 1.0;
  if (geometric) increment = initialFactor;
  while (lambda < 1.0 - 1e-12) {
    const double target = std::min(1.0, lambda + increment);
    auto makePoint = [&] {
      return OwnedPoint{x,
                        Eigen::VectorXd::Zero(x.size()),
                        Eigen::VectorXd::Zero(x.size()),
                        s.t,
                        1.0,
                        0.0,
                        0.0,
                        false,
                        target,
                        0.0};
    };
    const Eigen::VectorXd start = x;
    NewtonReport rep = newton(
        x, newton_.tolDisplacement, makePoint, [] {}, true);
    total.iterations += rep.iterations;
    total.residualNorms.insert(total.residualNorms.end(), rep.residualNorms.begin(),
                               rep.residualNorms.end());
    if (!rep.converged) {
      x = start;
      sys_->revert();
      increment *= 0.5;
      if (increment < 1e-9) {
        total.failure = rep.failure + " at load factor " + std::to_string(target);
        return total;
      }
      continue;
    }
    sys_->commit(x);
    lambda = target;
    increment = geometric ? std::max(increment, lambda * (growth - 1.0)) : increment;
  }
  total.converged = true;
  s.x = x;
  s.v.setZero();
  s.a.setZero();
  return total;
}

}  // namespace chute
