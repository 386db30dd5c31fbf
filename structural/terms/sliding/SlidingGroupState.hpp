#pragma once
// Which element of a sliding group is active for each slider point (the search, hand-overs at
// nodes, the reference lengths hand-overs carry), with a trial / commit / revert lifecycle so a
// rejected step or a coupling checkpoint rolls back cleanly; it holds the sliders' friction
// history (SliderFrictionHistory), which its hand-overs restart.
#include <Eigen/Core>
#include <vector>

#include "model/History.hpp"
#include "model/Model.hpp"
#include "model/SliderSearch.hpp"
#include "terms/sliding/SliderFrictionHistory.hpp"

namespace chute {

class SlidingGroupState {
 public:
  explicit SlidingGroupState(const SlidingGroupDef& def);

  // Re-selects the trial active element of every slider for nodal positions x (size 3n).
  // Returns how many sliders changed element.
  int search(const Eigen::VectorXd& x, SliderSearch kind);

  // Fraction of the update dx from positions x at which a slider would pass straight through
  // an end node of its active element (the apex of the |x3 - xi| cone, where F9 has 1/l_i), or 1.
  // A slider exactly on a node that the update moves out of its element is handed over to the
  // neighbour there at the next search(): both elements describe the same configuration then.
  double passageFraction(const Eigen::VectorXd& x, const Eigen::VectorXd& dx);
  // At a converged state: a slider that has reached an end node of its element (within
  // radiusFraction of its reference length) while approaching it during the step is handed over
  // to the neighbour there when the step is committed, and node and slider are placed
  // separationFraction of the reference length apart along the cable, the slider just inside
  // its new element (the node moves, or the slider if the node is fixed). A slider that has
  // passed the node beside it (F12b: handoverGain from above the arrival band at the step's start
  // to within it or below) is handed over without moving anything, the part's material going
  // with it. Not earlier:
  // generalized-alpha evaluates this step's forces between its start and end, where the slider is
  // still inside its element. Returns whether x was moved.
  // immediate: hand over at the next search() instead of at commit, any number of times in a
  // solve (static equilibrium, where no step straddles the crossing).
  bool arriveAtNodes(const Model& model, Eigen::VectorXd& x, double radiusFraction,
                     double separationFraction, bool immediate = false);

  // Explicit integration (docs/formulation.md EX3, F12b), which has no iterations that would
  // land a slider on a node: a free slider has passed an end node of its element over the motion
  // dx from x when its part to that node turns round, (d + delta) . d < 0 with d = x3 - xi (head
  // on), or when the path through the node on the far side of the slider becomes the shorter,
  // Delta = l_after - l_before turning negative within kPassageCapture L of the node (a node
  // passing beside the slider). It is handed over to the neighbour there at the next search()
  // (at a chain end, or against another slider, it stays), and the material of the part between
  // node and slider where Delta = 0 goes with it to the neighbour (F12b). Returns how many
  // sliders passed a node.
  int notePassages(const Eigen::VectorXd& x, const Eigen::VectorXd& dx);
  // F12b: l_after - l_before of handing slider s over across end `end` (0, 1) of its active
  // element at positions x: |x_a - x_i| + |x_s - x_c| - |x_a - x_s| - |x_i - x_c| with x_a the
  // element's other end and x_c the neighbour's far node. Positive while node i is on the
  // neighbour's side of the slider, to first order (x_i - x_s) . (t_c - t_a); NaN at a chain end.
  double handoverGain(int slider, int end, const Eigen::VectorXd& x) const;

  // Driven sliders: all three dofs follow a moving prescribed path. Where such a slider is at
  // any time is given, so its node passages need no locating in time: passageFraction() leaves
  // them out, and crossDriven() hands a driven slider over as soon as a motion from positions
  // `from` to `to` carries it past an end node of its element (the part to that node turns
  // round): for the prescribed jump at a step's start (the predictor) and after every Newton
  // update (which may also carry it back). A free node passed is put on the line from the slider
  // to the far end of the element left, at its distance from the slider (at least
  // separationFraction of the reference length), so the new short part starts along the cable.
  // Returns how many sliders change element.
  void setDriven(int slider, bool driven) { driven_[slider] = driven; }
  bool driven(int slider) const { return driven_[slider] != 0; }
  bool hasDriven() const;
  int crossDriven(const Model& model, const Eigen::VectorXd& from, Eigen::VectorXd& to,
                  double separationFraction);

  void commit(const Eigen::VectorXd& x);  // x: the converged positions
  void revert();
  // Everything the group remembers (trial and committed), exactly; load() checks each value.
  void save(History& h) const;
  void load(HistoryReader& h);

  const SlidingGroupDef& def() const { return *def_; }
  // Reference length of chain element k: the definition's, changed only by the material a
  // hand-over beside a node carries across it (F12b; the chain's total never changes).
  double refLength(int k) const { return ref_[k]; }
  int activeElement(int slider) const { return trial_[slider]; }
  int committedActiveElement(int slider) const { return committed_[slider]; }
  void setActiveElement(int slider, int element);  // tests: put a slider in an element
  // The trial active element of a slider, set where it is known to be (EM12's condensed chain);
  // commit() counts the nodes it passed.
  void moveTo(int slider, int element) { trial_[slider] = element; }
  bool isActive(int element) const;  // active for some slider (trial state)
  // The first slider in the element, -1 if inactive. Inline: every element of every sliding
  // group at every explicit step (the line drag's and the group's own loops).
  int sliderOfElement(int element) const {
    for (size_t s = 0; s < trial_.size(); ++s)
      if (trial_[s] == element) return static_cast<int>(s);
    return -1;
  }

  // Reference arc length from the chain's first node to the slider (uniform strain in the
  // active element: the slider splits its reference length as l1 : l2).
  double materialCoordinate(int slider, const Eigen::VectorXd& x) const;
  // |l - L| of element k with slider s: the F12 score.
  double lengthMismatch(int slider, int element, const Eigen::VectorXd& x) const;

  long committedHandovers() const { return handovers_; }

  // ---- friction history (terms/sliding/SliderFrictionHistory.hpp) ----------------------------
  using FrictionState = SliderFrictionHistory::State;
  bool hasFriction(int slider) const { return def_->frictionOf(slider) != nullptr; }
  // The split at the start of the step (the stick predictor), for the trial active element.
  double splitStart(int slider) const { return friction_.splitStart(slider); }
  // Converged friction state of a slider at the end of the step, before commit(x).
  void setConvergedFriction(int slider, const FrictionState& f) {
    friction_.setConverged(slider, f);
  }
  const FrictionState& friction(int slider) const { return friction_.committed(slider); }
  // Splits start uniform at the first positions seen (search or commit).
  void ensureSplits(const Eigen::VectorXd& x);

 private:
  const SlidingGroupDef* def_;
  std::vector<int> trial_, committed_;
  std::vector<double> committedDistance_[2];  // slider to end node 1 / 2 at the step start
  std::vector<double> committedGain_[2];      // handoverGain across end 1 / 2 at the step start
  std::vector<double> transferAtCommit_;      // reference length carried by handoverAtCommit_
  // F12b: whether slider s has passed end `end` beside the node at x (Delta <= the arrival band
  // within kPassageCapture L), and the reference length that goes with it; false for sliders with
  // friction (their split is history, FR16) and driven ones.
  bool passedBeside(int slider, int end, const Eigen::VectorXd& x, double& transfer) const;
  // Whether the line's two parts leave slider s at x at more than RG9's fold angle across end
  // `end` (a line folded back on itself, such as a rope over a pulley, has no side to pass on).
  bool foldOpen(int slider, int end, const Eigen::VectorXd& x) const;
  // F12b: the reference length handed across with slider s over end `end` at x: what keeps the
  // strain of the element it leaves (a -> slider -> i becomes the cable a -> i); where Delta = 0
  // the element it joins gains the same length, and keeps its strain too.
  double handoverTransfer(int slider, int end, const Eigen::VectorXd& x) const;
  std::vector<int> pendingHandover_;        // per slider: -1 across end 1, +1 across end 2, 0 none
  std::vector<double> pendingTransfer_;     // per slider: reference length carried across (F12b)
  std::vector<double> ref_, refCommitted_;  // per element: reference length (trial, committed)
  void setRefLengths(const std::vector<double>& ref);  // and the cumulative table
  // F12b: moves `length` of reference length (at most half of it) from element `from` to `to`.
  void carryMaterial(int from, int to, double length);
  std::vector<int> handoverAtCommit_;  // same, applied when the step is committed
  std::vector<double> cumulativeRef_;  // reference arc length at each chain node
  std::vector<char> driven_;           // per slider: follows a moving prescribed path
  long handovers_ = 0;                 // nodes passed by committed steps
  // The split of an element where both parts have one strain (a new element starts with it).
  double uniformSplit(int slider, int element, const Eigen::VectorXd& x) const;
  SliderFrictionHistory friction_;
};

}  // namespace chute
