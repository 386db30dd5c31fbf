// [[membranes]]: disks, rectangles and explicit elements, or mesh groups (MeshGroups.cpp).
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "ElementShape.hpp"
#include "StructuredMeshes.hpp"
#include "case/MeshGroups.hpp"
#include "case/sections/SectionLookup.hpp"
#include "case/sections/Sections.hpp"

namespace chute::caseio {

namespace {

// Why a membrane element is unusable ("" if it is fine): mesh/ElementShape.hpp, the check every
// imported mesh element passes too.
std::string degenerateElement(const Model& m, const MembraneElement& e) {
  std::array<Vec3, 4> x;
  std::array<std::size_t, 4> ids{};
  for (int i = 0; i < e.numNodes; ++i)
    x[i] = m.X[e.nodes[i]], ids[i] = static_cast<std::size_t>(e.nodes[i]);
  const mesh::ShapeProblem p = mesh::elementShapeProblem(x.data(), ids.data(), e.numNodes);
  return p ? p.text(p.node < 0 ? "" : "'" + m.nodeName[e.nodes[p.node]] + "'") : "";
}

void readMembraneSet(Model& m, TomlTable t) {
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

}  // namespace

void readMembranes(Model& m, const MeshImport* mesh, TomlTable& top) {
  for (auto& t : top.tables("membranes"))
    t.has("group") ? readMeshMembranes(m, mesh, t) : readMembraneSet(m, t);
}

}  // namespace chute::caseio
