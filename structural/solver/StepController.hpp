#pragma once
// Step-size control shared by `chute run` and the coupling interface. Steps are at most the
// case's dt; a sliver of less than a tenth of a step before a stop (output time, end, cut) is
// absorbed; a step in which Newton finds an event (a slider at a node, a cable slack / taut) is
// tried again ending there; a failed step is halved and the step doubles back after four
// successes.
#include "solver/GeneralizedAlpha.hpp"

namespace chute {

class StepController {
 public:
  StepController(double dtNominal, double dtMin)
      : dt(dtNominal), dtNominal_(dtNominal), dtMin_(dtMin) {}

  // Length of the next step from time t towards `stop`.
  double propose(double t, double stop);
  bool reachesStop() const { return reachesStop_; }  // the last proposal ends at the stop

  enum class Verdict {
    Accepted,
    EventRetry,    // an event inside the step: the next proposal ends there
    Rejected,      // Newton failed: the step is halved
    BelowMinimum,  // halving would fall below dt_min: the run cannot go on
  };
  Verdict judge(const NewtonReport& rep, double h);

  // History (saved with checkpoints): the controlled step, the pending event step, successes
  // since the last cut.
  double dt;
  double eventStep = 0.0;
  int successesSinceCut = 0;

 private:
  double dtNominal_, dtMin_;
  bool reachesStop_ = false;
};

}  // namespace chute
