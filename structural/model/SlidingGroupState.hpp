#pragma once
// Which element of a sliding group is active for each slider point, with a trial / commit /
// revert lifecycle so a rejected step or a coupling checkpoint rolls back cleanly.
#include <Eigen/Core>
#include <vector>

#include "model/Model.hpp"

namespace chute {

enum class SliderSearch {
  NearestLength,       // F12: every element of the group, least |l - L| (the paper's search)
  MaterialCoordinate,  // track the slider along the chain: only hand over to a neighbour
};

class SlidingGroupState {
 public:
  explicit SlidingGroupState(const SlidingGroupDef& def);

  // Re-selects the trial active element of every slider for nodal positions x (size 3n).
  // Returns how many sliders changed element.
  int search(const Eigen::VectorXd& x, SliderSearch kind);

  void commit();
  void revert();

  const SlidingGroupDef& def() const { return *def_; }
  int activeElement(int slider) const { return trial_[slider]; }
  int committedActiveElement(int slider) const { return committed_[slider]; }
  void setActiveElement(int slider, int element);  // restart / checkpoint restore
  bool isActive(int element) const;  // active for some slider (trial state)
  int sliderOfElement(int element) const;  // -1 if inactive

  // Reference arc length from the chain's first node to the slider (uniform strain in the
  // active element: the slider splits its reference length as l1 : l2).
  double materialCoordinate(int slider, const Eigen::VectorXd& x) const;
  // |l - L| of element k with slider s: the F12 score.
  double lengthMismatch(int slider, int element, const Eigen::VectorXd& x) const;

  long committedHandovers() const { return handoversCommitted_; }

 private:
  const SlidingGroupDef* def_;
  std::vector<int> trial_, committed_;
  std::vector<double> cumulativeRef_;  // reference arc length at each chain node
  long handoversTrial_ = 0, handoversCommitted_ = 0;
};

}  // namespace chute
