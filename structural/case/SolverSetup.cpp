#include "case/SolverSetup.hpp"

#include <algorithm>
#include <stdexcept>

#include "solver/CentralDifference.hpp"
#include "solver/EnergyMomentum.hpp"
#include "solver/GeneralizedAlpha.hpp"

namespace chute {

namespace {
// Diagonal of the reference bounding box: the length scale of tolerances.
double modelSize(const Model& m) {
  Vec3 lo = m.X.front(), hi = m.X.front();
  for (const auto& x : m.X) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  return std::max((hi - lo).norm(), 1e-300);
}
}  // namespace

NewtonSettings newtonSettings(const SolverSpec& sv, const Model& m) {
  NewtonSettings ns;
  ns.maxIterations = sv.maxNewton;
  ns.lengthScale = modelSize(m);
  ns.tolDisplacement = sv.tolDisplacement > 0 ? sv.tolDisplacement : 1e-10 * ns.lengthScale;
  ns.nominalStep = sv.dt;
  ns.slackTautEvents = sv.slackTautEvents;
  ns.sliderEvents = sv.sliderEvents;
  ns.reuseTangent = sv.reuseTangent;
  ns.symmetricPartSolver = sv.symmetricPartSolver;
  return ns;
}

std::unique_ptr<TimeIntegrator> makeIntegrator(StructuralSystem& sys, const SolverSpec& sv,
                                               const Model& m, bool verboseNewton) {
  NewtonSettings ns = newtonSettings(sv, m);
  ns.verbose = verboseNewton;
  switch (sv.integrator) {
    case IntegratorKind::Bossak:
      return std::make_unique<GeneralizedAlpha>(sys, sv.rhoInf, AlphaScheme::Bossak, ns, sv.dt,
                                                sv.dtMin);
    case IntegratorKind::GeneralizedAlpha:
      return std::make_unique<GeneralizedAlpha>(sys, sv.rhoInf, AlphaScheme::ChungHulbert, ns,
                                                sv.dt, sv.dtMin);
    case IntegratorKind::EnergyMomentum:
      return std::make_unique<EnergyMomentum>(sys, ns, sv.dt, sv.dtMin, sv.emDissipation,
                                              sv.emOrder);
    case IntegratorKind::CentralDifference:
      return std::make_unique<CentralDifference>(
          sys,
          ExplicitSettings{sv.safetyFactor, sv.targetDt, sv.stiffnessDamping,
                           sv.massScalingQuantile},
          sv.dt);
  }
  throw std::logic_error("makeIntegrator: unknown integrator");
}

}  // namespace chute
