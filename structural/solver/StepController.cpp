#include "solver/StepController.hpp"

#include <algorithm>

namespace chute {

double StepController::propose(const StepControl& c, double t, double stop) {
  double h = std::min(c.dt, stop - t);
  if (stop - t - h < 0.1 * h) h = stop - t;
  if (c.eventStep > 0 && c.eventStep < h) h = c.eventStep;
  reachesStop_ = h == stop - t;
  return h;
}

StepController::Verdict StepController::judge(StepControl& c, const NewtonReport& rep,
                                              double h) const {
  c.eventStep = 0.0;
  if (!rep.converged && rep.eventFraction > 0.0 && h * rep.eventFraction >= dtMin_) {
    c.eventStep = h * rep.eventFraction;
    return Verdict::EventRetry;
  }
  if (!rep.converged) {
    c.dt = 0.5 * h;
    c.successesSinceCut = 0;
    return c.dt < dtMin_ ? Verdict::BelowMinimum : Verdict::Rejected;
  }
  if (c.dt < dtNominal_ && ++c.successesSinceCut >= 4)
    c.dt = std::min(2 * c.dt, dtNominal_), c.successesSinceCut = 0;
  return Verdict::Accepted;
}

}  // namespace chute
