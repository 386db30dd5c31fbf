#include "solver/EnergyMonitor.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

namespace chute {

EnergyMonitor::EnergyMonitor(StructuralSystem& sys, double tolerance, bool trapezoidal)
    : sys_(&sys), tolerance_(tolerance), trapezoidal_(trapezoidal) {
  const Model& m = sys.model();
  for (int d = 0; d < sys.dofs().numDofs(); ++d) {
    if (sys.dofs().eqOfDof(d) >= 0) continue;
    const auto& c = m.constraint[d / 3];
    if (c.velocity[d % 3] != 0.0 || (c.amplitude[d % 3] != 0.0 && c.frequency != 0.0))
      supportsMove_ = true;
  }
  loads_ = std::any_of(sys.terms().begin(), sys.terms().end(),
                       [](const auto& t) { return t->doesExternalWork(); });
  // m |g| L: the gravity potential of every mass raised by the model's size L (the bounding
  // box's diagonal) along -g.
  if (m.hasGravity() && !m.X.empty()) {
    Vec3 lo = m.X.front(), hi = m.X.front();
    for (const auto& p : m.X) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    const double size = (hi - lo).norm();
    Eigen::VectorXd x(3 * m.numNodes()), up(3 * m.numNodes()), zero;
    for (int i = 0; i < m.numNodes(); ++i) {
      x.segment<3>(3 * i) = m.X[i];
      up.segment<3>(3 * i) = m.X[i] - size * m.gravity.normalized();
    }
    zero = Eigen::VectorXd::Zero(x.size());
    gravityFloor_ = std::abs(sys.energy(up, zero, 0.0).gravity - sys.energy(x, zero, 0.0).gravity);
  }
}

void EnergyMonitor::start(const StructuralState& s, const EquilibriumPoint& eq) {
  const EnergyBreakdown e = sys_->energy(eq.x, eq.v, s.t);
  energy0_ = energy_ = e.total();
  work_ = grossWork_ = 0.0;
  lastForce_.resize(0);
  if (trapezoidal_ && (loads_ || supportsMove_))
    lastForce_ = forceAt(EvalPoint::state(eq.x, eq.v, eq.a, eq.t));
  scale_ = e.kinetic + std::abs(e.strain);
  largest_ = 0.0;
  stepsOver_ = stepsGrowing_ = 0;
  startBalance_ = 0.0;
  steps_ = 0;
  reason_.clear();
}

Eigen::VectorXd EnergyMonitor::forceAt(const EvalPoint& p) const {
  Eigen::VectorXd f = loads_ ? Eigen::VectorXd(-sys_->residualOverAllDofs(p, false))  // -residual
                             : Eigen::VectorXd::Zero(sys_->dofs().numDofs());
  if (supportsMove_) {
    const Eigen::VectorXd r = sys_->residualOverAllDofs(p, true);
    for (int d = 0; d < sys_->dofs().numDofs(); ++d)
      if (sys_->dofs().eqOfDof(d) < 0) f[d] += r[d];  // R = r at constrained dofs
  }
  return f;
}

bool EnergyMonitor::afterStep(const StructuralState& before, const StructuralState& s,
                              const EquilibriumPoint& eq, double dt) {
  ++steps_;
  const Eigen::VectorXd dx = s.x - before.x;
  // The work of the step (EB1): loads without an energy, and the supports' reactions where the
  // supports move, at the step's equilibrium point.
  const EvalPoint p = EvalPoint::state(eq.x, eq.v, eq.a, eq.t).withStep(dt);
  double w = 0.0;
  Eigen::VectorXd force;
  EnergyBreakdown e;
  auto work = [&] {
    if (!loads_ && !supportsMove_) return;
    if (trapezoidal_ && lastForce_.size() == force.size())
      w = 0.5 * (lastForce_ + force).dot(dx);
    else
      w = force.dot(dx);
  };
  // EB1: the loads the step ending here applied, where it kept them (an explicit step), and the
  // energy on the assembly's two threads; else the loads evaluated here, on one thread while the
  // energy is on the other (each in its own order: the same bits as one after the other).
  if (const Eigen::VectorXd* applied = supportsMove_ ? nullptr : sys_->stepLoadsAt(eq.t)) {
    force = -*applied;
    work();
    e = sys_->energyOnTwoThreads(eq.x, eq.v, s.t);
  } else {
    sys_->runTwo(
        [&] {
          if (loads_ || supportsMove_) force = forceAt(p);
          work();
        },
        [&] { e = sys_->energy(eq.x, eq.v, s.t); });
  }
  if (trapezoidal_) lastForce_ = std::move(force);
  work_ += w;
  grossWork_ += std::abs(w);
  energy_ = e.total();
  scale_ = std::max(scale_, e.kinetic + std::abs(e.strain));
  const double b = balance();
  largest_ = std::max(largest_, b);
  if (!std::isfinite(b)) {
    reason_ = fmt::format("energy balance not finite at t = {:.9g}", s.t);
    return false;
  }
  const double S = fullScale();
  stepsOver_ = b > tolerance_ * S ? stepsOver_ + 1 : 0;
  if (tolerance_ > 0.0 && (stepsOver_ >= kPersistentSteps || b > S)) {
    reason_ = fmt::format(
        "energy balance violated at t = {:.9g}: the structure gained {:.6g} more energy than the "
        "loads and supports gave it (E = {:.6g}, E0 = {:.6g}, work {:.6g}), {} the energy scale "
        "{:.6g} (largest kinetic + strain energy, gross work, m g L); the integration is "
        "unstable: a smaller solver.dt or solver.rho_inf may help",
        s.t, b, energy_, energy0_, work_,
        b > S ? std::string("more than")
              : fmt::format("above solver.energy_tolerance = {:.3g} x for {} steps", tolerance_,
                            stepsOver_),
        S);
    return false;
  }
  if (steps_ == 2 * kPersistentSteps) startBalance_ = largest_;  // >= 0: a gain, not a loss
  stepsGrowing_ = closedViolated(b) ? stepsGrowing_ + 1 : 0;
  if (tolerance_ > 0.0 && stepsGrowing_ >= kPersistentSteps) {
    reason_ = fmt::format(
        "energy grew without external work at t = {:.9g}: the structure gained {:.6g} since "
        "its first {} steps (E = {:.6g}, E0 = {:.6g}) with no load or moving support to give "
        "it, above {:.3g} x the energy scale {:.6g} for {} steps (EB2); the integration is "
        "unstable: a smaller solver.dt or solver.rho_inf may help",
        s.t, b - startBalance_, 2 * kPersistentSteps, energy_, energy0_,
        kClosedFraction * tolerance_, S, stepsGrowing_);
    return false;
  }
  return true;
}

bool EnergyMonitor::finish() {
  const double S = fullScale(), b = balance();
  if (tolerance_ <= 0.0 || steps_ < 2 * kPersistentSteps) return true;
  if (closedViolated(b)) {
    reason_ = fmt::format(
        "energy grew without external work by the end of the run: the structure gained {:.6g} "
        "since its first {} steps (E = {:.6g}, E0 = {:.6g}) with no load or moving support to "
        "give it, above {:.3g} x the energy scale {:.6g} (EB2); the integration is unstable: a "
        "smaller solver.dt or solver.rho_inf may help",
        b - startBalance_, 2 * kPersistentSteps, energy_, energy0_, kClosedFraction * tolerance_,
        S);
    return false;
  }
  if (!(b > tolerance_ * S)) return true;
  reason_ = fmt::format(
      "energy balance violated at the end of the run: the structure holds {:.6g} more energy "
      "than the loads and supports gave it (E = {:.6g}, E0 = {:.6g}, work {:.6g}), above "
      "solver.energy_tolerance = {:.3g} x the energy scale {:.6g}; the integration is unstable: "
      "a smaller solver.dt or solver.rho_inf may help",
      b, energy_, energy0_, work_, tolerance_, S);
  return false;
}

}  // namespace chute
