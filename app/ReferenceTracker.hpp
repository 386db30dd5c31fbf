#pragma once
// The comparison of a run with its case's independent reference ([reference], docs/case-files.md),
// one probe row at a time as the rows are written: nothing of the rows is kept (a run of any
// length compares in constant memory). A small value: the output copies it where a run may be cut
// back to (the last good state of an unstable run).
#include <optional>
#include <string>
#include <vector>

#include "Probes.hpp"
#include "case/CaseSpec.hpp"
#include "verification/References.hpp"

namespace chute {

struct ReferenceError {
  std::string kind, probe;
  double maxError = 0.0;    // max over output times of |x - x_ref|
  double motionSize = 0.0;  // max over output times of |x_ref(t) - x_ref(0)|
  double relative() const { return motionSize > 0 ? maxError / motionSize : maxError; }
};

class ReferenceTracker {
 public:
  // The tracker of a case with a [reference] (nullopt without one).
  static std::optional<ReferenceTracker> forCase(const CaseSpec& spec, const ProbeSet& probes);
  // A probe row (the ProbeSet's columns) at time t; rows come in ascending time.
  void add(double t, const std::vector<double>& row);
  // The error over the rows so far (hencky: of the last row, the static run's answer).
  ReferenceError result() const;

 private:
  ReferenceTracker() = default;
  Vec3 expectedAt(double t);
  const CaseSpec* spec_ = nullptr;
  int node_ = -1, offset_ = 0;
  ReferenceError error_;
  bool first_ = true;
  Vec3 firstExpected_ = Vec3::Zero();
  std::optional<verification::BeadEllipseReference> bead_;
  verification::BeadEllipseReference::Walk walk_;
  std::optional<Vec3> last_;  // hencky: the last row's position
};

}  // namespace chute
