#include "coupling/CouplingInterface.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "case/SolverSetup.hpp"
#include "terms/LineTerms.hpp"

namespace chute::coupling {

namespace {
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
  if (spec_.solver.type == "static")
    throw std::invalid_argument(spec_.file + ": a coupled run needs a dynamic case (solver.type)");
  spec_ = withoutWetPressure(std::move(spec_), surface_);
  const Model& m = spec_.model;
  const SolverSpec& sv = spec_.solver;
  std::vector<std::unique_ptr<Term>> extra;
  auto loads = std::make_unique<ExternalLoadTerm>(surface_);
  loads_ = loads.get();
  extra.push_back(std::move(loads));
  sys_ = std::make_unique<StructuralSystem>(m, sv.search, std::move(extra));
  integrator_ =
      std::make_unique<GeneralizedAlpha>(*sys_, sv.rhoInf, alphaScheme(sv), newtonSettings(sv, m));
  // preCICE initialize(): the initial state at rest (or moving as the case prescribes), its
  // consistent acceleration under the loads known now (none from the flow yet).
  state_ = integrator_->initialState();
  integrator_->computeInitialAcceleration(state_);
  sys_->commit(state_.x);
  control_ = StepController(sv.dt, sv.dtMin);
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

double CouplingInterface::advance(double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw CouplingError("advance: the time step must be positive, got " + std::to_string(dt));
  const double target = state_.t + dt;
  while (state_.t < target - 1e-12 * dt) {
    // As `chute run` (StepController): the window's end is a stop.
    const double h = control_.propose(state_.t, target);
    const bool reachesEnd = control_.reachesStop();
    const NewtonReport rep = integrator_->step(state_, h);
    counters_.newtonIterations += rep.iterations;
    const auto verdict = control_.judge(rep, h);
    if (verdict == StepController::Verdict::EventRetry) {
      ++counters_.eventRetries;
      continue;
    }
    if (verdict != StepController::Verdict::Accepted) {
      ++counters_.rejectedSteps;
      if (verdict == StepController::Verdict::BelowMinimum)
        throw CouplingError("step rejected at t = " + std::to_string(state_.t) + " with dt = " +
                            std::to_string(h) + " (" + rep.failure + "); dt below dt_min");
      continue;
    }
    if (reachesEnd) state_.t = target;  // windows end exactly where the flow solver expects
    ++counters_.steps;
  }
  return dt;
}

WindowCheckpoint CouplingInterface::snapshot() const {
  WindowCheckpoint c;
  c.state = state_;  // Eigen vectors: copies
  c.control = control_;
  for (const auto* g : sys_->slidingGroups()) c.groups.push_back(g->state());
  if (const auto* mt = sys_->membranes()) c.membranes = mt->elementStates();
  return c;
}

void CouplingInterface::saveCheckpoint() {
  checkpoint_ = std::make_unique<WindowCheckpoint>(snapshot());
}

void CouplingInterface::restore(const WindowCheckpoint& c) {
  state_ = c.state;
  control_ = c.control;
  for (size_t g = 0; g < c.groups.size(); ++g) sys_->slidingGroups()[g]->state() = c.groups[g];
  if (auto* mt = sys_->membranes()) mt->setElementStates(c.membranes);
}

void CouplingInterface::restoreCheckpoint() {
  if (!checkpoint_) throw NoCheckpointError("restoreCheckpoint: no checkpoint saved");
  restore(*checkpoint_);  // the checkpoint stays: a window may be repeated many times
}

}  // namespace chute::coupling
