// [output]: output intervals, [[output.probes]] and [output.vtu].
#include <algorithm>
#include <climits>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "case/CaseText.hpp"
#include "case/sections/SectionLookup.hpp"
#include "case/sections/Sections.hpp"

namespace chute {

const std::vector<ProbeKindInfo>& probeKinds() {
  static const std::vector<ProbeKindInfo> kinds{
      {ProbeKind::NodePosition, "node_position", {"x", "y", "z"}},
      {ProbeKind::NodeVelocity, "node_velocity", {"vx", "vy", "vz"}},
      {ProbeKind::Slider, "slider", {"s", "element"}},
      {ProbeKind::Energy, "energy", {"kinetic", "strain", "gravity", "total"}},
      {ProbeKind::EnergyBalance, "energy_balance", {"work", "balance"}},
      {ProbeKind::LineForce, "line_force", {"N", "strain"}},
      {ProbeKind::MembraneStress, "membrane_stress", {"S1", "S2"}},
      {ProbeKind::Wrinkling, "wrinkling", {"taut", "wrinkled", "slack"}},
      {ProbeKind::SliderFriction,
       "slider_friction",
       {"state", "slip_rate", "tension_ratio", "wrap_angle", "N1", "N2"}},
      {ProbeKind::SkirtRadius, "skirt_radius", {"mean", "min", "max"}},
      {ProbeKind::EdgeAngle, "edge_angle", {"angle"}},
      {ProbeKind::SupportForce, "support_force", {"fx", "fy", "fz", "magnitude"}},
      {ProbeKind::LinePull, "line_pull", {"fx", "fy", "fz", "magnitude"}},
      {ProbeKind::LineForceMax, "line_force_max", {"N"}},
      {ProbeKind::Canopy,
       "canopy",
       {"volume", "projected_diameter", "inside_pressure", "dynamic_pressure", "airspeed",
        "descent_speed", "inflow", "cloth_outflow", "vent_outflow", "swing"}},
  };
  return kinds;
}

const ProbeKindInfo& probeKindInfo(ProbeKind k) {
  for (const auto& info : probeKinds())
    if (info.kind == k) return info;
  throw std::logic_error("probeKindInfo: unknown kind");
}

std::vector<std::string> ProbeSpec::columns() const {
  std::vector<std::string> q;
  for (const char* quantity : probeKindInfo(kind).quantities) q.push_back(name + "." + quantity);
  return q;
}

namespace caseio {

namespace {

bool onAMembrane(const Model& m, int node) {
  for (const auto& e : m.membranes)
    for (int k = 0; k < e.numNodes; ++k)
      if (e.nodes[k] == node) return true;
  return false;
}

ProbeSpec readProbe(const Model& m, TomlTable t) {
  ProbeSpec p;
  p.name = t.string("name");
  // Probe names head the columns of probes.csv.
  if (p.name.empty() || std::any_of(p.name.begin(), p.name.end(), [](char ch) {
        return (ch >= 0 && ch < 32) || ch == ',' || ch == '"';
      }))
    t.fail("name", "must be non-empty, without commas, quotes or control characters");
  std::vector<std::string> names;
  for (const auto& info : probeKinds()) names.emplace_back(info.name);
  const std::string kind = t.choice("kind", "node_position", names);
  for (const auto& info : probeKinds())
    if (kind == info.name) p.kind = info.kind;
  const std::string why = "by a probe of kind \"" + kind + "\"";
  const bool atNode = p.kind == ProbeKind::NodePosition || p.kind == ProbeKind::NodeVelocity ||
                      p.kind == ProbeKind::MembraneStress || p.kind == ProbeKind::LinePull;
  const bool overLines = p.kind == ProbeKind::LinePull || p.kind == ProbeKind::LineForceMax;
  const bool atSlider = p.kind == ProbeKind::Slider || p.kind == ProbeKind::SliderFriction;
  if (!atNode) t.notUsed({"node"}, why);
  if (!atSlider) t.notUsed({"group", "slider"}, why);
  if (p.kind != ProbeKind::LineForce) t.notUsed({"element"}, why);
  if (p.kind != ProbeKind::LineForce && p.kind != ProbeKind::SkirtRadius &&
      p.kind != ProbeKind::SupportForce)
    t.notUsed({"set"}, why);
  if (p.kind != ProbeKind::SupportForce) t.notUsed({"nodes"}, why);
  if (!overLines) t.notUsed({"sets"}, why);
  if (p.kind != ProbeKind::Canopy) t.notUsed({"membranes"}, why);
  if (p.kind != ProbeKind::SkirtRadius) t.notUsed({"axis"}, why);
  if (p.kind != ProbeKind::EdgeAngle) t.notUsed({"from", "to"}, why);
  if (overLines) {
    // The line sets by name; all of them when not given.
    if (t.has("sets")) {
      for (const auto& name : t.strings("sets")) {
        int set = -1;
        for (size_t i = 0; i < m.lineSets.size(); ++i)
          if (m.lineSets[i].name == name) set = static_cast<int>(i);
        if (set < 0)
          t.fail("sets", "unknown cable set or sliding group '" + name + "'" +
                             nameSuggestion(name, lineSetNames(m, true, true), "line sets"));
        p.lineSets.push_back(set);
      }
    } else {
      for (size_t i = 0; i < m.lineSets.size(); ++i) p.lineSets.push_back(static_cast<int>(i));
    }
    if (p.lineSets.empty()) t.fail("sets", "the model has no lines");
  }
  if (atNode) {
    p.node = nodeRef(m, t, "node", t.string("node", p.name));
    if (p.kind == ProbeKind::MembraneStress && !onAMembrane(m, p.node))
      t.fail("node", "node '" + m.nodeName[p.node] +
                         "' is on no membrane element: a membrane_stress probe averages the "
                         "stresses of the membrane elements at its node");
  } else if (p.kind == ProbeKind::SupportForce) {
    p.nodes = caseio::nodesOf(m, t);
    for (int n : p.nodes) {
      const auto& c = m.constraint[n];
      if (!(c.fixed[0] || c.fixed[1] || c.fixed[2]))
        t.fail(t.has("set") ? "set" : "nodes",
               "node '" + m.nodeName[n] + "' has no support (no fixed or prescribed dof)");
    }
  } else if (p.kind == ProbeKind::Canopy) {
    const std::string set = t.string("membranes");
    for (const auto& f : m.canopyFlows)
      if (m.membraneSets[f.set].name == set) p.membraneSet = f.set;
    if (p.membraneSet < 0) {
      std::vector<std::string> flown;
      for (const auto& f : m.canopyFlows) flown.push_back(m.membraneSets[f.set].name);
      t.fail("membranes", "no membrane set '" + set + "' with loads from the airflow" +
                              caseio::nameSuggestion(set, flown, "membrane sets with them"));
    }
  } else if (p.kind == ProbeKind::EdgeAngle) {
    p.node = nodeRef(m, t, "from", t.string("from"));
    p.node2 = nodeRef(m, t, "to", t.string("to"));
    if (p.node == p.node2) t.fail("to", "the edge needs two different nodes");
  } else if (p.kind == ProbeKind::Slider || p.kind == ProbeKind::SliderFriction) {
    const std::string g = t.string("group");
    for (size_t i = 0; i < m.groups.size(); ++i)
      if (m.groups[i].name == g) p.group = static_cast<int>(i);
    if (p.group < 0)
      t.fail("group", "unknown sliding group '" + g + "'" +
                          nameSuggestion(g, lineSetNames(m, false, true), "sliding groups"));
    const auto& sl = m.groups[p.group].sliders;
    const int node = nodeRef(m, t, "slider", t.string("slider", m.nodeName[sl.front()]));
    auto it = std::find(sl.begin(), sl.end(), node);
    if (it == sl.end()) t.fail("slider", "node is not a slider of group '" + g + "'");
    p.slider = static_cast<int>(it - sl.begin());
  } else if (p.kind == ProbeKind::LineForce) {
    const std::string set = t.string("set");
    for (size_t i = 0; i < m.lineSets.size(); ++i)
      if (m.lineSets[i].name == set) p.lineSet = static_cast<int>(i);
    if (p.lineSet < 0)
      t.fail("set", "unknown cable set or sliding group '" + set + "'" +
                        nameSuggestion(set, lineSetNames(m, true, true), "line sets"));
    long count = 0;
    for (const auto& c : m.cables) count += c.set == p.lineSet;
    for (const auto& g : m.groups) count += g.set == p.lineSet ? g.numElements() : 0;
    p.element = static_cast<int>(t.integer("element", 0, 0, count - 1));
  } else if (p.kind == ProbeKind::SkirtRadius) {
    // A node set (or one node) by name: its node ids.
    auto nodesOf = [&](const std::string& key, const std::string& name) -> std::vector<int> {
      if (auto it = m.nodeSets.find(name); it != m.nodeSets.end() && !it->second.empty())
        return it->second;
      if (auto it = m.nodeByName.find(name); it != m.nodeByName.end()) return {it->second};
      std::vector<std::string> known = nodeSetNames(m), nodes = nodeNames(m);
      known.insert(known.end(), nodes.begin(), nodes.end());
      t.fail(key, "no node or node set '" + name + "'" +
                      nameSuggestion(name, known, "nodes and node sets"));
    };
    p.nodes = nodesOf("set", t.string("set"));
    const auto axis = t.strings("axis");
    if (axis.size() != 2) t.fail("axis", "give two nodes or node sets: [from, to]");
    p.axisFrom = nodesOf("axis", axis[0]);
    p.axisTo = nodesOf("axis", axis[1]);
  }
  t.finish();
  return p;
}

}  // namespace

namespace {

// Most probe rows and VTU frames a run may write unless the case raises the limit, and the most
// it may be raised to (docs/limits.md): a typo in an interval must not fill a disk.
constexpr long kMaxRowsLimit = 1000000000;
constexpr long kMaxFramesLimit = 10000000;
constexpr double kMaxSteps = 1e9;

// What output times do to a dynamic run's size, judged before it starts (docs/limits.md): rows
// and frames at an interval, an implicit run's steps capped by an interval shorter than dt, and
// rows or frames every N implicit steps. (An explicit run's step is known once the model is
// built: app/RunLimits.cpp.)
void checkOutputSize(const CaseSpec& c, TomlTable& o, TomlTable* v) {
  const auto& sv = c.solver;
  if (sv.type != AnalysisType::Dynamic) return;
  const auto& out = c.output;
  const bool implicitStep = sv.integrator != IntegratorKind::CentralDifference;
  double step = sv.dt;  // an implicit run's longest step: dt, capped by the output intervals
  if (implicitStep && out.interval > 0.0) step = std::min(step, out.interval);
  if (implicitStep && out.vtu.write && out.vtu.interval > 0.0)
    step = std::min(step, out.vtu.interval);
  if (out.interval > 0.0 && sv.tEnd / out.interval + 1.0 > static_cast<double>(out.maxRows))
    o.fail("interval", "t_end / interval is " + shortNumber(sv.tEnd / out.interval) +
                           " probe rows, more than output.max_rows = " +
                           std::to_string(out.maxRows) + " (raise it to write them)");
  if (v && out.vtu.write && out.vtu.interval > 0.0 &&
      sv.tEnd / out.vtu.interval + 1.0 > static_cast<double>(out.vtu.maxFrames))
    v->fail("interval", "t_end / interval is " + shortNumber(sv.tEnd / out.vtu.interval) +
                            " VTU frames, more than output.vtu.max_frames = " +
                            std::to_string(out.vtu.maxFrames) + " (raise it to write them)");
  if (!implicitStep) return;
  if (sv.tEnd / step > kMaxSteps) {
    const bool vtuCaps = out.vtu.write && out.vtu.interval > 0.0 && out.vtu.interval == step;
    (vtuCaps && v ? *v : o)
        .fail("interval", "caps the step at " + shortNumber(step) +
                              " (steps land on output times): t_end / " + shortNumber(step) +
                              " = " + shortNumber(sv.tEnd / step) + " steps, more than " +
                              shortNumber(kMaxSteps));
  }
  const double steps = sv.tEnd / step;
  if (out.interval <= 0.0 && steps / out.everySteps + 1.0 > static_cast<double>(out.maxRows))
    o.fail("every", "a row every " + std::to_string(out.everySteps) + " of " + shortNumber(steps) +
                        " steps is more than output.max_rows = " + std::to_string(out.maxRows) +
                        " probe rows (raise it, or give interval)");
  if (v && out.vtu.write && out.vtu.interval <= 0.0 &&
      steps / out.vtu.everySteps + 1.0 > static_cast<double>(out.vtu.maxFrames))
    v->fail("every",
            "a frame every " + std::to_string(out.vtu.everySteps) + " of " + shortNumber(steps) +
                " steps is more than output.vtu.max_frames = " + std::to_string(out.vtu.maxFrames) +
                " VTU frames (raise it, or give interval)");
}

}  // namespace

void readOutput(CaseSpec& c, TomlTable o) {
  const Model& m = c.model;
  c.output.everySteps = static_cast<int>(o.integer("every", 1, 1, INT_MAX));
  if (o.has("interval")) c.output.interval = o.positive("interval");
  if (o.has("interval") && o.has("every")) o.fail("every", "give either every or interval");
  c.output.maxRows = o.integer("max_rows", c.output.maxRows, 1, kMaxRowsLimit);
  std::set<std::string> names;
  for (auto& p : o.tables("probes")) {
    c.output.probes.push_back(readProbe(m, p));
    if (!names.insert(c.output.probes.back().name).second)
      p.fail("name", "duplicate probe name '" + c.output.probes.back().name + "'");
  }
  std::optional<TomlTable> vtuTable;
  if (o.has("vtu")) {
    vtuTable.emplace(o.table("vtu"));
    TomlTable& v = *vtuTable;
    auto& vtu = c.output.vtu;
    vtu.write = v.boolean("write", true);
    vtu.maxFrames = v.integer("max_frames", vtu.maxFrames, 1, kMaxFramesLimit);
    vtu.everySteps = static_cast<int>(v.integer("every", 1, 1, INT_MAX));
    if (v.has("interval")) vtu.interval = v.positive("interval");
    if (v.has("interval") && v.has("every")) v.fail("every", "give either every or interval");
    vtu.fields = v.strings("fields", {});
    for (const auto& f : vtu.fields) {
      const auto& known = vtuPointFieldNames();
      if (std::find(known.begin(), known.end(), f) == known.end()) {
        std::string list;
        for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
        v.fail("fields", "unknown field '" + f + "' (known: " + list + ")");
      }
    }
    v.finish();
  }
  checkOutputSize(c, o, vtuTable ? &*vtuTable : nullptr);
  o.finish();
}

}  // namespace caseio
}  // namespace chute
