// [[point_masses]]: masses at named nodes or on mesh groups.

#include "case/MeshGroups.hpp"
#include "case/sections/SectionLookup.hpp"
#include "case/sections/Sections.hpp"

namespace chute::caseio {

void readPointMasses(Model& m, const MeshImport* mesh, TomlTable& top) {
  for (auto& t : top.tables("point_masses")) {
    if (t.has("group")) {
      readMeshPointMasses(m, mesh, t);
      continue;
    }
    const int n = nodeRef(m, t, "node", t.string("node"));
    m.pointMass[n] += t.positive("mass");
    t.finish();
  }
}

}  // namespace chute::caseio
