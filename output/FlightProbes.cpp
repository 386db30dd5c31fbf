#include "FlightProbes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "kernels/CableKernel.hpp"
#include "terms/CanopyFlowTerm.hpp"
#include "terms/sliding/SlidingGroupTerm.hpp"

namespace chute {

namespace {
Vec3 at(const Eigen::VectorXd& x, int n) {
  return x.segment<3>(3 * n);
}
bool inSets(const std::vector<int>& sets, int set) {
  return std::find(sets.begin(), sets.end(), set) != sets.end();
}
// Calls f(from, to, N) for every straight part of the lines of `sets` at x: a cable, an inactive
// sliding element, or one part of an active one (end 1 -> slider, slider -> end 2).
template <class F>
void forLineParts(const Model& m, const StructuralSystem& sys, const std::vector<int>& sets,
                  const Eigen::VectorXd& x, double t, F&& f) {
  for (const auto& c : m.cables) {
    if (!inSets(sets, c.set) || m.lineSets[c.set].cutBy(t)) continue;
    const auto r = kernels::cableForce(at(x, c.a), at(x, c.b), c.L, m.materials[c.material], false);
    f(c.a, c.b, r.axialForce);
  }
  const auto& groups = sys.termList().slidingGroups();
  for (size_t g = 0; g < m.groups.size(); ++g) {
    const auto& def = m.groups[g];
    if (!inSets(sets, def.set) || m.lineSets[def.set].cutBy(t)) continue;
    const auto& st = groups[g]->state();
    for (int k = 0; k < def.numElements(); ++k) {
      const int n1 = def.chain[k], n2 = def.chain[k + 1];
      const auto parts = groups[g]->activeParts(k, x);
      const int s = st.sliderOfElement(k);
      if (s < 0) {
        f(n1, n2, parts.N1);
      } else {
        f(n1, def.sliders[s], parts.N1);
        f(def.sliders[s], n2, parts.N2);
      }
    }
  }
}
}  // namespace

Vec3 linePull(const Model& m, const StructuralSystem& sys, int node, const std::vector<int>& sets,
              const Eigen::VectorXd& x, double t) {
  Vec3 pull = Vec3::Zero();
  forLineParts(m, sys, sets, x, t, [&](int a, int b, double N) {
    if (a != node && b != node) return;
    const Vec3 d = at(x, a == node ? b : a) - at(x, node);
    const double l = d.norm();
    if (l > 0.0 && N > 0.0) pull += N * d / l;
  });
  return pull;
}

double largestLineForce(const Model& m, const StructuralSystem& sys, const std::vector<int>& sets,
                        const Eigen::VectorXd& x, double t) {
  double largest = 0.0;
  forLineParts(m, sys, sets, x, t, [&](int, int, double N) { largest = std::max(largest, N); });
  return largest;
}

std::vector<double> canopyFigures(const Model& m, const StructuralSystem& sys, int membraneSet,
                                  const StructuralState& s) {
  const CanopyFlowTerm* term = nullptr;
  for (const auto* c : sys.termList().canopyFlows())
    if (c->set() == membraneSet) term = c;
  if (!term) return std::vector<double>(10, std::nan(""));
  const auto f = term->figuresAt(s.x, s.v);
  const Vec3 down = m.hasGravity() ? Vec3(m.gravity.normalized()) : Vec3(-Vec3::UnitZ());
  const double airspeed = std::sqrt(2.0 * f.dynamicPressure / m.air.density);
  const Vec3 canopyVelocity = m.air.wind - airspeed * f.flowDirection;
  const double cosSwing = std::clamp(f.axis.dot(-down), -1.0, 1.0);
  return {f.volume,      2.0 * std::sqrt(f.projectedArea / std::numbers::pi),
          f.insideGauge, f.dynamicPressure,
          airspeed,      canopyVelocity.dot(down),
          f.inflow,      f.clothOutflow,
          f.ventOutflow, std::acos(cosSwing) * 180.0 / std::numbers::pi};
}

}  // namespace chute
