// [loads]: gravity, pressure, line drag and face drag.
#include <cmath>
#include <string>

#include "case/CaseText.hpp"
#include "case/MeshGroups.hpp"
#include "case/sections/SectionLookup.hpp"
#include "case/sections/Sections.hpp"
#include "terms/CanopyFlowTerm.hpp"

namespace chute::caseio {

namespace {
// FL7's base pressure coefficient, calibrated once on the generated 5 m solid flat circular
// canopy's drag coefficient (docs/flight.md, "Calibration").
constexpr double kCalibratedBasePressure = -0.83;

// The membrane set a load names under key "membranes" (one lookup, one message for every load).
int membraneSetOf(const Model& m, TomlTable& t) {
  const std::string set = t.string("membranes");
  for (size_t k = 0; k < m.membraneSets.size(); ++k)
    if (m.membraneSets[k].name == set) return static_cast<int>(k);
  t.fail("membranes", "unknown membrane set '" + set + "'" +
                          nameSuggestion(set, membraneSetNames(m), "membrane sets"));
}
}  // namespace

void readLoads(Model& m, const MeshImport* mesh, TomlTable l) {
  m.gravity = l.vec3("gravity", Vec3::Zero());
  for (auto& t : l.tables("pressure")) {
    PressureLoadDef p;
    p.set = membraneSetOf(m, t);
    p.pressure = t.number("pressure");
    p.rampTime = t.nonNegative("ramp_time", 0.0);
    if (t.has("element_factors")) {
      const auto& arr = toml::find(t.raw(), "element_factors");
      if (!arr.is_array()) t.fail("element_factors", "expected an array of numbers");
      for (const auto& v : arr.as_array()) {
        if (!v.is_floating() && !v.is_integer())
          t.failAt(v, "element_factors", "expected a number");
        const double f = v.is_floating() ? v.as_floating() : static_cast<double>(v.as_integer());
        if (!std::isfinite(f)) t.failAt(v, "element_factors", "must be finite");
        p.elementFactor.push_back(f);
      }
      long count = 0;
      for (const auto& e : m.membranes) count += e.set == p.set;
      if (static_cast<long>(p.elementFactor.size()) != count)
        t.fail("element_factors", "needs one factor per element of '" + m.membraneSets[p.set].name +
                                      "' (" + std::to_string(count) + ")");
    }
    t.finish();
    m.pressures.push_back(p);
  }
  for (auto& t : l.tables("drag")) {
    DragLoadDef d;
    if (t.has("group")) {
      d.edges = meshEdges(mesh, t);  // the 2-node elements of a 1-D physical group
    } else if (t.has("edge")) {
      // Edges between consecutive nodes of a node set (e.g. "bag.xmax", a disk's "rim").
      const std::string edge = t.string("edge");
      auto it = m.nodeSets.find(edge);
      if (it == m.nodeSets.end() || it->second.size() < 2)
        t.fail("edge",
               "no node set '" + edge + "' of two or more nodes" +
                   (it == m.nodeSets.end() ? nameSuggestion(edge, nodeSetNames(m), "node sets")
                                           : std::string()));
      const auto& ns = it->second;
      for (size_t k = 0; k + 1 < ns.size(); ++k) d.edges.push_back({ns[k], ns[k + 1]});
      if (t.boolean("closed", false)) d.edges.push_back({ns.back(), ns.front()});
    } else {
      const std::string set = t.string("set");
      for (size_t k = 0; k < m.lineSets.size(); ++k)
        if (m.lineSets[k].name == set) d.lineSet = static_cast<int>(k);
      if (d.lineSet < 0)
        t.fail("set", "unknown cable set or sliding group '" + set + "'" +
                          nameSuggestion(set, lineSetNames(m, true, true), "line sets"));
    }
    const double diameter = t.positive("diameter");
    const double cd = t.positive("cd");
    const double rho = t.positive("air_density");
    d.coefficient = 0.5 * rho * cd * diameter;
    d.wind = t.vec3("wind", Vec3::Zero());
    t.finish();
    m.drags.push_back(d);
  }
  // [[loads.face_drag]]: drag on the faces of a membrane set (docs/formulation.md FD1).
  for (auto& t : l.tables("face_drag")) {
    FaceDragLoadDef d;
    d.set = membraneSetOf(m, t);
    const double cd = t.positive("cd");
    const double rho = t.positive("air_density");
    d.coefficient = 0.5 * rho * cd;
    d.wind = t.vec3("wind", Vec3::Zero());
    d.steadySubtracted = t.boolean("subtract_steady", false);
    t.finish();
    m.faceDrags.push_back(d);
  }
  // [[loads.canopy_flow]]: loads from the relative airflow on a canopy (docs/flight.md).
  for (auto& t : l.tables("canopy_flow")) {
    if (!m.air.given) t.fail("membranes", "loads from the airflow need the air: an [air] table");
    CanopyFlowDef d;
    d.set = membraneSetOf(m, t);
    const std::string set = m.membraneSets[d.set].name;
    for (const auto& other : m.canopyFlows)
      if (other.set == d.set) t.fail("membranes", "'" + set + "' has loads from the airflow twice");
    d.baseCoefficient = t.number("base_pressure", kCalibratedBasePressure);
    if (!(d.baseCoefficient <= 0.0 && d.baseCoefficient >= -3.0))
      t.fail("base_pressure", "a wake's base pressure coefficient is in [-3, 0]");
    d.discharge = t.positive("discharge", d.discharge);
    if (d.discharge > 1.0) t.fail("discharge", "a discharge coefficient is at most 1");
    const double u = t.nonNegative("permeability", 0.0);
    if (u > 0.0) {
      const double dp = t.positive("permeability_pressure");
      const double inertial = t.nonNegative("permeability_inertial", 0.0);
      try {
        d.cloth = kernels::ClothPermeability::fromTest(u, dp, inertial);
      } catch (const std::invalid_argument& e) {
        t.fail("permeability_inertial", e.what());
      }
    } else {
      t.notUsed({"permeability_pressure", "permeability_inertial"}, "without permeability");
    }
    d.normalDrag = t.nonNegative("normal_drag", d.normalDrag);
    d.apparentMass = t.nonNegative("apparent_mass", d.apparentMass);
    d.gamma = t.positive("gamma", d.gamma);
    d.volumeFloor = t.positive("volume_floor", d.volumeFloor);
    if (d.volumeFloor > 1.0) t.fail("volume_floor", "must be in (0, 1]");
    d.initialInsideGauge = t.nonNegative("initial_inside_pressure", 0.0);
    if (m.air.pressure > 0.0 && d.initialInsideGauge > m.air.pressure)
      t.fail("initial_inside_pressure", "more than the ambient pressure over it is not a canopy's");
    t.finish();
    m.canopyFlows.push_back(d);
    try {
      CanopyFlowTerm check(m, static_cast<int>(m.canopyFlows.size()) - 1);
    } catch (const std::invalid_argument& e) {
      m.canopyFlows.pop_back();
      t.fail("membranes", "'" + set + "' cannot carry loads from the airflow: " + e.what());
    }
  }
  l.finish();
}

}  // namespace chute::caseio
