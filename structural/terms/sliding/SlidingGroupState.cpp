#include "terms/sliding/SlidingGroupState.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "kernels/SlidingCableKernel.hpp"

namespace chute {

namespace {
Vec3 nodePos(const Eigen::VectorXd& x, int n) {
  return x.segment<3>(3 * n);
}

// handoverGain of slider `slider` on element k at the positions pos(node) gives.
template <class Positions>
double gainAt(const SlidingGroupDef& def, int k, int slider, int end, Positions pos) {
  const int next = k + (end == 0 ? -1 : +1);
  if (next < 0 || next >= def.numElements()) return std::numeric_limits<double>::quiet_NaN();
  const Vec3 xs = pos(def.sliders[slider]);
  const Vec3 xi = pos(def.chain[k + end]);                   // the node passed
  const Vec3 xa = pos(def.chain[k + 1 - end]);               // the element's other end
  const Vec3 xc = pos(def.chain[end == 0 ? k - 1 : k + 2]);  // the neighbour's far node
  return (xa - xi).norm() + (xs - xc).norm() - (xa - xs).norm() - (xi - xc).norm();
}

// The positions x + dx at a node, for the gain at the step's end without forming x + dx whole
// (the same sums, element by element: the same bits).
auto movedBy(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) {
  return [&x, &dx](int n) { return Vec3(nodePos(x, n) + nodePos(dx, n)); };
}
}  // namespace

SlidingGroupState::SlidingGroupState(const SlidingGroupDef& def)
    : def_(&def),
      trial_(def.initialActive),
      committed_(def.initialActive),
      pendingHandover_(def.sliders.size(), 0),
      pendingTransfer_(def.sliders.size(), 0.0),
      handoverAtCommit_(def.sliders.size(), 0),
      driven_(def.sliders.size(), 0),
      friction_(def.sliders.size()) {
  // Sized from the start (set by every commit) so that the history record has one shape.
  for (auto& d : committedDistance_) d.assign(def.sliders.size(), 0.0);
  for (auto& d : committedGain_) d.assign(def.sliders.size(), 0.0);
  transferAtCommit_.assign(def.sliders.size(), 0.0);
  setRefLengths(def.refLength);
  refCommitted_ = ref_;
}

void SlidingGroupState::setRefLengths(const std::vector<double>& ref) {
  ref_ = ref;
  cumulativeRef_.assign(def_->chain.size(), 0.0);
  for (int k = 0; k < def_->numElements(); ++k) cumulativeRef_[k + 1] = cumulativeRef_[k] + ref_[k];
}

void SlidingGroupState::carryMaterial(int from, int to, double length) {
  // At most half the element left: a transfer never empties it (each reference length stays
  // positive, as load() checks).
  const double m = std::min(length, 0.5 * ref_[from]);
  if (!(m > 0.0)) return;
  std::vector<double> ref = ref_;
  ref[from] -= m;
  ref[to] += m;
  setRefLengths(ref);
}

double SlidingGroupState::lengthMismatch(int slider, int element, const Eigen::VectorXd& x) const {
  const Vec3 xs = nodePos(x, def_->sliders[slider]);
  const double l = (xs - nodePos(x, def_->chain[element])).norm() +
                   (xs - nodePos(x, def_->chain[element + 1])).norm();
  return std::abs(l - ref_[element]);
}

bool SlidingGroupState::isActive(int element) const {
  return sliderOfElement(element) >= 0;
}

void SlidingGroupState::setActiveElement(int slider, int element) {
  if (element < 0 || element >= def_->numElements())
    throw std::out_of_range("active element out of range in group " + def_->name);
  trial_[slider] = committed_[slider] = element;
}

int SlidingGroupState::search(const Eigen::VectorXd& x, SliderSearch kind) {
  ensureSplits(x);
  int changed = 0;
  const int nEl = def_->numElements();
  for (size_t s = 0; s < trial_.size(); ++s) {
    // An element can carry only one slider; the others' elements are excluded.
    auto takenByOther = [&](int k) {
      for (size_t o = 0; o < trial_.size(); ++o)
        if (o != s && trial_[o] == k) return true;
      return false;
    };
    int best = trial_[s];
    if (pendingHandover_[s] != 0) {
      const int k = best + pendingHandover_[s];
      // At a chain end, or against another slider, the slider stays where it is.
      if (k >= 0 && k < nEl && !takenByOther(k)) {
        // F12b: the material between node and slider where they passed goes with the slider.
        carryMaterial(best, k, pendingTransfer_[s]);
        best = k;
      }
    }
    pendingTransfer_[s] = 0.0;
    if (kind == SliderSearch::NearestLength) {
      // F12, with ties kept by the current element: at a node both neighbours fit to within
      // round-off of the strains, and only a clear improvement (kArrivalFraction L) is a reason
      // to move the slider.
      const int current = best;
      double bestScore = lengthMismatch(static_cast<int>(s), best, x);
      // Within the arrival radius of the node it shares with a neighbour, the slider stays:
      // there both fit to within the strains' difference, and F12 alone could hand a slider
      // just handed over across the node (arriveAtNodes) straight back.
      const Vec3 xs = nodePos(x, def_->sliders[s]);
      const double radius = kernels::kArrivalFraction * ref_[current];
      auto atSharedNode = [&](int k) {
        return std::abs(k - current) == 1 &&
               (xs - nodePos(x, def_->chain[std::max(k, current)])).norm() <= radius;
      };
      for (int k = 0; k < nEl; ++k) {
        if (k == best || takenByOther(k) || atSharedNode(k)) continue;
        const double margin = k == current ? 0.0 : radius;
        const double score = lengthMismatch(static_cast<int>(s), k, x);
        if (score < bestScore - margin) best = k, bestScore = score;
      }
    }
    pendingHandover_[s] = 0;
    if (best != trial_[s]) {
      trial_[s] = best;
      ++changed;
      // A new element starts with the uniform split (both parts at one strain).
      friction_.startTrialElement(static_cast<int>(s), uniformSplit(static_cast<int>(s), best, x));
    }
  }
  return changed;
}

double SlidingGroupState::passageFraction(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) {
  double fraction = 1.0;
  for (size_t s = 0; s < trial_.size(); ++s) {
    if (driven_[s]) continue;  // crossed within the solve (crossDriven)
    const int k = trial_[s];
    const int n1 = def_->chain[k], n2 = def_->chain[k + 1], n3 = def_->sliders[s];
    for (int end = 0; end < 2; ++end) {
      const int ni = end == 0 ? n1 : n2, other = end == 0 ? n2 : n1;
      const Vec3 d = nodePos(x, n3) - nodePos(x, ni);
      const Vec3 delta = nodePos(dx, n3) - nodePos(dx, ni);
      if (d.squaredNorm() == 0.0) {
        // Exactly on the node: leaving away from the element's other node is leaving the element.
        if (delta.dot(nodePos(x, other) - nodePos(x, ni)) < 0.0)
          pendingHandover_[s] = end == 0 ? -1 : +1;
        continue;
      }
      const double dDelta = d.dot(delta);
      // A slider with friction (FR16): the event is its entry into the arrival zone of the node,
      // the step ending where it would be half the zone's radius from the node.
      const double zone = kernels::kFrictionArrivalFraction * ref_[k];
      if (hasFriction(static_cast<int>(s)) && d.norm() > zone) {
        const double aim = 0.5 * zone, dd = delta.squaredNorm();
        const double disc = dDelta * dDelta - dd * (d.squaredNorm() - aim * aim);
        if (dd > 0.0 && disc >= 0.0) {  // |d + f delta| = aim at f = (-d.delta -+ sqrt) / dd
          const double f = (-dDelta - std::sqrt(disc)) / dd;
          if (f >= 0.0 && f <= 1.0) fraction = std::min(fraction, f);
        }
        continue;
      }
      // The part flips direction, (d + delta) . d < 0: the update passes the node, closest at
      // the fraction -d.delta / |delta|^2.
      if (d.squaredNorm() + dDelta < 0.0) {
        fraction = std::min(fraction, std::clamp(-dDelta / delta.squaredNorm(), 0.0, 1.0));
        continue;
      }
      // F12b: the update carries the node past the slider beside it: handoverGain from above the
      // arrival band to below zero, near the node; the update is cut where it is (linearly) at
      // half the band.
      if (hasFriction(static_cast<int>(s))) continue;
      const double capture = kernels::kPassageCapture * ref_[k];
      if (!(d.norm() < capture || (d + delta).norm() < capture)) continue;
      if (!foldOpen(static_cast<int>(s), end, x)) continue;
      const double band = kernels::kArrivalFraction * ref_[k];
      const double g0 = handoverGain(static_cast<int>(s), end, x);
      if (!(g0 > band)) continue;
      const double g1 = gainAt(*def_, k, static_cast<int>(s), end, movedBy(x, dx));
      if (g1 < 0.0)
        fraction = std::min(fraction, std::clamp((g0 - 0.5 * band) / (g0 - g1), 0.0, 1.0));
    }
  }
  return fraction;
}

double SlidingGroupState::handoverGain(int slider, int end, const Eigen::VectorXd& x) const {
  return gainAt(*def_, trial_[slider], slider, end, [&](int n) { return nodePos(x, n); });
}

bool SlidingGroupState::foldOpen(int slider, int end, const Eigen::VectorXd& x) const {
  const int k = trial_[slider];
  const int next = k + (end == 0 ? -1 : +1);
  if (next < 0 || next >= def_->numElements()) return false;
  const Vec3 xs = nodePos(x, def_->sliders[slider]);
  const Vec3 ta = nodePos(x, def_->chain[k + 1 - end]) - xs;
  const Vec3 tc = nodePos(x, def_->chain[end == 0 ? k - 1 : k + 2]) - xs;
  const double na = ta.norm(), nc = tc.norm();
  return na > 0.0 && nc > 0.0 && ta.dot(tc) < kernels::kPassageFoldCosine * na * nc;
}

int SlidingGroupState::notePassages(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) {
  int passed = 0;
  // The gain at x + dx from the four nodes it reads (movedBy), not the whole vector: forming it
  // for every group on every step was a full vector pass per group (9-10 % of the C-9's explicit
  // step with 28 groups), and still 2.5 % where only a slider near a node formed it.
  const auto moved = movedBy(x, dx);
  for (size_t s = 0; s < trial_.size(); ++s) {
    if (driven_[s] || pendingHandover_[s] != 0) continue;
    const int k = trial_[s];
    const int n3 = def_->sliders[s];
    for (int end = 0; end < 2; ++end) {
      const int ni = def_->chain[k + end];
      const Vec3 d = nodePos(x, n3) - nodePos(x, ni);
      const Vec3 delta = nodePos(dx, n3) - nodePos(dx, ni);
      double transfer = 0.0;
      if (d.dot(d + delta) >= 0.0) {
        // Not head on: beside the node? Delta from >= 0 to < 0, near the node (far from it a
        // sharply folded line has Delta ~ 0 of either sign, and nothing is passing).
        // Near first: the gain's four lengths only for a slider by the node (rare).
        const double capture = kernels::kPassageCapture * ref_[k];
        if (!(d.norm() < capture || (d + delta).norm() < capture)) continue;
        const double g0 = handoverGain(static_cast<int>(s), end, x);
        if (!(g0 >= 0.0)) continue;
        if (!foldOpen(static_cast<int>(s), end, x)) continue;
        const double g1 = gainAt(*def_, k, static_cast<int>(s), end, moved);
        if (!(g1 < 0.0)) continue;
        // Where Delta = 0 (positions linear over the step).
        const double f = g0 / (g0 - g1);
        transfer = handoverTransfer(static_cast<int>(s), end, x + f * dx);
      }
      pendingHandover_[s] = end == 0 ? -1 : +1;
      pendingTransfer_[s] = transfer;
      ++passed;
      break;
    }
  }
  return passed;
}

bool SlidingGroupState::passedBeside(int slider, int end, const Eigen::VectorXd& x,
                                     double& transfer) const {
  if (hasFriction(slider) || driven_[slider]) return false;
  const int k = trial_[slider];
  const double band = kernels::kArrivalFraction * ref_[k];
  // From clearly on the node's side at the step's start (a folded line with Delta ~ 0 throughout
  // never qualifies) ...
  if (!(committedGain_[end][slider] > band)) return false;
  // Near the node first (one length), the fold's two after it: a slider is far from both its
  // element's nodes on most steps.
  const Vec3 xs = nodePos(x, def_->sliders[slider]);
  const double li = (xs - nodePos(x, def_->chain[k + end])).norm();
  if (!(li < kernels::kPassageCapture * ref_[k])) return false;
  if (!foldOpen(slider, end, x)) return false;
  // ... to within the band or beyond it now.
  if (!(handoverGain(slider, end, x) <= band)) return false;
  transfer = handoverTransfer(slider, end, x);
  return true;
}

double SlidingGroupState::handoverTransfer(int slider, int end, const Eigen::VectorXd& x) const {
  const int k = trial_[slider];
  const Vec3 xs = nodePos(x, def_->sliders[slider]);
  const Vec3 xi = nodePos(x, def_->chain[k + end]), xa = nodePos(x, def_->chain[k + 1 - end]);
  // The element's length now (a -> slider -> i) and as the cable a -> i it becomes: the
  // reference length that keeps its strain, L (l_now - l_then) / l_now (uniform strain).
  const double now = (xa - xs).norm() + (xs - xi).norm(), then = (xa - xi).norm();
  return now > 0.0 ? std::max(0.0, ref_[k] * (now - then) / now) : 0.0;
}

bool SlidingGroupState::arriveAtNodes(const Model& model, Eigen::VectorXd& x, double radiusFraction,
                                      double separationFraction, bool immediate) {
  bool changed = false;
  for (size_t s = 0; s < trial_.size(); ++s) {
    const int k = trial_[s];
    // One hand-over per step: not after a free one at the step's start.
    if (pendingHandover_[s] != 0 || (!immediate && k != committed_[s])) continue;
    handoverAtCommit_[s] = 0;
    const int n3 = def_->sliders[s];
    for (int end = 0; end < 2; ++end) {
      const int ni = def_->chain[k + end];
      const int next = k + (end == 0 ? -1 : +1);
      const double dist = (nodePos(x, n3) - nodePos(x, ni)).norm();
      const double radius =
          hasFriction(static_cast<int>(s)) ? kernels::kFrictionArrivalFraction : radiusFraction;
      if (next < 0 || next >= def_->numElements()) continue;  // the chain ends here
      if (dist > radius * ref_[k] || dist >= committedDistance_[end][s]) {
        // Not at the node (or not approaching it): passed beside it?
        double transfer = 0.0;
        if (!passedBeside(static_cast<int>(s), end, x, transfer)) continue;
        if (immediate) {
          pendingHandover_[s] = end == 0 ? -1 : +1;
          pendingTransfer_[s] = transfer;
        } else {
          handoverAtCommit_[s] = end == 0 ? -1 : +1;
          transferAtCommit_[s] = transfer;
        }
        changed = true;
        break;
      }
      // Node and slider are placed a hair apart, the node on the side of the element being
      // left, at kSeparation (outside the apex radius): the new element's short part then starts
      // with its true direction along the cable instead of an apex where any direction goes.
      const int far = def_->chain[k + 1 - end];
      const double sep = separationFraction * ref_[k];
      const Vec3 back = (nodePos(x, far) - nodePos(x, n3)).normalized();
      bool nodeFree = true;
      for (int c = 0; c < 3; ++c) nodeFree &= !model.constraint[ni].fixed[c];
      if (nodeFree) {
        x.segment<3>(3 * ni) = nodePos(x, n3) + sep * back;
      } else {
        // A fixed node: the slider moves just past it, into the neighbouring element.
        const Vec3 ahead = (nodePos(x, def_->chain[next + 1 - end]) - nodePos(x, ni)).normalized();
        for (int c = 0; c < 3; ++c)
          if (!model.constraint[n3].fixed[c]) x[3 * n3 + c] = x[3 * ni + c] + sep * ahead[c];
      }
      (immediate ? pendingHandover_ : handoverAtCommit_)[s] = end == 0 ? -1 : +1;
      changed = true;
      break;
    }
  }
  return changed;
}

bool SlidingGroupState::hasDriven() const {
  return std::any_of(driven_.begin(), driven_.end(), [](char d) { return d != 0; });
}

int SlidingGroupState::crossDriven(const Model& model, const Eigen::VectorXd& from,
                                   Eigen::VectorXd& to, double separationFraction) {
  int changed = 0;
  const int nEl = def_->numElements();
  for (size_t s = 0; s < trial_.size(); ++s) {
    if (!driven_[s]) continue;
    auto takenByOther = [&](int k) {
      for (size_t o = 0; o < trial_.size(); ++o)
        if (o != s && trial_[o] == k) return true;
      return false;
    };
    const int n3 = def_->sliders[s];
    const int start = trial_[s] + pendingHandover_[s];
    int k = start, came = 0;
    double lastDistance = std::numeric_limits<double>::infinity();
    for (bool moved = true; moved;) {
      moved = false;
      for (int end = 0; end < 2 && !moved; ++end) {
        const int dir = end == 0 ? -1 : +1, next = k + dir;
        if (dir == -came || next < 0 || next >= nEl || takenByOther(next)) continue;
        const int ni = def_->chain[k + end], far = def_->chain[k + 1 - end];
        const Vec3 d0 = nodePos(from, n3) - nodePos(from, ni);
        const Vec3 d1 = nodePos(to, n3) - nodePos(to, ni);
        // The part turns round (slider and node met on the way), or the slider leaves the node
        // it sat on away from the element's other node.
        const bool passes = d0.squaredNorm() > 0.0
                                ? d0.dot(d1) < 0.0
                                : d1.dot(nodePos(from, far) - nodePos(from, ni)) < 0.0;
        if (!passes) continue;
        bool nodeFree = true;
        for (int c = 0; c < 3; ++c) nodeFree &= !model.constraint[ni].fixed[c];
        if (nodeFree) {
          const double dist =
              std::min(std::max(d1.norm(), separationFraction * ref_[k]), 0.5 * lastDistance);
          const Vec3 back = (nodePos(to, far) - nodePos(to, n3)).normalized();
          to.segment<3>(3 * ni) = nodePos(to, n3) + dist * back;
          lastDistance = dist;
        }
        k = next, came = dir, moved = true;
      }
    }
    if (k != start) {
      pendingHandover_[s] = k - trial_[s];
      ++changed;
    }
  }
  return changed;
}

void SlidingGroupState::commit(const Eigen::VectorXd& x) {
  ensureSplits(x);
  for (size_t s = 0; s < trial_.size(); ++s) {
    const int k = trial_[s] + handoverAtCommit_[s];
    if (hasFriction(static_cast<int>(s))) friction_.keepConvergedSplit(static_cast<int>(s));
    if (handoverAtCommit_[s] != 0 && k >= 0 && k < def_->numElements()) {
      carryMaterial(trial_[s], k, transferAtCommit_[s]);  // F12b
      trial_[s] = k;
      friction_.startCommittedElement(static_cast<int>(s), uniformSplit(static_cast<int>(s), k, x));
    }
    handoverAtCommit_[s] = 0;
    transferAtCommit_[s] = 0.0;
  }
  friction_.commit();
  refCommitted_ = ref_;
  // Nodes passed by the committed step (not the trial changes a Newton solve made and undid).
  for (size_t s = 0; s < trial_.size(); ++s) handovers_ += std::abs(trial_[s] - committed_[s]);
  committed_ = trial_;
  for (int end = 0; end < 2; ++end) {
    committedDistance_[end].resize(trial_.size());
    for (size_t s = 0; s < trial_.size(); ++s)
      committedDistance_[end][s] =
          (nodePos(x, def_->sliders[s]) - nodePos(x, def_->chain[trial_[s] + end])).norm();
    committedGain_[end].resize(trial_.size());
    for (size_t s = 0; s < trial_.size(); ++s)
      committedGain_[end][s] = handoverGain(static_cast<int>(s), end, x);
  }
  std::fill(pendingHandover_.begin(), pendingHandover_.end(), 0);
  std::fill(pendingTransfer_.begin(), pendingTransfer_.end(), 0.0);
}

void SlidingGroupState::revert() {
  trial_ = committed_;
  if (ref_ != refCommitted_) setRefLengths(refCommitted_);
  std::fill(pendingTransfer_.begin(), pendingTransfer_.end(), 0.0);
  friction_.revert();
  std::fill(pendingHandover_.begin(), pendingHandover_.end(), 0);
  std::fill(handoverAtCommit_.begin(), handoverAtCommit_.end(), 0);
  std::fill(transferAtCommit_.begin(), transferAtCommit_.end(), 0.0);
}

double SlidingGroupState::materialCoordinate(int slider, const Eigen::VectorXd& x) const {
  const int k = trial_[slider];
  if (hasFriction(slider)) return cumulativeRef_[k] + friction_.splitStart(slider);
  const double offset =
      kernels::sliderReferenceOffset(nodePos(x, def_->chain[k]), nodePos(x, def_->chain[k + 1]),
                                     nodePos(x, def_->sliders[slider]), ref_[k]);
  return cumulativeRef_[k] + offset;
}

double SlidingGroupState::uniformSplit(int slider, int element, const Eigen::VectorXd& x) const {
  return kernels::sliderReferenceOffset(nodePos(x, def_->chain[element]),
                                        nodePos(x, def_->chain[element + 1]),
                                        nodePos(x, def_->sliders[slider]), ref_[element]);
}

void SlidingGroupState::ensureSplits(const Eigen::VectorXd& x) {
  if (friction_.initialised()) return;
  std::vector<double> uniform(trial_.size());
  for (size_t s = 0; s < trial_.size(); ++s)
    uniform[s] = uniformSplit(static_cast<int>(s), committed_[s], x);
  friction_.initialise(uniform);
}

void SlidingGroupState::save(History& h) const {
  h.put(trial_);
  h.put(committed_);
  for (const auto& d : committedDistance_) h.put(d);
  h.put(pendingHandover_);
  h.put(handoverAtCommit_);
  h.put(static_cast<std::int64_t>(handovers_));
  friction_.saveSplits(h);
  h.put(pendingTransfer_);
  h.put(transferAtCommit_);
  for (const auto& d : committedGain_) h.put(d);
  h.put(ref_);
  h.put(refCommitted_);
  friction_.saveStates(h);
}

void SlidingGroupState::load(HistoryReader& h) {
  const size_t n = trial_.size();
  const int last = def_->numElements() - 1;
  trial_ = h.ints(n, 0, last);
  committed_ = h.ints(n, 0, last);
  for (auto& d : committedDistance_) d = h.reals(n);
  pendingHandover_ = h.ints(n, -1, 1);
  handoverAtCommit_ = h.ints(n, -1, 1);
  handovers_ = static_cast<long>(h.integer(0, std::numeric_limits<std::int64_t>::max()));
  friction_.loadSplits(h);
  pendingTransfer_ = h.reals(n);
  transferAtCommit_ = h.reals(n);
  for (auto& d : committedGain_) d = h.reals(n);
  for (double m : transferAtCommit_)
    if (!(m >= 0.0) || !std::isfinite(m)) h.fail("transfer at commit not a length");
  const size_t nEl = def_->refLength.size();
  std::vector<double> ref = h.reals(nEl), committed = h.reals(nEl);
  // Each positive, and together the chain's length: material moves between elements, never in or
  // out (F12b).
  double total = 0.0;
  for (double L : def_->refLength) total += L;
  for (const auto* r : {&ref, &committed}) {
    double sum = 0.0;
    for (double L : *r) {
      if (!(L > 0.0) || !std::isfinite(L)) h.fail("element reference length not positive");
      sum += L;
    }
    if (!(std::abs(sum - total) <= 1e-9 * total))
      h.fail("element reference lengths changed the chain");
  }
  for (double m : pendingTransfer_)
    if (!(m >= 0.0) || !std::isfinite(m)) h.fail("pending transfer not a length");
  setRefLengths(ref);
  refCommitted_ = committed;
  friction_.loadStates(h);
  for (size_t s = 0; s < n; ++s) {
    const double split = friction_.splitStart(static_cast<int>(s));
    if (split < 0.0 || split > ref_[trial_[s]] || !std::isfinite(split))
      h.fail("slider split outside its element");
  }
}

}  // namespace chute
