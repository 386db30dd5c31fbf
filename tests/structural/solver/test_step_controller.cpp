// The step-size control of the time stepper (StepControl is part of the StructuralState).
#include <gtest/gtest.h>

#include "solver/StepController.hpp"

using namespace chute;

namespace {
NewtonReport converged() {
  NewtonReport r;
  r.converged = true;
  return r;
}
NewtonReport failed() {
  NewtonReport r;
  r.failure = "no convergence";
  return r;
}
NewtonReport eventAt(double fraction) {
  NewtonReport r;
  r.failure = "an event";
  r.eventFraction = fraction;
  return r;
}
}  // namespace

TEST(StepController, StepsOfDtWithASliverBeforeAStopAbsorbed) {
  StepController c(0.1, 1e-6);
  StepControl k = c.initial();
  EXPECT_DOUBLE_EQ(c.propose(k, 0.0, 1.0), 0.1);
  EXPECT_FALSE(c.reachesStop());
  // 0.105 left: a step of 0.1 would leave 0.005 < a tenth of it, so the step takes it all.
  EXPECT_DOUBLE_EQ(c.propose(k, 0.0, 0.105), 0.105);
  EXPECT_TRUE(c.reachesStop());
  // 0.13 left: 0.1 then 0.03 (not a sliver).
  EXPECT_DOUBLE_EQ(c.propose(k, 0.0, 0.13), 0.1);
  EXPECT_DOUBLE_EQ(c.propose(k, 0.1, 0.13), 0.13 - 0.1);
}

TEST(StepController, AnEventCutsTheRetryToEndThereOnce) {
  StepController c(0.1, 1e-6);
  StepControl k = c.initial();
  const double h = c.propose(k, 0.0, 1.0);
  EXPECT_EQ(c.judge(k, eventAt(0.25), h), StepController::Verdict::EventRetry);
  EXPECT_DOUBLE_EQ(c.propose(k, 0.0, 1.0), 0.025);
  EXPECT_EQ(c.judge(k, converged(), 0.025), StepController::Verdict::Accepted);
  EXPECT_DOUBLE_EQ(c.propose(k, 0.025, 1.0), 0.1);  // the controlled step is untouched
  // An event step below dt_min is a plain failure: halved.
  EXPECT_EQ(c.judge(k, eventAt(1e-9), 0.1), StepController::Verdict::Rejected);
  EXPECT_DOUBLE_EQ(k.dt, 0.05);
}

TEST(StepController, HalvesOnFailureDoublesBackAfterFourSuccessesStopsBelowDtMin) {
  StepController c(0.1, 0.02);
  StepControl k = c.initial();
  EXPECT_EQ(c.judge(k, failed(), 0.1), StepController::Verdict::Rejected);
  EXPECT_DOUBLE_EQ(k.dt, 0.05);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(c.judge(k, converged(), k.dt), StepController::Verdict::Accepted);
    EXPECT_DOUBLE_EQ(k.dt, 0.05);
  }
  EXPECT_EQ(c.judge(k, converged(), k.dt), StepController::Verdict::Accepted);
  EXPECT_DOUBLE_EQ(k.dt, 0.1);  // and never above the nominal step
  for (int i = 0; i < 8; ++i) c.judge(k, converged(), k.dt);
  EXPECT_DOUBLE_EQ(k.dt, 0.1);
  EXPECT_EQ(c.judge(k, failed(), 0.1), StepController::Verdict::Rejected);   // 0.05
  EXPECT_EQ(c.judge(k, failed(), 0.05), StepController::Verdict::Rejected);  // 0.025
  EXPECT_EQ(c.judge(k, failed(), 0.025), StepController::Verdict::BelowMinimum);
}
