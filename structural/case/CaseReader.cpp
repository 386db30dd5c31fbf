// Case file -> CaseSpec. The schema is documented in docs/case-files.md.
#include <Eigen/Geometry>
#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>

#include "StructuredMeshes.hpp"
#include "case/CaseSpec.hpp"
#include "case/CaseText.hpp"
#include "case/MeshGroups.hpp"
#include "case/TomlTable.hpp"
#include "case/sections/SectionLookup.hpp"
#include "verification/References.hpp"

namespace chute {

std::vector<std::string> ProbeSpec::columns() const {
  std::vector<std::string> q;
  if (kind == "node_position") q = {"x", "y", "z"};
  if (kind == "node_velocity") q = {"vx", "vy", "vz"};
  if (kind == "slider") q = {"s", "element"};
  if (kind == "slider_friction")
    q = {"state", "slip_rate", "tension_ratio", "wrap_angle", "N1", "N2"};
  if (kind == "energy") q = {"kinetic", "strain", "gravity", "total"};
  if (kind == "line_force") q = {"N", "strain"};
  if (kind == "membrane_stress") q = {"S1", "S2"};
  if (kind == "edge_angle") q = {"angle"};
  if (kind == "wrinkling") q = {"taut", "wrinkled", "slack"};
  if (kind == "skirt_radius") q = {"mean", "min", "max"};
  for (auto& s : q) s = name + "." + s;
  return q;
}

namespace {

using namespace caseio;

// Most steps a dynamic run may ask for (t_end / dt), and the least step relative to t_end that
// still advances time (a few ulps of t_end).
constexpr double kMaxSteps = 1e9;
constexpr double kLeastRelativeStep = 1e-15;

kernels::MembraneMaterial readMembraneMaterial(TomlTable t) {
  kernels::MembraneMaterial m;
  t.string("kind");
  m.E = t.positive("E");
  m.nu = t.number("nu", 0.3);
  if (m.nu < 0.0 || m.nu >= 0.5) t.fail("nu", "must be in [0, 0.5)");
  m.thickness = t.positive("thickness");
  m.density = t.nonNegative("density", 0.0);
  t.finish();
  return m;
}

kernels::LineMaterial readMaterial(TomlTable t) {
  kernels::LineMaterial m;
  const std::string kind = t.choice("kind", "cable", {"cable", "truss", "membrane"});
  m.tensionOnly = kind == "cable";
  m.E = t.positive("E");
  m.area = t.positive("area");
  m.density = t.nonNegative("density", 0.0);
  m.compressionStiffnessRatio = t.nonNegative("compression_stiffness_ratio", 0.0);
  t.finish();
  return m;
}

// Points at equal arc length along a polyline, n intervals; returns n + 1 points.
std::vector<Vec3> resample(const std::vector<Vec3>& path, int n, double* totalLength) {
  std::vector<double> s(path.size(), 0.0);
  for (size_t i = 1; i < path.size(); ++i) s[i] = s[i - 1] + (path[i] - path[i - 1]).norm();
  *totalLength = s.back();
  std::vector<Vec3> out;
  size_t seg = 1;
  for (int k = 0; k <= n; ++k) {
    const double target = s.back() * k / n;
    while (seg + 1 < path.size() && s[seg] < target) ++seg;
    const double len = s[seg] - s[seg - 1];
    const double f = len > 0 ? std::clamp((target - s[seg - 1]) / len, 0.0, 1.0) : 0.0;
    out.push_back(path[seg - 1] + f * (path[seg] - path[seg - 1]));
  }
  out.front() = path.front();
  out.back() = path.back();
  return out;
}

std::vector<int> pathNodes(const Model& m, TomlTable& t) {
  const auto names = t.strings("path");
  if (names.size() < 2) t.fail("path", "needs at least two nodes");
  std::vector<int> ids;
  for (const auto& n : names) ids.push_back(nodeRef(m, t, "path", n));
  return ids;
}

void readCable(Model& m, TomlTable t, int index) {
  CableElement proto;
  const std::string name = setName(m, t, "cables" + std::to_string(index));
  proto.material = materialRef(m, t);
  const auto ids = pathNodes(m, t);
  const long perSegment = t.integer("elements_per_segment", 1, 1, kMaxNodes);
  checkNodeBudget(m, t, "elements_per_segment",
                  (perSegment - 1) * static_cast<long>(ids.size() - 1));
  const double prestrain = t.number("prestrain", 0.0);
  if (prestrain <= -1.0) t.fail("prestrain", "must be > -1");
  t.finish();
  proto.set = static_cast<int>(m.lineSets.size());
  m.lineSets.push_back({name, false});
  for (size_t i = 0; i + 1 < ids.size(); ++i) {
    const Vec3 a = m.X[ids[i]], b = m.X[ids[i + 1]];
    if ((b - a).norm() <= 0.0)
      t.fail("path", "zero-length segment between '" + m.nodeName[ids[i]] + "' and '" +
                         m.nodeName[ids[i + 1]] + "'");
    int prev = ids[i];
    for (long k = 1; k <= perSegment; ++k) {
      const int next = k == perSegment ? ids[i + 1]
                                       : m.addNode(a + (b - a) * (double(k) / perSegment),
                                                   name + "." + std::to_string(m.numNodes()));
      CableElement c = proto;
      c.a = prev;
      c.b = next;
      c.L = (m.X[next] - m.X[prev]).norm() / (1.0 + prestrain);
      m.cables.push_back(c);
      prev = next;
    }
  }
}

// Friction, lock and one-way flow of a slider point (docs/friction.md): keys `friction =
// {mu_static, mu_dynamic, slip_rate_scale}`, `lock_at`, `one_way = "+" | "-"` over `base`.
kernels::SliderFrictionLaw readFrictionLaw(TomlTable& t, kernels::SliderFrictionLaw base) {
  if (t.has("friction")) {
    TomlTable f = t.table("friction");
    base.muStatic = f.nonNegative("mu_static", 0.0);
    base.muDynamic = f.nonNegative("mu_dynamic", base.muStatic);
    base.slipRateScale = f.nonNegative("slip_rate_scale", 0.0);
    if (base.muDynamic > base.muStatic)
      f.fail("mu_dynamic", "must not exceed mu_static (the stick limit)");
    f.finish();
  }
  if (t.has("lock_at")) base.lockAt = t.nonNegative("lock_at", 0.0);
  if (t.has("one_way")) base.oneWay = t.choice("one_way", "+", {"+", "-"}) == "+" ? 1 : -1;
  return base;
}

void readSlidingGroup(Model& m, TomlTable t, int index) {
  SlidingGroupDef g;
  g.name = setName(m, t, "sliding_group" + std::to_string(index));
  g.material = materialRef(m, t);
  const auto path = pathNodes(m, t);
  std::vector<int> sliders;
  for (const auto& s : t.strings("sliders")) sliders.push_back(nodeRef(m, t, "sliders", s));
  if (sliders.empty()) t.fail("sliders", "a sliding group needs at least one slider");
  std::set<int> sliderSet(sliders.begin(), sliders.end());
  if (sliderSet.size() != sliders.size()) t.fail("sliders", "a slider is listed twice");
  if (sliderSet.count(path.front()) || sliderSet.count(path.back()))
    t.fail("path", "the chain's end nodes cannot be sliders");
  for (size_t i = 1; i + 1 < path.size(); ++i)
    if (!sliderSet.count(path[i]))
      t.fail("path", "interior path node '" + m.nodeName[path[i]] +
                         "' is not a slider (the path runs end -> sliders -> end)");
  const long n = t.integer("elements", 1, 1, kMaxNodes);
  checkNodeBudget(m, t, "elements", n - 1);
  const double prestrain = t.number("prestrain", 0.0);
  if (prestrain <= -1.0) t.fail("prestrain", "must be > -1");
  std::vector<long> active;
  if (t.has("active")) active = t.integers("active");
  const auto groupLaw = readFrictionLaw(t, {});
  g.friction.assign(sliders.size(), groupLaw);
  for (auto& sp : t.tables("slider_points")) {
    const int node = nodeRef(m, sp, "slider", sp.string("slider"));
    auto it = std::find(sliders.begin(), sliders.end(), node);
    if (it == sliders.end()) sp.fail("slider", "not a slider of this group");
    g.friction[it - sliders.begin()] = readFrictionLaw(sp, groupLaw);
    sp.finish();
  }
  t.finish();

  std::vector<Vec3> geom;
  for (int id : path) geom.push_back(m.X[id]);
  double total = 0.0;
  const auto pts = resample(geom, static_cast<int>(n), &total);
  if (total <= 0.0) t.fail("path", "the path has zero length");
  const double h = total / n;
  g.chain.push_back(path.front());
  for (long k = 1; k < n; ++k)
    g.chain.push_back(m.addNode(pts[k], g.name + "." + std::to_string(k)));
  g.chain.push_back(path.back());
  g.refLength.assign(n, h / (1.0 + prestrain));
  g.sliders = sliders;
  g.set = static_cast<int>(m.lineSets.size());
  m.lineSets.push_back({g.name, true});

  if (!active.empty() && active.size() != sliders.size())
    t.fail("active", "needs one element index per slider (" + std::to_string(sliders.size()) + ")");
  // Arc length of each path vertex, for the initially active element of sliders on the path.
  std::vector<double> arc(path.size(), 0.0);
  for (size_t i = 1; i < path.size(); ++i) arc[i] = arc[i - 1] + (geom[i] - geom[i - 1]).norm();
  for (size_t s = 0; s < sliders.size(); ++s) {
    int k;
    if (!active.empty()) {
      if (active[s] < 0 || active[s] >= n)
        t.fail("active", "element " + std::to_string(active[s]) + " out of range [0, " +
                             std::to_string(n - 1) + "]");
      k = static_cast<int>(active[s]);
    } else {
      auto it = std::find(path.begin(), path.end(), sliders[s]);
      if (it == path.end())
        t.fail("active", "slider '" + m.nodeName[sliders[s]] +
                             "' is not on the path: give its initially active element");
      const double sArc = arc[it - path.begin()];
      k = static_cast<int>(std::clamp(std::floor(sArc / h), 0.0, static_cast<double>(n - 1)));
    }
    // The slider must lie on its active element: l = l1 + l2 equals the element's current
    // length (1 + prestrain) L up to round-off.
    const Vec3 xs = m.X[sliders[s]];
    const double l = (xs - m.X[g.chain[k]]).norm() + (xs - m.X[g.chain[k + 1]]).norm();
    if (std::abs(l - h) > 1e-6 * h)
      t.fail(active.empty() ? "sliders" : "active",
             "slider '" + m.nodeName[sliders[s]] + "' is not on element " + std::to_string(k) +
                 " of the chain (l1 + l2 = " + std::to_string(l) + ", element length " +
                 std::to_string(h) + ")");
    for (size_t o = 0; o < s; ++o)
      if (g.initialActive[o] == k)
        t.fail("sliders", "two sliders on element " + std::to_string(k) +
                              ": use more elements so each slider has its own");
    g.initialActive.push_back(k);
  }
  m.groups.push_back(std::move(g));
}

// Why a membrane element is unusable ("" if it is fine): a repeated node, no area, or (quads) a
// corner that is not convex about the normal the kernel uses (its reference frame,
// docs/formulation.md M1).
std::string degenerateElement(const Model& m, const MembraneElement& e) {
  const int n = e.numNodes;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (e.nodes[i] == e.nodes[j]) return "node '" + m.nodeName[e.nodes[i]] + "' appears twice";
  double edge2 = 0.0;
  for (int i = 0; i < n; ++i)
    edge2 = std::max(edge2, (m.X[e.nodes[(i + 1) % n]] - m.X[e.nodes[i]]).squaredNorm());
  const double tol = 1e-12 * edge2;
  auto X = [&](int i) { return m.X[e.nodes[(i + n) % n]]; };
  if (n == 3) {
    if ((X(1) - X(0)).cross(X(2) - X(0)).norm() <= tol)
      return "zero area (its nodes are collinear)";
    return "";
  }
  const Vec3 normal = (X(2) - X(0)).cross(X(3) - X(1));
  if (normal.norm() <= tol) return "zero area (its diagonals are parallel)";
  for (int i = 0; i < 4; ++i)
    if ((X(i + 1) - X(i)).cross(X(i - 1) - X(i)).dot(normal.normalized()) <= tol)
      return "not convex at node '" + m.nodeName[e.nodes[i]] +
             "' (nodes must go round the element, counter-clockwise about its normal)";
  return "";
}

void readMembranes(Model& m, TomlTable t) {
  MembraneSet set;
  set.name = setName(m, t, "");
  const int material = membraneMaterialRef(m, t);
  set.wrinkling = t.boolean("wrinkling", true);
  set.prestrain = t.number("prestrain", 0.0);
  if (set.prestrain <= -1.0) t.fail("prestrain", "must be > -1");
  const int setId = static_cast<int>(m.membraneSets.size());
  const std::string kind = t.choice("mesh", "disk", {"disk", "rectangle", "elements"});
  const std::vector<std::string> diskKeys = {"center", "radius", "rings"},
                                 rectangleKeys = {"corner", "size", "divisions", "element"},
                                 elementKeys = {"triangles", "quads"};
  if (kind != "disk") t.notUsed(diskKeys, "with mesh = \"" + kind + "\"");
  if (kind != "rectangle") t.notUsed(rectangleKeys, "with mesh = \"" + kind + "\"");
  if (kind != "elements") t.notUsed(elementKeys, "with mesh = \"" + kind + "\"");
  if (kind == "disk" || !t.has("bulge"))
    t.notUsed({"bulge_centre", "bulge_extent"},
              kind == "disk" ? "with mesh = \"disk\"" : "without bulge");
  if (kind == "elements") {
    // Explicit elements over named nodes: triangles = [["a", "b", "c"], ...], quads likewise.
    auto& all = m.nodeSets[set.name];
    std::set<int> seen;
    for (const char* key : {"triangles", "quads"}) {
      if (!t.has(key)) continue;
      const size_t n = std::string(key) == "triangles" ? 3 : 4;
      const auto& arr = toml::find(t.raw(), key);
      if (!arr.is_array()) t.fail(key, "expected an array of node-name arrays");
      for (const auto& el : arr.as_array()) {
        if (!el.is_array() || el.as_array().size() != n)
          t.failAt(el, key, "each element needs " + std::to_string(n) + " node names");
        MembraneElement e;
        e.numNodes = static_cast<int>(n);
        e.set = setId;
        e.material = material;
        for (size_t i = 0; i < n; ++i) {
          const auto& v = el.as_array()[i];
          if (!v.is_string()) t.failAt(v, key, "expected a node name");
          auto it = m.nodeByName.find(v.as_string().str);
          if (it == m.nodeByName.end())
            t.failAt(v, key, "unknown node '" + v.as_string().str + "'");
          e.nodes[i] = it->second;
          if (seen.insert(it->second).second) all.push_back(it->second);
        }
        const std::string bad = degenerateElement(m, e);
        if (!bad.empty()) t.failAt(el, key, "degenerate element: " + bad);
        m.membranes.push_back(e);
      }
    }
    if (all.empty())
      t.fail("mesh", "an \"elements\" mesh needs triangles = [...] or quads = [...]");
  } else if (kind == "disk") {
    const Vec3 origin = Vec3::Zero();
    const Vec3 centre = point(t, "center", &origin);
    const double radius = length(t, "radius");
    const long rings = t.integer("rings", 8, 1, kMaxNodes);
    checkNodeBudget(m, t, "rings", 1 + 3 * rings * (rings + 1));
    mesh::addDisk(m, set.name, setId, material, centre, radius, static_cast<int>(rings));
  } else {
    const Vec3 origin = Vec3::Zero();
    const Vec3 corner = point(t, "corner", &origin);
    const Vec3 size = point(t, "size");
    if (size.x() <= 0 || size.y() <= 0) t.fail("size", "needs positive x and y extents");
    const auto div = t.integers("divisions");
    if (div.size() != 2 || div[0] < 1 || div[1] < 1) t.fail("divisions", "expected [nx, ny] >= 1");
    if (div[0] >= kMaxNodes || div[1] >= kMaxNodes)
      t.fail("divisions", "more than " + std::to_string(kMaxNodes) + " divisions");
    checkNodeBudget(m, t, "divisions", (div[0] + 1) * (div[1] + 1));
    const bool quads = t.choice("element", "quad", {"quad", "triangle"}) == "quad";
    mesh::addRectangle(m, set.name, setId, material, corner, size.x(), size.y(),
                       static_cast<int>(div[0]), static_cast<int>(div[1]), quads);
  }
  // Optional bulged start (the reference stays flat): u_z = bulge cos(pi/2 dx/ax) cos(pi/2 dy/ay)
  // around bulge_centre [x, y] within bulge_extent [ax, ay] (disk: bulge (1 - r^2/R^2)).
  if (t.has("bulge")) {
    const double h = t.number("bulge");
    if (std::abs(h) > kMaxLength) t.fail("bulge", "lengths beyond 1e100");
    const auto& nodes = m.nodeSets[set.name];
    if (kind == "disk") {
      const Vec3 c = m.X[m.nodeId(set.name + ".center")];
      double R = 0.0;
      for (int n : nodes) R = std::max(R, (m.X[n] - c).norm());
      for (int n : nodes) m.u0[n].z() += h * (1.0 - (m.X[n] - c).squaredNorm() / (R * R));
    } else {
      const Vec3 c = point(t, "bulge_centre");
      const Vec3 ext = point(t, "bulge_extent");
      if (ext.x() <= 0.0 || ext.y() <= 0.0)
        t.fail("bulge_extent", "needs positive x and y extents");
      for (int n : nodes) {
        const double dx = std::abs(m.X[n].x() - c.x()) / ext.x(),
                     dy = std::abs(m.X[n].y() - c.y()) / ext.y();
        if (dx < 1.0 && dy < 1.0)
          m.u0[n].z() += h * std::cos(M_PI / 2 * dx) * std::cos(M_PI / 2 * dy);
      }
    }
  }
  t.finish();
  m.membraneSets.push_back(set);
}

ProbeSpec readProbe(const Model& m, TomlTable t) {
  ProbeSpec p;
  p.name = t.string("name");
  // Probe names head the columns of probes.csv.
  if (p.name.empty() || std::any_of(p.name.begin(), p.name.end(), [](char ch) {
        return (ch >= 0 && ch < 32) || ch == ',' || ch == '"';
      }))
    t.fail("name", "must be non-empty, without commas, quotes or control characters");
  p.kind =
      t.choice("kind", "node_position",
               {"node_position", "node_velocity", "slider", "energy", "line_force",
                "membrane_stress", "wrinkling", "slider_friction", "skirt_radius", "edge_angle"});
  const std::string why = "by a probe of kind \"" + p.kind + "\"";
  const bool atNode =
      p.kind == "node_position" || p.kind == "node_velocity" || p.kind == "membrane_stress";
  const bool atSlider = p.kind == "slider" || p.kind == "slider_friction";
  if (!atNode) t.notUsed({"node"}, why);
  if (!atSlider) t.notUsed({"group", "slider"}, why);
  if (p.kind != "line_force") t.notUsed({"element"}, why);
  if (p.kind != "line_force" && p.kind != "skirt_radius") t.notUsed({"set"}, why);
  if (p.kind != "skirt_radius") t.notUsed({"axis"}, why);
  if (p.kind != "edge_angle") t.notUsed({"from", "to"}, why);
  if (atNode) {
    p.node = nodeRef(m, t, "node", t.string("node", p.name));
  } else if (p.kind == "edge_angle") {
    p.node = nodeRef(m, t, "from", t.string("from"));
    p.node2 = nodeRef(m, t, "to", t.string("to"));
    if (p.node == p.node2) t.fail("to", "the edge needs two different nodes");
  } else if (p.kind == "slider" || p.kind == "slider_friction") {
    const std::string g = t.string("group");
    for (size_t i = 0; i < m.groups.size(); ++i)
      if (m.groups[i].name == g) p.group = static_cast<int>(i);
    if (p.group < 0) t.fail("group", "unknown sliding group '" + g + "'");
    const auto& sl = m.groups[p.group].sliders;
    const int node = nodeRef(m, t, "slider", t.string("slider", m.nodeName[sl.front()]));
    auto it = std::find(sl.begin(), sl.end(), node);
    if (it == sl.end()) t.fail("slider", "node is not a slider of group '" + g + "'");
    p.slider = static_cast<int>(it - sl.begin());
  } else if (p.kind == "line_force") {
    const std::string set = t.string("set");
    for (size_t i = 0; i < m.lineSets.size(); ++i)
      if (m.lineSets[i].name == set) p.lineSet = static_cast<int>(i);
    if (p.lineSet < 0) t.fail("set", "unknown cable set or sliding group '" + set + "'");
    long count = 0;
    for (const auto& c : m.cables) count += c.set == p.lineSet;
    for (const auto& g : m.groups) count += g.set == p.lineSet ? g.numElements() : 0;
    p.element = static_cast<int>(t.integer("element", 0, 0, count - 1));
  } else if (p.kind == "skirt_radius") {
    // A node set (or one node) by name: its node ids.
    auto nodesOf = [&](const std::string& key, const std::string& name) -> std::vector<int> {
      if (auto it = m.nodeSets.find(name); it != m.nodeSets.end() && !it->second.empty())
        return it->second;
      if (auto it = m.nodeByName.find(name); it != m.nodeByName.end()) return {it->second};
      t.fail(key, "no node or node set '" + name + "'");
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

using namespace caseio;

CaseSpec readCase(const std::string& file, const std::vector<std::string>& overrides) {
  return readCaseFromString(readText(file), file, overrides);
}

CaseSpec readCaseFromString(const std::string& text, const std::string& file,
                            const std::vector<std::string>& overrides) {
  toml::value root = parseText(text, file);
  for (const auto& o : overrides) applyOverride(root, file, o);
  TomlTable top(root, "", file);
  // Unknown top-level keys first: a misspelt table would otherwise surface as something missing.
  top.finish({"name", "description", "units", "nodes", "materials", "cables", "sliding_groups",
              "membranes", "point_masses", "boundary", "loads", "solver", "output", "reference",
              "mesh", "events"});
  CaseSpec c;
  c.file = file;
  c.name = top.string("name", std::filesystem::path(file).stem().string());
  // The name is the default output directory out/<name>/: one plain path component.
  if (c.name.empty() || c.name == "." || c.name == ".." ||
      c.name.find_first_of("/\\") != std::string::npos ||
      std::any_of(c.name.begin(), c.name.end(), [](char ch) { return ch >= 0 && ch < 32; }))
    top.fail("name", "must be a plain file name (no '/', not empty, '.' or '..')");
  c.description = top.string("description", "");
  c.units = top.string("units", "");
  Model& m = c.model;

  if (top.has("nodes")) {
    TomlTable nodes = top.table("nodes");
    const auto names = nodes.keys();
    if (static_cast<long>(names.size()) > kMaxNodes)
      nodes.fail("", "more than " + std::to_string(kMaxNodes) + " nodes");
    for (const auto& name : names) {
      if (name.empty()) nodes.fail(name, "a node name cannot be empty");
      if (name.find('.') != std::string::npos) nodes.fail(name, "node names cannot contain '.'");
      m.addNode(point(nodes, name), name);
    }
  }
  std::unique_ptr<MeshImport> mesh;  // [mesh]: a gmsh mesh whose physical groups entries map
  if (top.has("mesh")) mesh = importMesh(m, top.table("mesh"), file);
  if (top.has("materials")) {
    TomlTable mats = top.table("materials");
    for (const auto& name : mats.keys()) {
      TomlTable t = mats.table(name);
      if (t.has("kind") && t.string("kind") == "membrane") {
        m.membraneMaterialName.push_back(name);
        m.membraneMaterials.push_back(readMembraneMaterial(t));
      } else {
        m.materialName.push_back(name);
        m.materials.push_back(readMaterial(t));
      }
    }
  }
  int i = 0;
  for (auto& t : top.tables("cables"))
    t.has("group") ? readMeshCables(m, mesh.get(), t, i++) : readCable(m, t, i++);
  i = 0;
  for (auto& t : top.tables("sliding_groups"))
    t.has("group") ? readMeshSlidingGroup(m, mesh.get(), t, i++) : readSlidingGroup(m, t, i++);
  for (auto& t : top.tables("membranes"))
    t.has("group") ? readMeshMembranes(m, mesh.get(), t) : readMembranes(m, t);
  if (m.numNodes() == 0) top.fail("nodes", "the case has no nodes (no [nodes] and no meshes)");
  for (auto& t : top.tables("point_masses")) {
    if (t.has("group")) {
      readMeshPointMasses(m, mesh.get(), t);
      continue;
    }
    const int n = nodeRef(m, t, "node", t.string("node"));
    m.pointMass[n] += t.positive("mass");
    t.finish();
  }
  if (top.has("boundary")) {
    TomlTable b = top.table("boundary");
    for (const auto& name : b.strings("fixed", {}))
      m.constraint[nodeRef(m, b, "fixed", name)].fixed = {true, true, true};
    for (auto& t : b.tables("prescribed")) {
      const std::string dofs = t.string("dofs", "xyz");
      if (dofs.empty() || dofs.find_first_not_of("xyz") != std::string::npos)
        t.fail("dofs", "expected a combination of x, y, z");
      const Vec3 velocity = t.vec3("velocity", Vec3::Zero());
      const Vec3 amplitude = t.vec3("amplitude", Vec3::Zero());
      const double frequency = t.nonNegative("frequency", 0.0);
      for (int node : nodesOf(m, t)) {
        auto& nc = m.constraint[node];
        for (char d : dofs) nc.fixed[d - 'x'] = true;
        nc.velocity = velocity;
        nc.amplitude = amplitude;
        nc.frequency = frequency;
      }
      t.finish();
    }
    for (auto& t : b.tables("constraints")) {
      const std::string dofs = t.string("dofs");
      if (dofs.empty() || dofs.find_first_not_of("xyz") != std::string::npos)
        t.fail("dofs", "expected a combination of x, y, z");
      for (int n : nodesOf(m, t))
        for (char d : dofs) m.constraint[n].fixed[d - 'x'] = true;
      t.finish();
    }
    b.finish();
  }
  if (top.has("loads")) {
    TomlTable l = top.table("loads");
    m.gravity = l.vec3("gravity", Vec3::Zero());
    for (auto& t : l.tables("pressure")) {
      PressureLoadDef p;
      const std::string set = t.string("membranes");
      for (size_t k = 0; k < m.membraneSets.size(); ++k)
        if (m.membraneSets[k].name == set) p.set = static_cast<int>(k);
      if (p.set < 0) t.fail("membranes", "unknown membrane set '" + set + "'");
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
          t.fail("element_factors",
                 "needs one factor per element of '" + set + "' (" + std::to_string(count) + ")");
      }
      t.finish();
      m.pressures.push_back(p);
    }
    for (auto& t : l.tables("drag")) {
      DragLoadDef d;
      if (t.has("group")) {
        d.edges = meshEdges(mesh.get(), t);  // the 2-node elements of a 1-D physical group
      } else if (t.has("edge")) {
        // Edges between consecutive nodes of a node set (e.g. "bag.xmax", a disk's "rim").
        const std::string edge = t.string("edge");
        auto it = m.nodeSets.find(edge);
        if (it == m.nodeSets.end() || it->second.size() < 2)
          t.fail("edge", "no node set '" + edge + "' of two or more nodes");
        const auto& ns = it->second;
        for (size_t k = 0; k + 1 < ns.size(); ++k) d.edges.push_back({ns[k], ns[k + 1]});
        if (t.boolean("closed", false)) d.edges.push_back({ns.back(), ns.front()});
      } else {
        const std::string set = t.string("set");
        for (size_t k = 0; k < m.lineSets.size(); ++k)
          if (m.lineSets[k].name == set) d.lineSet = static_cast<int>(k);
        if (d.lineSet < 0) t.fail("set", "unknown cable set or sliding group '" + set + "'");
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
      const std::string set = t.string("membranes");
      for (size_t k = 0; k < m.membraneSets.size(); ++k)
        if (m.membraneSets[k].name == set) d.set = static_cast<int>(k);
      if (d.set < 0) t.fail("membranes", "unknown membrane set '" + set + "'");
      const double cd = t.positive("cd");
      const double rho = t.positive("air_density");
      d.coefficient = 0.5 * rho * cd;
      d.wind = t.vec3("wind", Vec3::Zero());
      d.steadySubtracted = t.boolean("subtract_steady", false);
      t.finish();
      m.faceDrags.push_back(d);
    }
    l.finish();
  }
  // [[events]] cut = "<cable set>", at = t: the set carries load up to t and is gone after it.
  for (auto& t : top.tables("events")) {
    const std::string set = t.string("cut");
    auto it = std::find_if(m.lineSets.begin(), m.lineSets.end(),
                           [&](const LineSet& s) { return s.name == set; });
    if (it == m.lineSets.end()) t.fail("cut", "unknown cable set '" + set + "'");
    if (it->sliding)
      t.fail("cut", "'" + set + "' is a sliding group; only [[cables]] sets can be cut");
    if (std::isfinite(it->cutAt)) t.fail("cut", "'" + set + "' is cut twice");
    it->cutAt = t.nonNegative("at", 0.0);
    t.finish();
  }
  {
    TomlTable s = top.table("solver");
    auto& sv = c.solver;
    sv.type = s.choice("type", "dynamic", {"dynamic", "static"});
    if (sv.type == "dynamic") {
      sv.dt = s.positive("dt");
      sv.tEnd = s.positive("t_end");
      sv.rhoInf = s.number("rho_inf", 0.9);
      sv.integrator = s.choice("integrator", "bossak", {"bossak", "generalized_alpha"});
      m.massDamping = s.nonNegative("mass_damping", 0.0);
      if (sv.rhoInf < 0.0 || sv.rhoInf > 1.0) s.fail("rho_inf", "must be in [0, 1]");
      sv.dtMin = s.positive("dt_min", sv.dt * 1e-6);
      if (sv.dtMin > sv.dt) s.fail("dt_min", "must not exceed dt");
      // Steps a run can take (docs/limits.md): dt within t_end, at most kMaxSteps of it, and a
      // least step that still moves time near t_end (t + dt_min == t would loop forever).
      if (sv.dt > sv.tEnd) s.fail("dt", "is larger than t_end: not one step fits");
      if (sv.tEnd / sv.dt > kMaxSteps)
        s.fail("dt", "t_end / dt is " + shortNumber(sv.tEnd / sv.dt) + " steps, more than " +
                         shortNumber(kMaxSteps));
      if (sv.dtMin < kLeastRelativeStep * sv.tEnd)
        s.fail(s.has("dt_min") ? "dt_min" : "dt",
               "the least step (dt_min = " + shortNumber(sv.dtMin) +
                   ") is lost in rounding near t_end: keep it above t_end * 1e-15");
    } else {
      s.notUsed({"dt", "t_end", "rho_inf", "integrator", "mass_damping", "dt_min"},
                "by static runs (type = \"static\")");
    }
    sv.loadSteps = static_cast<int>(s.integer("load_steps", 1, 1, 1000000));
    sv.initialLoadFactor = s.positive("initial_load_factor", 0.0 + 1.0);
    if (sv.initialLoadFactor > 1.0) s.fail("initial_load_factor", "must be in (0, 1]");
    m.massKind = s.choice("mass", "lumped", {"lumped", "consistent"}) == "lumped"
                     ? kernels::MassKind::Lumped
                     : kernels::MassKind::Consistent;
    sv.search = s.choice("search", "material_coordinate",
                         {"nearest_length", "material_coordinate"}) == "nearest_length"
                    ? SliderSearch::NearestLength
                    : SliderSearch::MaterialCoordinate;
    sv.maxNewton = static_cast<int>(s.integer("newton_max_iterations", 25, 1, 1000));
    if (s.has("newton_tolerance")) sv.tolDisplacement = s.positive("newton_tolerance");
    sv.slackTautEvents = s.boolean("slack_events", true);
    sv.sliderEvents = s.boolean("slider_events", true);
    if (!sv.sliderEvents && sv.integrator != "bossak")
      s.fail("slider_events",
             "false needs integrator = \"bossak\" (forces at the step's end, where a slider "
             "crossed inside the step is in its new element)");
    s.finish();
  }
  if (top.has("output")) {
    TomlTable o = top.table("output");
    c.output.everySteps = static_cast<int>(o.integer("every", 1, 1, INT_MAX));
    if (o.has("interval")) c.output.interval = o.positive("interval");
    if (o.has("interval") && o.has("every")) o.fail("every", "give either every or interval");
    std::set<std::string> names;
    for (auto& p : o.tables("probes")) {
      c.output.probes.push_back(readProbe(m, p));
      if (!names.insert(c.output.probes.back().name).second)
        p.fail("name", "duplicate probe name '" + c.output.probes.back().name + "'");
    }
    if (o.has("vtu")) {
      TomlTable v = o.table("vtu");
      auto& vtu = c.output.vtu;
      vtu.write = v.boolean("write", true);
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
    o.finish();
  }
  if (top.has("reference")) {
    TomlTable r = top.table("reference");
    ReferenceSpec ref;
    ref.kind = r.choice("kind", "", {"pulley", "bead_ellipse", "free_fall", "hencky"});
    const std::string probe = r.string("probe");
    for (size_t p = 0; p < c.output.probes.size(); ++p)
      if (c.output.probes[p].name == probe) ref.probe = static_cast<int>(p);
    if (ref.probe < 0 || c.output.probes[ref.probe].kind != "node_position")
      r.fail("probe", "no node_position probe named '" + probe + "'");
    if (ref.kind == "pulley") {
      ref.pulley = nodeRef(m, r, "pulley", r.string("pulley"));
      const std::string group = r.string("group");
      for (const auto& g : m.groups)
        if (g.name == group)
          for (double L : g.refLength) ref.ropeLength += L;
      if (ref.ropeLength <= 0.0) r.fail("group", "unknown sliding group '" + group + "'");
    } else if (ref.kind == "hencky") {
      const std::string set = r.string("membranes");
      int setId = -1;
      for (size_t k = 0; k < m.membraneSets.size(); ++k)
        if (m.membraneSets[k].name == set) setId = static_cast<int>(k);
      auto rim = m.nodeSets.find(set + ".rim");
      if (setId < 0 || rim == m.nodeSets.end())
        r.fail("membranes", "no disk membrane '" + set + "'");
      const int centre = c.output.probes[ref.probe].node;
      for (int n : rim->second) ref.radius = std::max(ref.radius, (m.X[n] - m.X[centre]).norm());
      for (const auto& e : m.membranes) {
        if (e.set != setId) continue;
        const auto& mat = m.membraneMaterials[e.material];
        ref.E = mat.E, ref.nu = mat.nu, ref.thickness = mat.thickness;
        ref.direction = (m.X[e.nodes[1]] - m.X[e.nodes[0]])
                            .cross(m.X[e.nodes[2]] - m.X[e.nodes[0]])
                            .normalized();
        break;
      }
      for (const auto& pl : m.pressures)
        if (pl.set == setId) ref.pressure += pl.pressure;
      if (ref.pressure == 0.0) r.fail("membranes", "no pressure on membrane set '" + set + "'");
    } else if (ref.kind == "bead_ellipse") {
      const auto anchors = r.strings("anchors");
      if (anchors.size() != 2) r.fail("anchors", "expected the two fixed rope ends");
      ref.anchor1 = nodeRef(m, r, "anchors", anchors[0]);
      ref.anchor2 = nodeRef(m, r, "anchors", anchors[1]);
      // The reference is built when the run starts; its geometry is checked here, before it.
      try {
        verification::BeadEllipseReference(m.X[ref.anchor1], m.X[ref.anchor2],
                                           m.X[c.output.probes[ref.probe].node], m.gravity);
      } catch (const std::invalid_argument& e) {
        r.fail("probe", e.what());
      }
    }
    r.finish();
    c.reference = ref;
  }
  if (mesh) holdUnusedMeshNodes(m, *mesh);
  if (DofMap(m).numEquations() == 0)
    top.fail(top.has("boundary") ? "boundary" : "nodes",
             "every degree of freedom is fixed or prescribed: there is nothing to solve");
  top.finish();
  return c;
}

}  // namespace chute
