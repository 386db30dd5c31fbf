#include "solver/StepController.hpp"

#include <algorithm>

namespace chute {

double StepController::propose(double t, double stop) {
  double h = std::min(dt, stop - t);
  if (stop - t - h < 0.1 * h) h = stop - t;
  if (eventStep > 0 && eventStep < h) h = eventStep;
  reachesStop_ = h == stop - t;
  return h;
}

StepController::Verdict StepController::judge(const NewtonReport& rep, double h) {
  eventStep = 0.0;
  if (!rep.converged && rep.eventFraction > 0.0 && h * rep.eventFraction >= dtMin_) {
    eventStep = h * rep.eventFraction;
    return Verdict::EventRetry;
  }
  if (!rep.converged) {
    dt = 0.5 * h;
    successesSinceCut = 0;
    return dt < dtMin_ ? Verdict::BelowMinimum : Verdict::Rejected;
  }
  if (dt < dtNominal_ && ++successesSinceCut >= 4)
    dt = std::min(2 * dt, dtNominal_), successesSinceCut = 0;
  return Verdict::Accepted;
}

}  // namespace chute
