// [contact]: fabric contact between the membrane and line sets that take part (docs/contact.md).
#include <Eigen/Geometry>
#include <algorithm>
#include <limits>
#include <string>

#include "case/sections/SectionLookup.hpp"
#include "case/sections/Sections.hpp"

namespace chute::caseio {

namespace {

// Indices of the sets named by `key` (all of them when absent).
template <class Set>
std::vector<int> setsNamed(TomlTable& t, const std::string& key, const std::vector<Set>& sets,
                           const std::string& kind) {
  std::vector<int> out;
  if (!t.has(key)) {
    for (int k = 0; k < static_cast<int>(sets.size()); ++k) out.push_back(k);
    return out;
  }
  for (const auto& name : t.strings(key)) {
    const auto it =
        std::find_if(sets.begin(), sets.end(), [&](const Set& s) { return s.name == name; });
    if (it == sets.end()) t.fail(key, "unknown " + kind + " '" + name + "'");
    const int k = static_cast<int>(it - sets.begin());
    if (std::find(out.begin(), out.end(), k) != out.end())
      t.fail(key, "'" + name + "' named twice");
    out.push_back(k);
  }
  return out;
}

// The smallest altitude of the contact triangles in the reference geometry (quads as the two
// triangles the contact sees).
double smallestAltitude(const Model& m, const std::vector<int>& sets) {
  double h = std::numeric_limits<double>::infinity();
  auto tri = [&](int a, int b, int c) {
    const Vec3 A = m.X[a], B = m.X[b], C = m.X[c];
    const double twice = (B - A).cross(C - A).norm();
    const double longest = std::max({(B - A).norm(), (C - B).norm(), (A - C).norm()});
    if (longest > 0.0) h = std::min(h, twice / longest);
  };
  for (const auto& e : m.membranes) {
    if (std::find(sets.begin(), sets.end(), e.set) == sets.end()) continue;
    tri(e.nodes[0], e.nodes[1], e.nodes[2]);
    if (e.numNodes == 4) tri(e.nodes[0], e.nodes[2], e.nodes[3]);
  }
  return h;
}

}  // namespace

void readContact(Model& m, TomlTable t) {
  ContactDef& c = m.contact;
  c.enabled = t.boolean("enabled", true);
  c.membraneSets = setsNamed(t, "membranes", m.membraneSets, "membrane set");
  c.lineSets = setsNamed(t, "lines", m.lineSets, "cable set or sliding group");
  if (c.membraneSets.empty())
    t.fail(t.has("membranes") ? "membranes" : "enabled",
           "contact needs at least one membrane set (lines touch only fabric)");
  // CT9-CT10 defaults: the cloth's own thickness, LS-DYNA's soft-constraint scale, a tenth of
  // critical damping at full penetration, nylon fabric's friction, a skin of one thickness.
  double cloth = 0.0;
  for (const auto& e : m.membranes)
    if (std::find(c.membraneSets.begin(), c.membraneSets.end(), e.set) != c.membraneSets.end())
      cloth = std::max(cloth, m.membraneMaterials[e.material].thickness);
  c.thickness = t.has("thickness") ? length(t, "thickness") : cloth;
  const double h = smallestAltitude(m, c.membraneSets);
  // CT11: features of a flat, stress-free mesh that share no node are at least one altitude
  // apart; a thickness beyond half of it would hold the mesh's own neighbours in contact at rest.
  if (!(c.thickness < 0.5 * h))
    t.fail("thickness", "contact thickness " + shortNumber(c.thickness) +
                            " is not below half the smallest altitude of the contact triangles (" +
                            shortNumber(h) +
                            "): neighbouring elements would be in contact at rest (refine the "
                            "mesh less there, or give a smaller thickness)");
  c.stiffnessScale = t.positive("stiffness_scale", 0.01);
  if (c.stiffnessScale > 1.0)
    t.fail("stiffness_scale",
           "must be at most 1 (above it the contact springs would set the "
           "explicit step instead of the fabric)");
  c.dampingRatio = t.nonNegative("damping_ratio", 0.1);
  if (c.dampingRatio > 1.0) t.fail("damping_ratio", "must be at most 1 (critical damping)");
  c.friction = t.nonNegative("friction", 0.25);
  if (c.friction > 2.0) t.fail("friction", "must be at most 2");
  c.slipSpeed = t.has("slip_speed") ? t.positive("slip_speed") : c.thickness;  // per second
  // CT10: a skin of six thicknesses (the near list's a quarter of it) balanced the candidate
  // lists' builds against the near lists' on the C-9 (docs/contact.md, "What it costs").
  c.skin = t.has("skin") ? length(t, "skin") : 6.0 * c.thickness;
  if (c.skin > 100.0 * c.thickness)
    t.fail("skin",
           "must be at most 100 times the thickness (the candidate lists would hold "
           "most of the mesh)");
  t.finish();
  if (!c.enabled) c = ContactDef{};
}

}  // namespace chute::caseio
