// [boundary]: fixed nodes, prescribed motions and constraints.
#include <string>

#include "case/sections/SectionLookup.hpp"
#include "case/sections/Sections.hpp"

namespace chute::caseio {

void readBoundary(Model& m, TomlTable b) {
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

}  // namespace chute::caseio
