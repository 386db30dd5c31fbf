#include "model/SlidingGroupState.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace chute {

namespace {
Vec3 nodePos(const Eigen::VectorXd& x, int n) { return x.segment<3>(3 * n); }
}  // namespace

SlidingGroupState::SlidingGroupState(const SlidingGroupDef& def)
    : def_(&def), trial_(def.initialActive), committed_(def.initialActive) {
  cumulativeRef_.assign(def.chain.size(), 0.0);
  for (int k = 0; k < def.numElements(); ++k)
    cumulativeRef_[k + 1] = cumulativeRef_[k] + def.refLength[k];
}

double SlidingGroupState::lengthMismatch(int slider, int element, const Eigen::VectorXd& x) const {
  const Vec3 xs = nodePos(x, def_->sliders[slider]);
  const double l = (xs - nodePos(x, def_->chain[element])).norm() +
                   (xs - nodePos(x, def_->chain[element + 1])).norm();
  return std::abs(l - def_->refLength[element]);
}

bool SlidingGroupState::isActive(int element) const { return sliderOfElement(element) >= 0; }

int SlidingGroupState::sliderOfElement(int element) const {
  for (size_t s = 0; s < trial_.size(); ++s)
    if (trial_[s] == element) return static_cast<int>(s);
  return -1;
}

void SlidingGroupState::setActiveElement(int slider, int element) {
  if (element < 0 || element >= def_->numElements())
    throw std::out_of_range("active element out of range in group " + def_->name);
  trial_[slider] = committed_[slider] = element;
}

int SlidingGroupState::search(const Eigen::VectorXd& x, SliderSearch kind) {
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
    double bestScore = lengthMismatch(static_cast<int>(s), best, x);
    if (kind == SliderSearch::NearestLength) {
      for (int k = 0; k < nEl; ++k) {
        if (k == best || takenByOther(k)) continue;
        const double score = lengthMismatch(static_cast<int>(s), k, x);
        if (score < bestScore) best = k, bestScore = score;
      }
    } else {
      // Walk to a neighbour while it fits better: the slider's material coordinate moves
      // continuously, so it can only leave its element through an end node.
      for (bool moved = true; moved;) {
        moved = false;
        for (int k : {best - 1, best + 1}) {
          if (k < 0 || k >= nEl || takenByOther(k)) continue;
          const double score = lengthMismatch(static_cast<int>(s), k, x);
          if (score < bestScore) {
            best = k, bestScore = score, moved = true;
            break;
          }
        }
      }
    }
    if (best != trial_[s]) {
      handoversTrial_ += std::abs(best - trial_[s]);
      trial_[s] = best;
      ++changed;
    }
  }
  return changed;
}

void SlidingGroupState::commit() {
  committed_ = trial_;
  handoversCommitted_ = handoversTrial_;
}

void SlidingGroupState::revert() {
  trial_ = committed_;
  handoversTrial_ = handoversCommitted_;
}

double SlidingGroupState::materialCoordinate(int slider, const Eigen::VectorXd& x) const {
  const int k = trial_[slider];
  const double offset = kernels::sliderReferenceOffset(
      nodePos(x, def_->chain[k]), nodePos(x, def_->chain[k + 1]),
      nodePos(x, def_->sliders[slider]), def_->refLength[k]);
  return cumulativeRef_[k] + offset;
}

}  // namespace chute
