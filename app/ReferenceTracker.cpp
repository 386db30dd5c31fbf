#include "app/ReferenceTracker.hpp"

#include <algorithm>
#include <cmath>

#include "verification/HenckyReference.hpp"

namespace chute {

std::optional<ReferenceTracker> ReferenceTracker::forCase(const CaseSpec& spec,
                                                          const ProbeSet& probes) {
  if (!spec.reference) return std::nullopt;
  const auto& ref = *spec.reference;
  const Model& m = spec.model;
  ReferenceTracker t;
  t.spec_ = &spec;
  t.node_ = probes.probes()[ref.probe].node;
  t.offset_ = probes.columnOffset(ref.probe);
  t.error_.kind = std::string(referenceKindName(ref.kind));
  t.error_.probe = probes.probes()[ref.probe].name;
  if (ref.kind == ReferenceKind::BeadEllipse) {
    t.bead_.emplace(m.X[ref.anchor1], m.X[ref.anchor2], m.X[t.node_], m.gravity);
    t.walk_ = t.bead_->release();
  }
  return t;
}

Vec3 ReferenceTracker::expectedAt(double t) {
  const auto& ref = *spec_->reference;
  const Model& m = spec_->model;
  if (ref.kind == ReferenceKind::Pulley) {
    const Vec3 d = m.X[node_] - m.X[ref.pulley];
    const verification::PulleyReference p{ref.ropeLength, d.norm(), m.gravity.norm(),
                                          m.X[ref.pulley], d.normalized()};
    return p.endPosition(t);
  }
  if (ref.kind == ReferenceKind::FreeFall) return m.X[node_] + 0.5 * t * t * m.gravity;
  return bead_->walkTo(walk_, t);  // BeadEllipse
}

void ReferenceTracker::add(double t, const std::vector<double>& row) {
  const Vec3 x(row[offset_], row[offset_ + 1], row[offset_ + 2]);
  if (spec_->reference->kind == ReferenceKind::Hencky) {
    last_ = x;  // static: the final state is the answer
    return;
  }
  const Vec3 expected = expectedAt(t);
  if (first_) firstExpected_ = expected, first_ = false;
  error_.maxError = std::max(error_.maxError, (x - expected).norm());
  error_.motionSize = std::max(error_.motionSize, (expected - firstExpected_).norm());
}

ReferenceError ReferenceTracker::result() const {
  const auto& ref = *spec_->reference;
  if (ref.kind != ReferenceKind::Hencky || !last_) return error_;
  // Static: the final state against the Foeppl-Hencky centre deflection.
  const verification::HenckyReference h{ref.E, ref.nu, ref.thickness, std::abs(ref.pressure),
                                        ref.radius};
  const double w0 = h.centreDeflection();
  const Vec3 d = (ref.pressure > 0 ? 1.0 : -1.0) * ref.direction;
  ReferenceError e = error_;
  e.maxError = (*last_ - (spec_->model.X[node_] + w0 * d)).norm();
  e.motionSize = w0;
  return e;
}

}  // namespace chute
