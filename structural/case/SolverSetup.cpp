#include "case/SolverSetup.hpp"

#include <algorithm>

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

AlphaScheme alphaScheme(const SolverSpec& sv) {
  if (sv.integrator == "energy_momentum") return AlphaScheme::EnergyMomentum;
  if (sv.integrator == "generalized_alpha") return AlphaScheme::ChungHulbert;
  // Bossak, and central_difference: the explicit path uses the implicit integrator only for the
  // start; its forces, like Bossak's, hold at the step's end (TI5: equilibrium point = state).
  return AlphaScheme::Bossak;
}

}  // namespace chute
