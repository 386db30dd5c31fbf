#pragma once
// Step-size control. Steps are at most the case's dt; a sliver of less than a tenth of a step
// before a stop (output time, end, cut) is absorbed; a step in which Newton finds an event (a
// slider at a node, a cable slack / taut) is tried again ending there; a failed step is halved
// and the step doubles back after four successes. What it remembers is StepControl, part of the
// StructuralState (so checkpoints and coupling windows carry it).
#include "solver/Newton.hpp"
#include "solver/StructuralState.hpp"

namespace chute {

class StepController {
 public:
  StepController(double dtNominal, double dtMin) : dtNominal_(dtNominal), dtMin_(dtMin) {}
  StepControl initial() const { return StepControl{dtNominal_, 0.0, 0}; }

  // Length of the next step from time t towards `stop`.
  double propose(const StepControl& c, double t, double stop);
  bool reachesStop() const { return reachesStop_; }  // the last proposal ends at the stop

  enum class Verdict {
    Accepted,
    EventRetry,    // an event inside the step: the next proposal ends there
    Rejected,      // Newton failed: the step is halved
    BelowMinimum,  // halving would fall below dt_min: the run cannot go on
  };
  Verdict judge(StepControl& c, const NewtonReport& rep, double h) const;

  double nominal() const { return dtNominal_; }
  double minimum() const { return dtMin_; }

 private:
  double dtNominal_, dtMin_;
  bool reachesStop_ = false;
};

}  // namespace chute
