// [air]: the air the structure moves in (docs/flight.md): the standard atmosphere at an altitude,
// or a density and an ambient pressure, and the wind.
#include <string>

#include "case/sections/SectionLookup.hpp"
#include "case/sections/Sections.hpp"
#include "model/StandardAtmosphere.hpp"

namespace chute::caseio {

namespace {
// The case's unit system from its `units` string: SI ("m, kg, s, N") or US customary ("ft, slug,
// s, lbf"); the standard atmosphere's values are converted into it.
struct UnitSystem {
  bool known = false;
  double metre = 1.0, densityPerSI = 1.0, pressurePerSI = 1.0;  // case units per SI unit
};
UnitSystem unitSystem(const std::string& units) {
  UnitSystem u;
  if (units.rfind("m,", 0) == 0 || units == "m") {
    u.known = true;
  } else if (units.rfind("ft,", 0) == 0 || units == "ft") {
    u.known = true;
    u.metre = 1.0 / 0.3048;                                          // ft per m (exact)
    u.densityPerSI = 0.3048 * 0.3048 * 0.3048 / 14.593902937206364;  // slug/ft^3 per kg/m^3
    u.pressurePerSI = 0.3048 * 0.3048 / 4.4482216152605;             // lbf/ft^2 per Pa
  }
  return u;
}
}  // namespace

void readAir(CaseSpec& c, TomlTable a) {
  AirSpec& air = c.model.air;
  air.given = true;
  const UnitSystem u = unitSystem(c.units);
  if (a.has("altitude")) {
    if (!u.known)
      a.fail("altitude",
             "the standard atmosphere needs the case's unit system: units = \"m, kg, s, N\" or "
             "\"ft, slug, s, lbf\" (or give density and pressure)");
    if (a.has("density") || a.has("pressure"))
      a.fail("altitude", "give either altitude or density and pressure");
    const double z = a.number("altitude");
    try {
      const AtmosphereState s = standardAtmosphere(z / u.metre);
      air.density = s.density * u.densityPerSI;
      air.pressure = s.pressure * u.pressurePerSI;
    } catch (const std::out_of_range& e) {
      a.fail("altitude", e.what());
    }
  } else {
    air.density = a.positive("density");
    if (a.has("pressure") || !u.known)
      air.pressure = a.positive("pressure");
    else
      air.pressure = standardAtmosphere(0.0).pressure * u.pressurePerSI;
  }
  const Vec3 still = Vec3::Zero();
  air.wind = point(a, "wind", &still);
  a.finish();
}

void readInitial(Model& m, TomlTable i) {
  m.v0.assign(m.numNodes(), Vec3::Zero());
  if (i.has("velocity")) {
    const Vec3 v = point(i, "velocity");
    for (auto& v0 : m.v0) v0 = v;
  }
  // Named sets after the whole: a set's velocity wins.
  for (auto& t : i.tables("velocities")) {
    const Vec3 v = point(t, "velocity");
    for (int n : nodesOf(m, t)) m.v0[n] = v;
    t.finish();
  }
  i.finish();
}

}  // namespace chute::caseio
