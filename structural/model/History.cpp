#include "model/History.hpp"

#include <cmath>
#include <cstring>

namespace chute {

void History::put(const std::vector<double>& v) {
  put(static_cast<std::int64_t>(v.size()));
  reals_.insert(reals_.end(), v.begin(), v.end());
}

void History::put(const std::vector<int>& v) {
  put(static_cast<std::int64_t>(v.size()));
  ints_.insert(ints_.end(), v.begin(), v.end());
}

void History::put(const Eigen::VectorXd& v) {
  put(static_cast<std::int64_t>(v.size()));
  reals_.insert(reals_.end(), v.data(), v.data() + v.size());
}

History History::fromRecords(std::vector<double> reals, std::vector<std::int64_t> ints) {
  History h;
  h.reals_ = std::move(reals);
  h.ints_ = std::move(ints);
  return h;
}

bool History::operator==(const History& o) const {
  if (reals_.size() != o.reals_.size() || ints_ != o.ints_) return false;
  for (size_t k = 0; k < reals_.size(); ++k) {
    // Bit for bit: NaN payloads and signed zeros included.
    if (std::memcmp(&reals_[k], &o.reals_[k], sizeof(double)) != 0) return false;
  }
  return true;
}

void HistoryReader::fail(const std::string& what) const {
  throw HistoryError(owner_ + ": " + what);
}

double HistoryReader::real() {
  if (r_ >= h_->reals().size()) fail("history record too short");
  return h_->reals()[r_++];
}

double HistoryReader::finiteReal() {
  const double v = real();
  if (!std::isfinite(v)) fail("history value not finite");
  return v;
}

std::int64_t HistoryReader::integer(std::int64_t min, std::int64_t max) {
  if (i_ >= h_->ints().size()) fail("history record too short");
  const std::int64_t v = h_->ints()[i_++];
  if (v < min || v > max)
    fail("history value " + std::to_string(v) + " outside [" + std::to_string(min) + ", " +
         std::to_string(max) + "]");
  return v;
}

std::vector<double> HistoryReader::reals(size_t expectedSize) {
  const auto n = static_cast<size_t>(integer(0, static_cast<std::int64_t>(h_->reals().size())));
  if (n != expectedSize) fail("history vector of the wrong size");
  if (r_ + n > h_->reals().size()) fail("history record too short");
  std::vector<double> out(h_->reals().begin() + static_cast<long>(r_),
                          h_->reals().begin() + static_cast<long>(r_ + n));
  r_ += n;
  return out;
}

std::vector<int> HistoryReader::ints(size_t expectedSize, int min, int max) {
  const auto n = static_cast<size_t>(integer(0, static_cast<std::int64_t>(h_->ints().size())));
  if (n != expectedSize) fail("history vector of the wrong size");
  std::vector<int> out(n);
  for (size_t k = 0; k < n; ++k) out[k] = static_cast<int>(integer(min, max));
  return out;
}

Eigen::VectorXd HistoryReader::vector(long expectedSize) {
  const auto n = integer(0, static_cast<std::int64_t>(h_->reals().size()));
  if (expectedSize >= 0 && n != 0 && n != expectedSize) fail("history vector of the wrong size");
  if (r_ + static_cast<size_t>(n) > h_->reals().size()) fail("history record too short");
  Eigen::VectorXd v = Eigen::Map<const Eigen::VectorXd>(h_->reals().data() + r_, n);
  r_ += static_cast<size_t>(n);
  return v;
}

void HistoryReader::finish() const {
  if (r_ != h_->reals().size() || i_ != h_->ints().size()) fail("history record too long");
}

}  // namespace chute
