#pragma once
// Values of a case outside the physical range of their kind, and settings that make a run much
// slower than the alternative: notes, not errors (the run goes on; docs/sanity.md gives the
// ranges and their sources). A slip of 1e3 or 1e6 in a fabric's thickness or modulus gives a
// valid case that runs to the end: these notes say so before an engineer reads its answer.
// The ranges are physical (SI); a case's `units` string says what its numbers are in
// ("m, kg, s, N" or "ft, slug, s, lbf": the generated cases' labels); a case whose units are
// neither is not judged.
#include <string>
#include <vector>

#include "case/CaseSpec.hpp"

namespace chute {

// The unit system a case's `units` string names.
enum class UnitSystem { Unknown, SI, FootSlug };
UnitSystem unitSystemOf(const std::string& units);

// One line each: "file:line: key: what, the range and why it matters".
std::vector<std::string> sanityNotes(const CaseSpec& spec);

}  // namespace chute
