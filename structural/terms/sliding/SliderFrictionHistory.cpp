#include "terms/sliding/SliderFrictionHistory.hpp"

#include <limits>

namespace chute {

double SliderFrictionHistory::State::tensionRatio() const {
  if (N1 <= 0.0 && N2 <= 0.0) return 1.0;
  return N1 > 0.0 ? N2 / N1 : std::numeric_limits<double>::infinity();
}

void SliderFrictionHistory::initialise(const std::vector<double>& uniform) {
  for (std::size_t s = 0; s < splitStart_.size(); ++s) {
    splitStart_[s] = uniform[s];
    trial_[s] = committed_[s] = State{};
    trial_[s].s = committed_[s].s = splitStart_[s];
  }
  initialised_ = true;
}

void SliderFrictionHistory::revert() {
  trial_ = committed_;
  for (std::size_t s = 0; s < splitStart_.size(); ++s) splitStart_[s] = committed_[s].s;
}

void SliderFrictionHistory::saveSplits(History& h) const {
  h.put(initialised_);
  h.put(splitStart_);
}

void SliderFrictionHistory::saveStates(History& h) const {
  for (const auto* fr : {&trial_, &committed_})
    for (const auto& f : *fr) {
      h.put(f.s), h.put(f.slipRate), h.put(f.N1), h.put(f.N2), h.put(f.wrapAngle);
      h.put(static_cast<int>(f.state));
    }
}

void SliderFrictionHistory::loadSplits(HistoryReader& h) {
  initialised_ = h.flag();
  splitStart_ = h.reals(splitStart_.size());
}

void SliderFrictionHistory::loadStates(HistoryReader& h) {
  for (auto* fr : {&trial_, &committed_})
    for (auto& f : *fr) {
      f.s = h.finiteReal(), f.slipRate = h.finiteReal(), f.N1 = h.finiteReal();
      f.N2 = h.finiteReal(), f.wrapAngle = h.finiteReal();
      f.state = static_cast<kernels::SliderStick>(h.integer(-1, 1));
    }
}

}  // namespace chute
