#include "Probes.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "FlightProbes.hpp"
#include "kernels/CableKernel.hpp"
#include "kernels/SliderFriction.hpp"
#include "terms/MembraneTerm.hpp"
#include "terms/sliding/SlidingGroupTerm.hpp"

namespace chute {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}

ProbeSet::ProbeSet(const Model& model, std::vector<ProbeSpec> probes)
    : model_(&model), probes_(std::move(probes)) {
  int off = 0;
  for (const auto& p : probes_) {
    offset_.push_back(off);
    off += static_cast<int>(p.columns().size());
  }
}

std::vector<std::string> ProbeSet::columns() const {
  std::vector<std::string> c;
  for (const auto& p : probes_)
    for (auto& q : p.columns()) c.push_back(q);
  return c;
}

namespace {
// Axial force and strain of element `element` of line set `set` (cables first, then groups).
std::pair<double, double> lineForce(const Model& m, const StructuralSystem& sys, int set,
                                    int element, const Eigen::VectorXd& x, double t) {
  if (m.lineSets[set].cutBy(t)) return {0.0, 0.0};  // a cut set carries nothing
  auto at = [&](int n) { return Vec3(x.segment<3>(3 * n)); };
  int k = 0;
  for (const auto& c : m.cables) {
    if (c.set != set) continue;
    if (k++ == element) {
      const auto r = kernels::cableForce(at(c.a), at(c.b), c.L, m.materials[c.material], false);
      return {r.axialForce, r.strain};
    }
  }
  for (size_t g = 0; g < m.groups.size(); ++g) {
    const auto& def = m.groups[g];
    if (def.set != set) continue;
    // Active elements with friction: part 1 (end 1 -> slider); see slider_friction for both.
    const auto parts = sys.termList().slidingGroups()[g]->activeParts(element, x);
    return {parts.N1, parts.strain1};
  }
  throw std::logic_error("line_force probe: element not found");
}

Vec3 centroid(const std::vector<int>& nodes, const Eigen::VectorXd& x) {
  Vec3 c = Vec3::Zero();
  for (int n : nodes) c += x.segment<3>(3 * n);
  return c / static_cast<double>(nodes.size());
}

// Mean, least and largest distance of `nodes` from the axis through the centroids of axisFrom
// and axisTo (a canopy's skirt radius about the line confluence -> vent).
std::array<double, 3> radiusAboutAxis(const ProbeSpec& p, const Eigen::VectorXd& x) {
  const Vec3 a = centroid(p.axisFrom, x);
  const Vec3 axis = centroid(p.axisTo, x) - a;
  const Vec3 e = axis.norm() > 0.0 ? Vec3(axis.normalized()) : Vec3::UnitZ();
  double sum = 0.0, lo = kInf, hi = 0.0;
  for (int n : p.nodes) {
    const Vec3 d = x.segment<3>(3 * n) - a;
    const double r = (d - d.dot(e) * e).norm();
    sum += r;
    lo = std::min(lo, r);
    hi = std::max(hi, r);
  }
  return {sum / static_cast<double>(p.nodes.size()), lo, hi};
}
}  // namespace

std::vector<double> ProbeSet::evaluate(StructuralSystem& sys, const StructuralState& s,
                                       const EquilibriumPoint& eq, const EnergyBreakdown& e,
                                       const ProbeBalance& balance) const {
  std::vector<double> out;
  Eigen::VectorXd reaction;  // the supports' forces at eq, when a probe asks for them
  for (const auto& p : probes_)
    if (p.kind == ProbeKind::SupportForce && reaction.size() == 0)
      reaction = sys.nodalForces(eq.x, eq.v, eq.a, eq.t, true).reaction;
  for (const auto& p : probes_) {
    if (p.kind == ProbeKind::NodePosition || p.kind == ProbeKind::NodeVelocity) {
      const Eigen::VectorXd& v = p.kind == ProbeKind::NodePosition ? s.x : s.v;
      for (int k = 0; k < 3; ++k) out.push_back(v[3 * p.node + k]);
    } else if (p.kind == ProbeKind::Slider) {
      const auto& st = sys.termList().slidingGroups()[p.group]->state();
      out.push_back(st.materialCoordinate(p.slider, s.x));
      out.push_back(st.activeElement(p.slider));
    } else if (p.kind == ProbeKind::SliderFriction) {
      // Committed friction state (docs/friction.md); a frictionless slider reads as stuck-free:
      // state 0, slip rate 0, its (equal) part forces, and the wrap angle of its geometry (FR3).
      const auto& st = sys.termList().slidingGroups()[p.group]->state();
      const auto parts =
          sys.termList().slidingGroups()[p.group]->activeParts(st.activeElement(p.slider), eq.x);
      const auto& f = st.friction(p.slider);
      const bool fr = st.hasFriction(p.slider);
      out.push_back(fr ? static_cast<double>(f.state) : 0.0);
      out.push_back(fr ? f.slipRate : 0.0);
      out.push_back(parts.N1 > 0.0 ? parts.N2 / parts.N1 : (parts.N2 > 0.0 ? kInf : 1.0));
      if (fr) {
        out.push_back(f.wrapAngle);
      } else {
        const auto& def = st.def();
        const int k = st.activeElement(p.slider);
        auto at = [&](int n) { return Vec3(eq.x.segment<3>(3 * n)); };
        out.push_back(kernels::wrapAngle(at(def.chain[k]), at(def.chain[k + 1]),
                                         at(def.sliders[p.slider]), st.refLength(k))
                          .beta);
      }
      out.push_back(parts.N1);
      out.push_back(parts.N2);
    } else if (p.kind == ProbeKind::Energy) {
      out.insert(out.end(), {e.kinetic, e.strain, e.gravity, e.total()});
    } else if (p.kind == ProbeKind::EnergyBalance) {
      out.insert(out.end(), {balance.work, balance.balance});
    } else if (p.kind == ProbeKind::MembraneStress) {
      // Principal second Piola-Kirchhoff stresses averaged over the elements at the node.
      Eigen::Vector2d S = Eigen::Vector2d::Zero();
      const auto* mt = sys.termList().membranes();
      if (mt) {
        const auto around = mt->elementsAt(p.node);
        for (int k : around) S += mt->elementStates()[k].principalStress;
        if (!around.empty()) S /= static_cast<double>(around.size());
      }
      out.push_back(S[0]);
      out.push_back(S[1]);
    } else if (p.kind == ProbeKind::Wrinkling) {
      // Fractions of the membrane elements taut, wrinkled and slack.
      double count[3] = {0, 0, 0};
      if (const auto* mt = sys.termList().membranes())
        for (const auto& st : mt->elementStates()) count[static_cast<int>(st.state)] += 1.0;
      const double n = std::max(1.0, count[0] + count[1] + count[2]);
      for (double c : count) out.push_back(c / n);
    } else if (p.kind == ProbeKind::EdgeAngle) {
      // Angle in degrees between the edge node -> node2 and the upward vertical (against gravity;
      // +z without gravity): 0 when node2 is straight above node, 90 when the edge is level.
      const Model& m = *model_;
      const Vec3 up = m.hasGravity() ? Vec3(-m.gravity.normalized()) : Vec3::UnitZ();
      const Vec3 d = s.x.segment<3>(3 * p.node2) - s.x.segment<3>(3 * p.node);
      const double c = std::clamp(d.dot(up) / std::max(d.norm(), 1e-300), -1.0, 1.0);
      out.push_back(std::acos(c) * 180.0 / M_PI);
    } else if (p.kind == ProbeKind::LineForce) {
      const auto [N, eps] = lineForce(*model_, sys, p.lineSet, p.element, eq.x, s.t);
      out.push_back(N);
      out.push_back(eps);
    } else if (p.kind == ProbeKind::SkirtRadius) {
      const auto r = radiusAboutAxis(p, s.x);
      out.insert(out.end(), r.begin(), r.end());
    } else if (p.kind == ProbeKind::SupportForce) {
      // The residual at the supported dofs: the force the structure puts on its supports
      // (docs/output.md, "reaction"), summed over the set.
      Vec3 f = Vec3::Zero();
      for (int n : p.nodes) f += reaction.segment<3>(3 * n);
      out.insert(out.end(), {f.x(), f.y(), f.z(), f.norm()});
    } else if (p.kind == ProbeKind::LinePull) {
      const Vec3 f = linePull(*model_, sys, p.node, p.lineSets, eq.x, s.t);
      out.insert(out.end(), {f.x(), f.y(), f.z(), f.norm()});
    } else if (p.kind == ProbeKind::LineForceMax) {
      out.push_back(largestLineForce(*model_, sys, p.lineSets, eq.x, s.t));
    } else if (p.kind == ProbeKind::Canopy) {
      const auto c = canopyFigures(*model_, sys, p.membraneSet, s);
      out.insert(out.end(), c.begin(), c.end());
    }
  }
  return out;
}

}  // namespace chute
