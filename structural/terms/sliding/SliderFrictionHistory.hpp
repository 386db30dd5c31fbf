#pragma once
// The friction history of a sliding group's sliders (docs/friction.md): per slider the split s of
// its active element's reference length the step starts from (part 1 = end 1 -> slider), and the
// friction state (stick / slip, slip rate, part forces, wrap angle) converged in the trial step
// and committed. Sliders with friction, a lock or one-way flow carry it; a frictionless slider's
// split follows from its positions. Trial / commit / revert / save / load like every history.
#include <vector>

#include "kernels/SliderFriction.hpp"
#include "model/History.hpp"

namespace chute {

class SliderFrictionHistory {
 public:
  struct State {
    double s = 0.0;  // split: reference length of part 1 of the active element
    kernels::SliderStick state = kernels::SliderStick::Stick;
    double slipRate = 0.0;  // ds/dt over the last step (material length per time)
    double N1 = 0.0, N2 = 0.0, wrapAngle = 0.0;
    double tensionRatio() const;  // N2 / N1 (1 when both are slack)
  };

  explicit SliderFrictionHistory(std::size_t sliders)
      : splitStart_(sliders, 0.0), trial_(sliders), committed_(sliders) {}

  // Splits start uniform at the first positions a group sees: `uniform` per slider.
  bool initialised() const { return initialised_; }
  void initialise(const std::vector<double>& uniform);

  // The split the step starts from (the stick predictor), for the trial active element.
  double splitStart(int slider) const { return splitStart_[slider]; }
  // A trial step moved the slider to a new element: it starts there with the uniform split.
  void startTrialElement(int slider, double uniform) { splitStart_[slider] = uniform; }
  // A committed step: a slider with friction starts the next step from its converged split; one
  // handed over to a new element starts it with the uniform split.
  void keepConvergedSplit(int slider) { splitStart_[slider] = trial_[slider].s; }
  void startCommittedElement(int slider, double uniform) {
    splitStart_[slider] = trial_[slider].s = uniform;
  }

  // The converged friction state of a slider at the end of the trial step, and the committed one.
  void setConverged(int slider, const State& f) { trial_[slider] = f; }
  const State& committed(int slider) const { return committed_[slider]; }

  void commit() { committed_ = trial_; }
  void revert();
  // The record is written in two parts, where the group's record has always had them (the
  // splits among the hand-over state, the friction states last): checkpoints keep their format.
  void saveSplits(History& h) const;
  void saveStates(History& h) const;
  void loadSplits(HistoryReader& h);
  void loadStates(HistoryReader& h);

 private:
  bool initialised_ = false;
  std::vector<double> splitStart_;
  std::vector<State> trial_, committed_;
};

}  // namespace chute
