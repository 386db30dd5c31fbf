#include "case/SolverSetup.hpp"

#include <algorithm>

namespace chute {

double modelSize(const Model& m) {
  Vec3 lo = m.X.front(), hi = m.X.front();
  for (const auto& x : m.X) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  return std::max((hi - lo).norm(), 1e-300);
}

NewtonSettings newtonSettings(const SolverSpec& sv, const Model& m) {
  NewtonSettings ns;
  ns.maxIterations = sv.maxNewton;
  ns.tolDisplacement = sv.tolDisplacement > 0 ? sv.tolDisplacement : 1e-10 * modelSize(m);
  ns.nominalStep = sv.dt;
  ns.lengthScale = modelSize(m);
  ns.slackTautEvents = sv.slackTautEvents;
  ns.sliderEvents = sv.sliderEvents;
  return ns;
}

AlphaScheme alphaScheme(const SolverSpec& sv) {
  return sv.integrator == "bossak" ? AlphaScheme::Bossak : AlphaScheme::ChungHulbert;
}

}  // namespace chute
