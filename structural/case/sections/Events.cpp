// [[events]]: cable sets cut during the run.
#include <algorithm>
#include <cmath>
#include <string>

#include "case/CaseText.hpp"
#include "case/sections/SectionLookup.hpp"
#include "case/sections/Sections.hpp"

namespace chute::caseio {

// [[events]] cut = "<cable set>", at = t: the set carries load up to t and is gone after it.
void readEvents(Model& m, TomlTable& top) {
  for (auto& t : top.tables("events")) {
    const std::string set = t.string("cut");
    auto it = std::find_if(m.lineSets.begin(), m.lineSets.end(),
                           [&](const LineSet& s) { return s.name == set; });
    if (it == m.lineSets.end())
      t.fail("cut", "unknown cable set '" + set + "'" +
                        nameSuggestion(set, lineSetNames(m, true, false), "cable sets"));
    if (it->sliding)
      t.fail("cut", "'" + set + "' is a sliding group; only [[cables]] sets can be cut");
    if (std::isfinite(it->cutAt)) t.fail("cut", "'" + set + "' is cut twice");
    it->cutAt = t.nonNegative("at", 0.0);
    t.finish();
  }
}

}  // namespace chute::caseio
