#include "coupling/CouplingInterface.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "case/SolverSetup.hpp"

namespace chute::coupling {

namespace {
// advance() refuses windows longer than this many steps of dt_min (a window of 1e300 would
// never return).
constexpr double kMaxStepsPerWindow = 1e9;

// A number with its significant digits (std::to_string prints 1e-20 as 0.000000).
std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

// The flow solver owns the pressure on the wet surface: drop the case's pressure on wet sets.
CaseSpec withoutWetPressure(CaseSpec spec, const WetSurface& w) {
  auto& p = spec.model.pressures;
  p.erase(std::remove_if(p.begin(), p.end(),
                         [&](const PressureLoadDef& d) {
                           return std::find(w.sets.begin(), w.sets.end(), d.set) != w.sets.end();
                         }),
          p.end());
  return spec;
}
}  // namespace

CouplingInterface::CouplingInterface(CaseSpec spec, const std::vector<std::string>& surfaceSets)
    : spec_(std::move(spec)), surface_(WetSurface::fromModel(spec_.model, surfaceSets)) {
  if (spec_.solver.type == AnalysisType::Static)
    throw std::invalid_argument("a coupled run needs a dynamic case (solver.type)");
  spec_ = withoutWetPressure(std::move(spec_), surface_);
  const Model& m = spec_.model;
  const SolverSpec& sv = spec_.solver;
  std::vector<std::unique_ptr<Term>> extra;
  auto loads = std::make_unique<ExternalLoadTerm>(surface_);
  loads_ = loads.get();
  extra.push_back(std::move(loads));
  sys_ = std::make_unique<StructuralSystem>(m, sv.search, std::move(extra));
  integrator_ = makeIntegrator(*sys_, sv, m);
  stepper_ = std::make_unique<TimeStepper>(*sys_, *integrator_, sv.dt);
  // preCICE initialize(): the initial state at rest (or moving as the case prescribes), its
  // consistent acceleration under the loads known now (none from the flow yet).
  state_ = stepper_->start();
}

Eigen::VectorXd CouplingInterface::referenceCoordinates() const {
  Eigen::VectorXd out(3 * numVertices());
  const Model& m = spec_.model;
  for (int v = 0; v < numVertices(); ++v) {
    const int n = surface_.node[v];
    out.segment<3>(3 * v) = m.X[n] + m.u0[n];
  }
  return out;
}

Eigen::VectorXd CouplingInterface::currentCoordinates() const {
  return surface_.gather(state_.x);
}
Eigen::VectorXd CouplingInterface::displacements() const {
  return currentCoordinates() - referenceCoordinates();
}
Eigen::VectorXd CouplingInterface::velocities() const {
  return surface_.gather(state_.v);
}
Eigen::VectorXd CouplingInterface::accelerations() const {
  return surface_.gather(state_.a);
}
Eigen::VectorXd CouplingInterface::faceAreaVectors() const {
  return surface_.faceAreaVectors(state_.x);
}
Eigen::VectorXd CouplingInterface::faceAreas() const {
  const Eigen::VectorXd A = faceAreaVectors();
  Eigen::VectorXd out(numFaces());
  for (int f = 0; f < numFaces(); ++f) out[f] = A.segment<3>(3 * f).norm();
  return out;
}
Eigen::VectorXd CouplingInterface::faceNormals() const {
  Eigen::VectorXd n = faceAreaVectors();
  for (int f = 0; f < numFaces(); ++f) {
    const double a = n.segment<3>(3 * f).norm();
    if (a > 0.0) n.segment<3>(3 * f) /= a;
  }
  return n;
}
Eigen::VectorXd CouplingInterface::faceCentres() const {
  return surface_.faceMeans(currentCoordinates());
}

void CouplingInterface::initializeWithLoads() {
  if (stepper_->counters().steps > 0 || state_.t != 0.0)
    throw CallOrderError("initializeWithLoads: only before the first advance");
  state_ = stepper_->start();
}

double CouplingInterface::advance(double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw CouplingError("advance: the time step must be positive, got " + num(dt));
  const double target = state_.t + dt;
  // A window too short to move time, or one that would take more steps than any run can.
  // The stepper counts a stop within 1e-12 dt of the time as reached (round-off of summed
  // steps): a shorter window would return at once, OK, with time unchanged.
  if (target == state_.t || stepper_->reached(state_.t, target))
    throw CouplingError("advance: the time step " + num(dt) +
                        " is below the resolution of the time " + num(state_.t) +
                        " (1e-12 of solver.dt)");
  if (dt / spec_.solver.dtMin > kMaxStepsPerWindow)
    throw CouplingError("advance: a window of " + num(dt) + " would take more than " +
                        num(kMaxStepsPerWindow) + " steps of dt_min");
  // As `chute run` (TimeStepper): the window's end is a stop, and so are the case's cut events.
  // A window that fails leaves the state it started from (the last good window's end): a flow
  // solver may retry it with other loads or a shorter window, without a checkpoint of its own.
  const WindowCheckpoint start = sys_->saveState(state_);
  const auto before = stepper_->counters();
  const auto result = stepper_->advanceTo(
      state_, target, [](double) { return std::numeric_limits<double>::infinity(); },
      [this](const StructuralState& s, int) {
        if (stepObserver_) stepObserver_(s);
        return true;
      });
  const auto& after = stepper_->counters();
  counters_.steps += after.steps - before.steps;
  counters_.rejectedSteps += after.rejectedSteps - before.rejectedSteps;
  counters_.eventRetries += after.eventRetries - before.eventRetries;
  counters_.newtonIterations += after.newtonIterations - before.newtonIterations;
  if (result.outcome == TimeStepper::Outcome::BelowMinimum) {
    state_ = sys_->loadState(start);
    stepper_->counters() = before;
    throw CouplingError(result.reason +
                        "; the structure is back at the window's start, t = " + num(state_.t));
  }
  return dt;
}

WindowCheckpoint CouplingInterface::snapshot() const {
  return sys_->saveState(state_);
}

void CouplingInterface::saveCheckpoint() {
  checkpoint_ = std::make_unique<WindowCheckpoint>(snapshot());
}

void CouplingInterface::restoreCheckpoint() {
  if (!checkpoint_) throw NoCheckpointError("restoreCheckpoint: no checkpoint saved");
  state_ = sys_->loadState(*checkpoint_);  // the checkpoint stays: a window may be repeated
}

}  // namespace chute::coupling
