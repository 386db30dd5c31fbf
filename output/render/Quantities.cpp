#include "render/Quantities.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace chute::render {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The words of a note: split at commas, spaces, semicolons and parentheses.
std::vector<std::string> words(const std::string& note) {
  std::vector<std::string> out;
  std::string w;
  for (const char c : note + " ") {
    if (c == ',' || c == ' ' || c == ';' || c == '(' || c == ')' || c == '\t') {
      if (!w.empty()) out.push_back(w);
      w.clear();
    } else {
      w += c;
    }
  }
  return out;
}

// Named stress units of (length, force): engineering practice, not force/length^2.
std::string stressUnit(const std::string& L, const std::string& F) {
  static const std::map<std::pair<std::string, std::string>, std::string> kNamed = {
      {{"ft", "lbf"}, "psf"},
      {{"in", "lbf"}, "psi"},
      {{"m", "N"}, "Pa"},
      {{"mm", "N"}, "MPa"},
      {{"m", "kN"}, "kPa"}};
  const auto it = kNamed.find({L, F});
  return it != kNamed.end() ? it->second : F + "/" + L + "²";
}

std::string energyUnit(const std::string& L, const std::string& F) {
  if (L == "m" && F == "N") return "J";
  if (L == "m" && F == "kN") return "kJ";
  if (L == "mm" && F == "N") return "mJ";
  return L + "·" + F;
}

}  // namespace

UnitSystem parseUnits(const std::string& note) {
  static const std::set<std::string> kLengths = {"m", "mm", "cm", "km", "ft", "in"};
  static const std::set<std::string> kForces = {"N", "kN", "mN", "lbf"};
  static const std::set<std::string> kTimes = {"s", "ms"};
  UnitSystem u;
  u.note = note;
  bool time = false;
  for (const auto& w : words(note)) {
    if (u.length.empty() && kLengths.count(w)) u.length = w;
    if (u.force.empty() && kForces.count(w)) u.force = w;
    if (!time && kTimes.count(w)) u.time = w, time = true;
  }
  return u;
}

std::string unitOf(Quantity q, const UnitSystem& u) {
  const std::string& L = u.length;
  const std::string& F = u.force;
  const std::string& T = u.time;
  switch (q) {
    case Quantity::Length:
      return L;
    case Quantity::Velocity:
      return L.empty() ? "" : L + "/" + T;
    case Quantity::Acceleration:
      return L.empty() ? "" : L + "/" + T + "²";
    case Quantity::Force:
      return F;
    case Quantity::ForcePerLength:
      return u.known() ? F + "/" + L : "";
    case Quantity::Stress:
      return u.known() ? stressUnit(L, F) : "";
    case Quantity::Energy:
      return u.known() ? energyUnit(L, F) : "";
    case Quantity::Time:
      return T;
    case Quantity::Volume:
      return L.empty() ? "" : L + "³";
    case Quantity::VolumeFlow:
      return L.empty() ? "" : L + "³/" + T;
    case Quantity::Strain:
    case Quantity::Ratio:
    case Quantity::Fraction:
      return "-";
    case Quantity::AngleRad:
      return "rad";
    case Quantity::AngleDeg:
      return "deg";
    case Quantity::Unknown:
    case Quantity::Index:
    case Quantity::Category:
      return "";
  }
  return "";
}

std::string quantityName(Quantity q) {
  switch (q) {
    case Quantity::Length:
      return "length";
    case Quantity::Velocity:
      return "velocity";
    case Quantity::Acceleration:
      return "acceleration";
    case Quantity::Force:
      return "force";
    case Quantity::ForcePerLength:
      return "force per length";
    case Quantity::Stress:
      return "stress";
    case Quantity::Energy:
      return "energy";
    case Quantity::Time:
      return "time";
    case Quantity::Volume:
      return "volume";
    case Quantity::VolumeFlow:
      return "volume flow";
    case Quantity::Strain:
      return "strain";
    case Quantity::Ratio:
      return "ratio";
    case Quantity::Fraction:
      return "fraction";
    case Quantity::AngleRad:
    case Quantity::AngleDeg:
      return "angle";
    case Quantity::Index:
      return "index";
    case Quantity::Category:
      return "state";
    case Quantity::Unknown:
      return "value";
  }
  return "value";
}

std::string withUnit(const std::string& title, Quantity q, const UnitSystem& u) {
  const std::string unit = unitOf(q, u);
  // Parentheses: VTK 9.1's own font draws "[" and "]" as "(" and ")" anyway.
  return unit.empty() ? title : title + " (" + unit + ")";
}

FieldInfo vtuField(const std::string& name) {
  // The VTU fields of docs/output.md. Codes of cells a field does not apply to: -1 (integer
  // fields) or NaN.
  static const std::vector<FieldInfo> kFields = {
      {"displacement", "displacement", Quantity::Length, {}, {}, kNaN},
      {"velocity", "velocity", Quantity::Velocity, {}, {}, kNaN},
      {"acceleration", "acceleration", Quantity::Acceleration, {}, {}, kNaN},
      {"reaction", "support reaction", Quantity::Force, {}, {}, kNaN},
      {"applied_load", "applied load", Quantity::Force, {}, {}, kNaN},
      {"axial_force", "line force", Quantity::Force, {}, {}, kNaN},
      {"axial_strain", "line strain", Quantity::Strain, {}, {}, kNaN},
      {"principal_stress", "membrane stress", Quantity::Stress, {"S1", "S2"}, {}, kNaN},
      {"principal_strain", "membrane strain", Quantity::Strain, {"E1", "E2"}, {}, kNaN},
      {"stress_resultant", "fabric load", Quantity::ForcePerLength, {"N1", "N2"}, {}, kNaN},
      {"utilisation", "utilisation N1/strength", Quantity::Ratio, {}, {}, kNaN},
      {"pressure", "pressure", Quantity::Stress, {}, {}, kNaN},
      {"slider_material_coordinate", "slider position s", Quantity::Length, {}, {}, kNaN},
      {"slider_tension_ratio", "tension ratio N2/N1", Quantity::Ratio, {}, {}, kNaN},
      {"wrinkling_state",
       "wrinkling",
       Quantity::Category,
       {},
       {{0, "taut"}, {1, "wrinkled"}, {2, "slack"}},
       -1.0},
      {"kind",
       "element kind",
       Quantity::Category,
       {},
       {{1, "cable"},
        {2, "truss"},
        {3, "sliding, inactive"},
        {4, "sliding, active"},
        {5, "membrane"},
        {6, "point mass"}},
       -1.0},
      {"slider_stick_state",
       "slider friction",
       Quantity::Category,
       {},
       {{-1, "slip (split shrinks)"}, {0, "stick"}, {1, "slip (split grows)"}},
       kNaN},
      // Indices: categories named from the frame (part_names) or numbered.
      {"part", "part", Quantity::Category, {}, {}, -1.0},
      {"slider_group", "sliding group", Quantity::Category, {}, {}, -1.0},
  };
  for (const auto& f : kFields)
    if (f.name == name) return f;
  return {name, name, Quantity::Unknown, {}, {}, kNaN};
}

namespace {

struct ProbeKind {
  std::string kind;
  std::vector<std::pair<std::string, ColumnInfo>> columns;
};

// The probe kinds of docs/output.md and the quantity of each column.
const std::vector<ProbeKind>& probeKinds() {
  static const std::vector<ProbeKind> kKinds = {
      {"node_position",
       {{"x", {"position", Quantity::Length}},
        {"y", {"position", Quantity::Length}},
        {"z", {"position", Quantity::Length}}}},
      {"node_velocity",
       {{"vx", {"velocity", Quantity::Velocity}},
        {"vy", {"velocity", Quantity::Velocity}},
        {"vz", {"velocity", Quantity::Velocity}}}},
      {"slider",
       {{"s", {"slider position s", Quantity::Length}},
        {"element", {"active element", Quantity::Index}}}},
      {"slider_friction",
       {{"state", {"stick (0) / slip (+-1)", Quantity::Category}},
        {"slip_rate", {"slip rate", Quantity::Velocity}},
        {"tension_ratio", {"tension ratio N2/N1", Quantity::Ratio}},
        {"wrap_angle", {"wrap angle", Quantity::AngleRad}},
        {"N1", {"line force", Quantity::Force}},
        {"N2", {"line force", Quantity::Force}}}},
      {"energy",
       {{"kinetic", {"energy", Quantity::Energy}},
        {"strain", {"energy", Quantity::Energy}},
        {"gravity", {"energy", Quantity::Energy}},
        {"total", {"energy", Quantity::Energy}}}},
      {"energy_balance",
       {{"work", {"energy", Quantity::Energy}}, {"balance", {"energy", Quantity::Energy}}}},
      {"line_force",
       {{"N", {"line force", Quantity::Force}}, {"strain", {"line strain", Quantity::Strain}}}},
      {"membrane_stress",
       {{"S1", {"membrane stress", Quantity::Stress}},
        {"S2", {"membrane stress", Quantity::Stress}}}},
      {"edge_angle", {{"angle", {"angle from the vertical", Quantity::AngleDeg}}}},
      {"wrinkling",
       {{"taut", {"fraction of membrane elements", Quantity::Fraction}},
        {"wrinkled", {"fraction of membrane elements", Quantity::Fraction}},
        {"slack", {"fraction of membrane elements", Quantity::Fraction}}}},
      {"skirt_radius",
       {{"mean", {"skirt radius", Quantity::Length}},
        {"min", {"skirt radius", Quantity::Length}},
        {"max", {"skirt radius", Quantity::Length}}}},
      // support_force and line_pull have the same columns: one title fits both.
      {"support_force",
       {{"fx", {"force", Quantity::Force}},
        {"fy", {"force", Quantity::Force}},
        {"fz", {"force", Quantity::Force}},
        {"magnitude", {"force", Quantity::Force}}}},
      {"line_pull",
       {{"fx", {"force", Quantity::Force}},
        {"fy", {"force", Quantity::Force}},
        {"fz", {"force", Quantity::Force}},
        {"magnitude", {"force", Quantity::Force}}}},
      {"line_force_max", {{"N", {"largest line force", Quantity::Force}}}},
      // The canopy's flow figures (output/FlightProbes.hpp, docs/flight.md).
      {"canopy",
       {{"volume", {"canopy volume", Quantity::Volume}},
        {"projected_diameter", {"projected diameter", Quantity::Length}},
        {"inside_pressure", {"inside pressure over ambient", Quantity::Stress}},
        {"dynamic_pressure", {"dynamic pressure", Quantity::Stress}},
        {"airspeed", {"airspeed", Quantity::Velocity}},
        {"descent_speed", {"descent speed", Quantity::Velocity}},
        {"inflow", {"volume flow", Quantity::VolumeFlow}},
        {"cloth_outflow", {"volume flow", Quantity::VolumeFlow}},
        {"vent_outflow", {"volume flow", Quantity::VolumeFlow}},
        {"swing", {"swing from the vertical", Quantity::AngleDeg}}}},
  };
  return kKinds;
}

}  // namespace

ColumnInfo probeColumn(const std::string& column, const std::vector<std::string>& header) {
  const auto dot = column.rfind('.');
  if (dot == std::string::npos) return {column, Quantity::Unknown};
  const std::string probe = column.substr(0, dot), suffix = column.substr(dot + 1);
  std::vector<std::string> suffixes;  // the probe's columns, in file order
  for (const auto& h : header)
    if (h.size() > probe.size() && h.compare(0, probe.size() + 1, probe + ".") == 0 &&
        h.find('.', probe.size() + 1) == std::string::npos)
      suffixes.push_back(h.substr(probe.size() + 1));
  // The kind whose columns the probe has (a column name alone is ambiguous: "strain" is an
  // energy of an energy probe and a strain of a line_force probe).
  for (const auto& k : probeKinds()) {
    std::vector<std::string> names;
    for (const auto& [name, info] : k.columns) names.push_back(name);
    if (names != suffixes) continue;
    for (const auto& [name, info] : k.columns)
      if (name == suffix) return info;
  }
  for (const auto& k : probeKinds())  // not recognised: the first kind with that column
    for (const auto& [name, info] : k.columns)
      if (name == suffix) return info;
  return {column, Quantity::Unknown};
}

std::vector<std::pair<std::string, std::vector<std::string>>> probeKindColumns() {
  std::vector<std::pair<std::string, std::vector<std::string>>> out;
  for (const auto& k : probeKinds()) {
    out.push_back({k.kind, {}});
    for (const auto& [name, info] : k.columns) out.back().second.push_back(name);
  }
  return out;
}

}  // namespace chute::render
