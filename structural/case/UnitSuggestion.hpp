// What a number written with a unit ("2ms", "200 MPa") is in a case's own units, for the message
// that refuses it: case numbers are plain, in the units the case names (docs/case-files.md).
#pragma once

#include <optional>
#include <string>

namespace chute::caseio {

// `value` `unit` expressed in the unit system named by a case's `units` string (SI: "m, kg, s, N";
// foot-slug: "ft, slug, s, lbf"); nothing when the unit or the system is not known to it.
std::optional<double> inCaseUnits(double value, const std::string& unit,
                                  const std::string& caseUnits);

}  // namespace chute::caseio
