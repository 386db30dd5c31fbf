#include "case/MeshGroups.hpp"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <set>

#include "MeshError.hpp"
#include "MshReader.hpp"
#include "case/CaseText.hpp"
#include "case/sections/SectionLookup.hpp"

namespace chute {

namespace {

const char* roleOfDim(int dim) {
  return dim == 2 ? "a surface (2-D)" : dim == 1 ? "a curve (1-D)" : "a point (0-D)";
}
const char* groupsOfDim(int dim) {
  return dim == 2 ? "surface (2-D) groups" : dim == 1 ? "curve (1-D) groups" : "point (0-D) groups";
}

int lineMaterialRef(const Model& m, TomlTable& t) {
  const std::string name = t.string("material");
  for (size_t i = 0; i < m.materialName.size(); ++i)
    if (m.materialName[i] == name) return static_cast<int>(i);
  t.fail("material", "unknown material '" + name + "'" +
                         caseio::nameSuggestion(name, m.materialName, "line materials"));
}

int membraneMaterialRef(const Model& m, TomlTable& t) {
  const std::string name = t.string("material");
  for (size_t i = 0; i < m.membraneMaterialName.size(); ++i)
    if (m.membraneMaterialName[i] == name) return static_cast<int>(i);
  t.fail("material",
         "no membrane material '" + name + "' (kind = \"membrane\")" +
             caseio::nameSuggestion(name, m.membraneMaterialName, "membrane materials"));
}

const MeshImport& need(const MeshImport* mesh, TomlTable& t) {
  if (!mesh) t.fail("group", "physical groups need a [mesh] table with file = \"....msh\"");
  return *mesh;
}

double prestrainOf(TomlTable& t) {
  const double p = t.number("prestrain", 0.0);
  if (p <= -1.0) t.fail("prestrain", "must be > -1");
  return p;
}

int addLineSet(Model& m, TomlTable& t, const std::string& name, bool sliding) {
  for (const auto& s : m.lineSets)
    if (s.name == name) t.fail("name", "duplicate set name '" + name + "'");
  m.lineSets.push_back({name, sliding});
  return static_cast<int>(m.lineSets.size()) - 1;
}

}  // namespace

const mesh::MeshGroup& MeshImport::group(TomlTable& t, const std::string& key, int dim) const {
  const std::string name = t.string(key);
  const mesh::MeshGroup* g = mesh.group(name, dim);
  if (!g) {
    // The closest few of the groups of this dimension (a generated parachute has 75), not all.
    std::vector<std::string> names;
    for (const auto& h : mesh.groups)
      if (h.dim == dim) names.push_back(h.name);
    t.fail(key, "no physical group '" + name + "' in " + file +
                    caseio::nameSuggestion(name, names, groupsOfDim(dim)));
  }
  if (g->dim != dim)
    t.fail(key, "physical group '" + name + "' in " + file + " is " + roleOfDim(g->dim) +
                    "; this needs " + roleOfDim(dim));
  if (g->elements.empty()) t.fail(key, "physical group '" + name + "' in " + file + " is empty");
  return *g;
}

std::unique_ptr<MeshImport> importMesh(Model& m, TomlTable t, const std::string& caseFile) {
  namespace fs = std::filesystem;
  auto imp = std::make_unique<MeshImport>();
  const std::string given = t.string("file");
  fs::path p(given);
  if (p.is_relative()) p = fs::path(caseFile).parent_path() / p;
  imp->file = p.lexically_normal().string();
  // Limits on the mesh read (docs/limits.md), raised with --set mesh.max_nodes=...
  mesh::MshLimits limits;
  limits.maxNodes = static_cast<std::size_t>(
      t.integer("max_nodes", static_cast<long>(limits.maxNodes), 1, 100000000));
  limits.maxElements = static_cast<std::size_t>(
      t.integer("max_elements", static_cast<long>(limits.maxElements), 1, 400000000));
  try {
    imp->mesh = mesh::readMesh(imp->file, limits);
  } catch (const mesh::MeshError& e) {
    t.fail("file", e.what());
  }
  const double scale = t.positive("scale", 1.0);
  const mesh::NodeVectors* start = nullptr;
  if (t.has("initial_displacement")) {
    const std::string view = t.string("initial_displacement");
    auto it = imp->mesh.views.find(view);
    if (it == imp->mesh.views.end()) {
      std::string list;
      for (const auto& [name, v] : imp->mesh.views) list += (list.empty() ? "" : ", ") + name;
      // gmsh's File > Save Mesh writes no views: the usual way a generated start is lost.
      t.fail("initial_displacement",
             "no 3-component NodeData view '" + view + "' in " + imp->file +
                 (list.empty() ? " (it has no views: a mesh saved by gmsh drops them; save the "
                                 "view too, or remove this key for a flat start)"
                               : " (views: " + list + ")"));
    }
    start = &it->second;
  }
  const auto& msh = imp->mesh;
  // Scaled coordinates within the +-1e100 every coordinate keeps (docs/limits.md): squared
  // distances stay finite.
  for (size_t i = 0; i < msh.nodeTags.size(); ++i)
    if ((scale * msh.coords[i]).cwiseAbs().maxCoeff() > caseio::kMaxLength)
      t.fail("scale", "node " + std::to_string(msh.nodeTags[i]) + " of " + imp->file +
                          " is beyond +-1e100 once scaled by " + caseio::shortNumber(scale));
  if (start) {
    // A start must place every node: a node it leaves out would start at its reference point,
    // torn from its neighbours.
    std::size_t missing = 0, first = 0;
    for (const std::size_t tag : msh.nodeTags) {
      const auto u = start->find(tag);
      if (u == start->end()) {
        if (missing++ == 0) first = tag;
      } else if ((scale * u->second).cwiseAbs().maxCoeff() > caseio::kMaxLength) {
        t.fail("initial_displacement", "node " + std::to_string(tag) +
                                           ": the start is beyond +-1e100 once scaled by " +
                                           caseio::shortNumber(scale));
      }
    }
    if (missing > 0)
      t.fail("initial_displacement", "view '" + t.string("initial_displacement") + "' of " +
                                         imp->file + " has no value at node " +
                                         std::to_string(first) + " (" + std::to_string(missing) +
                                         " of the mesh's " + std::to_string(msh.nodeTags.size()) +
                                         " nodes missing): it must give every node");
  }
  t.finish();

  for (size_t i = 0; i < msh.nodeTags.size(); ++i) {
    const std::size_t tag = msh.nodeTags[i];
    const int id = m.addNode(scale * msh.coords[i], "mesh." + std::to_string(tag));
    imp->node[tag] = id;
    if (start) m.u0[id] = scale * start->at(tag);
  }
  for (const auto& g : msh.groups) {
    std::vector<int> ids;
    std::vector<std::size_t> tags = g.nodes();
    if (g.dim == 1) {
      try {
        tags = mesh::orderedChain(g);  // a chain: its node set in order (drag edges)
      } catch (const mesh::MeshError&) {
      }
    }
    for (std::size_t tag : tags) ids.push_back(imp->node.at(tag));
    if (!m.nodeSets.count(g.name)) m.nodeSets[g.name] = ids;
    // A single-node point group names its node (confluence, grommet_0, payload, ...).
    if (g.dim == 0 && ids.size() == 1) {
      auto it = m.nodeByName.find(g.name);
      if (it != m.nodeByName.end() && it->second != ids[0])
        t.fail("file",
               "physical point '" + g.name + "' of " + imp->file + " has the name of another node");
      m.nodeByName[g.name] = ids[0];
      if (m.nodeName[ids[0]].rfind("mesh.", 0) == 0) m.nodeName[ids[0]] = g.name;
    }
  }
  return imp;
}

void readMeshCables(Model& m, const MeshImport* mesh, TomlTable t, int /*index*/) {
  const auto& g = need(mesh, t).group(t, "group", 1);
  if (t.has("path")) t.fail("path", "give either path or group");
  CableElement proto;
  proto.material = lineMaterialRef(m, t);
  const std::string name = t.string("name", g.name);
  const double prestrain = prestrainOf(t);
  t.finish();
  proto.set = addLineSet(m, t, name, false);
  for (const auto& e : g.elements) {
    CableElement c = proto;
    c.a = mesh->node.at(e[0]);
    c.b = mesh->node.at(e[1]);
    c.L = (m.X[c.b] - m.X[c.a]).norm() / (1.0 + prestrain);
    if (c.L <= 0.0) t.fail("group", "zero-length element in group '" + g.name + "'");
    m.cables.push_back(c);
  }
}

void readMeshSlidingGroup(Model& m, const MeshImport* mesh, TomlTable t, int /*index*/) {
  const auto& g = need(mesh, t).group(t, "group", 1);
  if (t.has("path")) t.fail("path", "give either path or group");
  SlidingGroupDef def;
  def.name = t.string("name", g.name);
  def.material = lineMaterialRef(m, t);
  std::vector<std::size_t> chain;
  try {
    chain = mesh::orderedChain(g);
  } catch (const mesh::MeshError& e) {
    t.fail("group", std::string(e.what()) + " in " + mesh->file);
  }
  for (std::size_t tag : chain) def.chain.push_back(mesh->node.at(tag));
  for (const auto& s : t.strings("sliders")) {
    auto it = m.nodeByName.find(s);
    if (it == m.nodeByName.end())
      t.fail("sliders", "unknown node '" + s + "' (a node name or a single-node physical point)" +
                            caseio::nameSuggestion(s, caseio::nodeNames(m), "nodes"));
    if (std::find(def.chain.begin(), def.chain.end(), it->second) != def.chain.end())
      t.fail("sliders", "slider '" + s + "' is a node of the chain '" + g.name + "'");
    def.sliders.push_back(it->second);
  }
  if (def.sliders.empty()) t.fail("sliders", "a sliding group needs at least one slider");
  const double prestrain = prestrainOf(t);
  std::vector<long> active;
  if (t.has("active")) active = t.integers("active");
  t.finish();
  for (size_t k = 0; k + 1 < def.chain.size(); ++k) {
    const double L = (m.X[def.chain[k + 1]] - m.X[def.chain[k]]).norm() / (1.0 + prestrain);
    if (L <= 0.0) t.fail("group", "zero-length element in group '" + g.name + "'");
    def.refLength.push_back(L);
  }
  if (!active.empty() && active.size() != def.sliders.size())
    t.fail("active",
           "needs one element index per slider (" + std::to_string(def.sliders.size()) + ")");
  // Initially active element: as given, or the one the slider lies on at the start X + u0: the
  // least detour l1 + l2 - |x_{k+1} - x_k| (zero on a straight element, small where the line
  // bends at the slider).
  auto x0 = [&](int n) -> Vec3 { return m.X[n] + m.u0[n]; };
  for (size_t s = 0; s < def.sliders.size(); ++s) {
    int best = -1;
    if (!active.empty()) {
      if (active[s] < 0 || active[s] >= def.numElements())
        t.fail("active", "element " + std::to_string(active[s]) + " out of range [0, " +
                             std::to_string(def.numElements() - 1) + "]");
      best = static_cast<int>(active[s]);
    } else {
      double least = std::numeric_limits<double>::infinity();
      const Vec3 xs = x0(def.sliders[s]);
      for (int k = 0; k < def.numElements(); ++k) {
        const Vec3 a = x0(def.chain[k]), b = x0(def.chain[k + 1]);
        const double detour = (xs - a).norm() + (b - xs).norm() - (b - a).norm();
        if (detour < least) least = detour, best = k;
      }
    }
    for (size_t o = 0; o < s; ++o)
      if (def.initialActive[o] == best)
        t.fail("sliders", "two sliders on element " + std::to_string(best) + " of '" + g.name +
                              "': use more elements so each slider has its own");
    def.initialActive.push_back(best);
  }
  def.set = addLineSet(m, t, def.name, true);
  m.groups.push_back(std::move(def));
}

void readMeshMembranes(Model& m, const MeshImport* mesh, TomlTable t) {
  const auto& g = need(mesh, t).group(t, "group", 2);
  if (t.has("mesh")) t.fail("mesh", "give either mesh or group");
  MembraneSet set;
  set.name = t.string("name", g.name);
  if (set.name != g.name && m.nodeSets.count(set.name))
    t.fail("name", "a node set '" + set.name + "' exists already");
  for (const auto& s : m.membraneSets)
    if (s.name == set.name) t.fail("name", "duplicate membrane set '" + set.name + "'");
  const int material = membraneMaterialRef(m, t);
  set.wrinkling = t.boolean("wrinkling", true);
  set.prestrain = prestrainOf(t);
  t.finish();
  const int setId = static_cast<int>(m.membraneSets.size());
  std::vector<int> nodes;
  for (std::size_t tag : g.nodes()) nodes.push_back(mesh->node.at(tag));
  m.nodeSets[set.name] = nodes;
  for (const auto& e : g.elements) {
    MembraneElement el;
    el.numNodes = static_cast<int>(e.size());
    el.set = setId;
    el.material = material;
    for (size_t i = 0; i < e.size(); ++i) el.nodes[i] = mesh->node.at(e[i]);
    m.membranes.push_back(el);
  }
  m.membraneSets.push_back(set);
}

void readMeshPointMasses(Model& m, const MeshImport* mesh, TomlTable t) {
  const auto& g = need(mesh, t).group(t, "group", 0);
  if (t.has("node")) t.fail("node", "give either node or group");
  const double mass = t.positive("mass");
  t.finish();
  for (std::size_t tag : g.nodes()) m.pointMass[mesh->node.at(tag)] += mass;
}

std::vector<std::array<int, 2>> meshEdges(const MeshImport* mesh, TomlTable& t) {
  const auto& g = need(mesh, t).group(t, "group", 1);
  std::vector<std::array<int, 2>> edges;
  for (const auto& e : g.elements) edges.push_back({mesh->node.at(e[0]), mesh->node.at(e[1])});
  return edges;
}

void holdUnusedMeshNodes(Model& m, const MeshImport& mesh) {
  std::vector<char> used(m.numNodes(), 0);
  for (const auto& c : m.cables) used[c.a] = used[c.b] = 1;
  for (const auto& g : m.groups) {
    for (int n : g.chain) used[n] = 1;
    for (int n : g.sliders) used[n] = 1;
  }
  for (const auto& e : m.membranes)
    for (int i = 0; i < e.numNodes; ++i) used[e.nodes[i]] = 1;
  for (const auto& [tag, id] : mesh.node)
    if (!used[id] && m.pointMass[id] == 0.0) m.constraint[id].fixed = {true, true, true};
}

}  // namespace chute
