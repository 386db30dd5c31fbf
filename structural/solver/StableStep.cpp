#include "solver/StableStep.hpp"

#include <cmath>
#include <limits>

namespace chute {

StableStepEstimate stableStep(const std::vector<double>& stiffness,
                              const std::vector<double>& nodalMass, const std::vector<char>& free) {
  StableStepEstimate out;
  double omega2 = 0.0;
  for (size_t i = 0; i < stiffness.size(); ++i) {
    if (!free[i] || !(nodalMass[i] > 0.0)) continue;
    const double w2 = stiffness[i] / nodalMass[i];
    if (w2 > omega2) omega2 = w2, out.node = static_cast<int>(i);
  }
  out.dt = omega2 > 0.0 ? 2.0 / std::sqrt(omega2) : std::numeric_limits<double>::infinity();
  return out;
}

double dampedStableStep(double undampedStep, double beta) {
  if (!(beta > 0.0) || !std::isfinite(undampedStep)) return undampedStep;
  const double omega = 2.0 / undampedStep;
  const double xi = 0.5 * beta * omega;
  // sqrt(1 + xi^2) - xi loses digits to cancellation once xi > 1 and is 0 in floating point
  // beyond ~1e8 (a step that would not move time): there its equal 1 / (sqrt(1 + xi^2) + xi).
  if (xi > 1.0) return undampedStep / (std::sqrt(1.0 + xi * xi) + xi);
  return undampedStep * (std::sqrt(1.0 + xi * xi) - xi);
}

}  // namespace chute
