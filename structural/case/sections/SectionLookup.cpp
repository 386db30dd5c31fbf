// Shared lookups of the case sections (see SectionLookup.hpp).
#include "case/sections/SectionLookup.hpp"

#include <cstdio>

#include "case/CaseText.hpp"

namespace chute::caseio {

std::string shortNumber(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

// A coordinate triple within +-kMaxLength (required, or `fallback` when absent).
Vec3 point(TomlTable& t, const std::string& key, const Vec3* fallback) {
  const Vec3 x = fallback ? t.vec3(key, *fallback) : t.vec3(key);
  if (x.cwiseAbs().maxCoeff() > kMaxLength) t.fail(key, "coordinates beyond +-1e100");
  return x;
}
// A positive length up to kMaxLength.
double length(TomlTable& t, const std::string& key) {
  const double x = t.positive(key);
  if (x > kMaxLength) t.fail(key, "lengths beyond 1e100");
  return x;
}

std::vector<std::string> nodeNames(const Model& m) {
  std::vector<std::string> out;
  out.reserve(m.nodeByName.size());
  for (const auto& [name, id] : m.nodeByName) out.push_back(name);
  return out;
}
std::vector<std::string> nodeSetNames(const Model& m) {
  std::vector<std::string> out;
  for (const auto& [name, nodes] : m.nodeSets) out.push_back(name);
  return out;
}
std::vector<std::string> membraneSetNames(const Model& m) {
  std::vector<std::string> out;
  for (const auto& s : m.membraneSets) out.push_back(s.name);
  return out;
}
std::vector<std::string> lineSetNames(const Model& m, bool cables, bool sliding) {
  std::vector<std::string> out;
  for (const auto& s : m.lineSets)
    if (s.sliding ? sliding : cables) out.push_back(s.name);
  return out;
}

int nodeRef(const Model& m, TomlTable& t, const std::string& key, const std::string& name) {
  auto it = m.nodeByName.find(name);
  if (it == m.nodeByName.end())
    t.fail(key, "unknown node '" + name + "'" + nameSuggestion(name, nodeNames(m), "nodes"));
  return it->second;
}

int materialRef(const Model& m, TomlTable& t) {
  const std::string name = t.string("material");
  for (size_t i = 0; i < m.materialName.size(); ++i)
    if (m.materialName[i] == name) return static_cast<int>(i);
  for (const auto& membrane : m.membraneMaterialName)
    if (membrane == name)
      t.fail("material", "'" + name + "' is a membrane material, not a line one");
  t.fail("material", "unknown material '" + name + "'" +
                         nameSuggestion(name, m.materialName, "line materials"));
}

int membraneMaterialRef(const Model& m, TomlTable& t) {
  const std::string name = t.string("material");
  for (size_t i = 0; i < m.membraneMaterialName.size(); ++i)
    if (m.membraneMaterialName[i] == name) return static_cast<int>(i);
  t.fail("material", "no membrane material '" + name + "' (kind = \"membrane\")" +
                         nameSuggestion(name, m.membraneMaterialName, "membrane materials"));
}

// Cables, sliding groups and membranes name the nodes they generate after themselves, and probes
// and loads refer to them by name: one name, one entry.
std::string setName(const Model& m, TomlTable& t, const std::string& fallback) {
  const std::string name = fallback.empty() ? t.string("name") : t.string("name", fallback);
  if (name.empty()) t.fail("name", "cannot be empty");
  // Generated nodes and node sets are named "<name>.<...>": a dot would make names ambiguous.
  if (name.find('.') != std::string::npos) t.fail("name", "cannot contain '.'");
  for (const auto& s : m.lineSets)
    if (s.name == name)
      t.fail("name", "duplicate name: '" + name + "' is already a " +
                         (s.sliding ? "sliding group" : "cable set"));
  for (const auto& s : m.membraneSets)
    if (s.name == name) t.fail("name", "duplicate name: '" + name + "' is already a membrane set");
  if (m.nodeSets.count(name)) t.fail("name", "duplicate name: '" + name + "' is a node set");
  return name;
}

// Fails when adding `extra` nodes would take the model past kMaxNodes.
void checkNodeBudget(const Model& m, TomlTable& t, const std::string& key, long extra) {
  if (extra > kMaxNodes || m.numNodes() + extra > kMaxNodes)
    t.fail(key, "would make a model of more than " + std::to_string(kMaxNodes) +
                    " nodes (at least " + std::to_string(m.numNodes() + extra) + ")");
}

std::vector<int> nodesOf(const Model& m, TomlTable& t) {
  std::vector<int> out;
  if (t.has("nodes"))
    for (const auto& name : t.strings("nodes")) out.push_back(nodeRef(m, t, "nodes", name));
  if (t.has("set")) {
    const std::string set = t.string("set");
    auto it = m.nodeSets.find(set);
    if (it == m.nodeSets.end())
      t.fail("set",
             "unknown node set '" + set + "'" + nameSuggestion(set, nodeSetNames(m), "node sets"));
    out.insert(out.end(), it->second.begin(), it->second.end());
  }
  if (out.empty()) t.fail("nodes", "give nodes = [...] or set = \"...\"");
  return out;
}

}  // namespace chute::caseio
