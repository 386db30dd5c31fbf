// [reference]: the analytical solution a run is compared with.
#include <Eigen/Geometry>
#include <algorithm>
#include <stdexcept>
#include <string>

#include "case/CaseText.hpp"
#include "case/sections/SectionLookup.hpp"
#include "case/sections/Sections.hpp"
#include "verification/References.hpp"

namespace chute {

std::string_view referenceKindName(ReferenceKind k) {
  switch (k) {
    case ReferenceKind::Pulley:
      return "pulley";
    case ReferenceKind::BeadEllipse:
      return "bead_ellipse";
    case ReferenceKind::FreeFall:
      return "free_fall";
    case ReferenceKind::Hencky:
      return "hencky";
  }
  return "unknown";
}

namespace caseio {

void readReference(CaseSpec& c, TomlTable r) {
  const Model& m = c.model;
  ReferenceSpec ref;
  const std::string kind = r.choice("kind", "", {"pulley", "bead_ellipse", "free_fall", "hencky"});
  for (const auto k : {ReferenceKind::Pulley, ReferenceKind::BeadEllipse, ReferenceKind::FreeFall,
                       ReferenceKind::Hencky})
    if (kind == referenceKindName(k)) ref.kind = k;
  const std::string probe = r.string("probe");
  for (size_t p = 0; p < c.output.probes.size(); ++p)
    if (c.output.probes[p].name == probe) ref.probe = static_cast<int>(p);
  if (ref.probe < 0 || c.output.probes[ref.probe].kind != ProbeKind::NodePosition) {
    std::vector<std::string> names;
    for (const auto& pr : c.output.probes)
      if (pr.kind == ProbeKind::NodePosition) names.push_back(pr.name);
    r.fail("probe", "no node_position probe named '" + probe + "'" +
                        nameSuggestion(probe, names, "node_position probes"));
  }
  if (ref.kind == ReferenceKind::Pulley) {
    ref.pulley = nodeRef(m, r, "pulley", r.string("pulley"));
    const std::string group = r.string("group");
    for (const auto& g : m.groups)
      if (g.name == group)
        for (double L : g.refLength) ref.ropeLength += L;
    if (ref.ropeLength <= 0.0)
      r.fail("group", "unknown sliding group '" + group + "'" +
                          nameSuggestion(group, lineSetNames(m, false, true), "sliding groups"));
  } else if (ref.kind == ReferenceKind::Hencky) {
    const std::string set = r.string("membranes");
    int setId = -1;
    for (size_t k = 0; k < m.membraneSets.size(); ++k)
      if (m.membraneSets[k].name == set) setId = static_cast<int>(k);
    auto rim = m.nodeSets.find(set + ".rim");
    if (setId < 0 || rim == m.nodeSets.end())
      r.fail("membranes", "no disk membrane '" + set + "'" +
                              nameSuggestion(set, membraneSetNames(m), "membrane sets"));
    const int centre = c.output.probes[ref.probe].node;
    for (int n : rim->second) ref.radius = std::max(ref.radius, (m.X[n] - m.X[centre]).norm());
    for (const auto& e : m.membranes) {
      if (e.set != setId) continue;
      const auto& mat = m.membraneMaterials[e.material];
      ref.E = mat.E, ref.nu = mat.nu, ref.thickness = mat.thickness;
      ref.direction =
          (m.X[e.nodes[1]] - m.X[e.nodes[0]]).cross(m.X[e.nodes[2]] - m.X[e.nodes[0]]).normalized();
      break;
    }
    for (const auto& pl : m.pressures)
      if (pl.set == setId) ref.pressure += pl.pressure;
    if (ref.pressure == 0.0) r.fail("membranes", "no pressure on membrane set '" + set + "'");
  } else if (ref.kind == ReferenceKind::BeadEllipse) {
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

}  // namespace caseio
}  // namespace chute
