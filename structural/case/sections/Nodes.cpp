// [nodes]: named nodes and their coordinates.
#include <string>

#include "case/sections/SectionLookup.hpp"
#include "case/sections/Sections.hpp"

namespace chute::caseio {

void readNodes(Model& m, TomlTable nodes) {
  const auto names = nodes.keys();
  if (static_cast<long>(names.size()) > kMaxNodes)
    nodes.fail("", "more than " + std::to_string(kMaxNodes) + " nodes");
  for (const auto& name : names) {
    if (name.empty()) nodes.fail(name, "a node name cannot be empty");
    if (name.find('.') != std::string::npos) nodes.fail(name, "node names cannot contain '.'");
    m.addNode(point(nodes, name), name);
  }
}

}  // namespace chute::caseio
