#pragma once
// What a number in a picture or a plot is, and its unit: the case's `units` note ("ft, slug, s,
// lbf", "m, kg, s, N, Pa") read into a unit system, and two tables -- the VTU fields (name ->
// display name, kind of quantity, categories) and the probe columns (probe kind -> its columns'
// quantities) -- so that a colour bar or an axis reads "membrane stress S1 (psf)" or
// "skirt radius (m)". A new field or probe column is one line in Quantities.cpp.
#include <optional>
#include <string>
#include <vector>

namespace chute::render {

// Kinds of quantity, by their dimension (the unit follows from the unit system).
enum class Quantity {
  Unknown,  // no unit known: shown without one
  Length,
  Velocity,
  Acceleration,
  Force,
  ForcePerLength,  // stress resultants of fabric (force per unit width)
  Stress,          // and pressure
  Energy,
  Time,
  Volume,      // length^3
  VolumeFlow,  // length^3 per time
  Strain,      // dimensionless
  Ratio,       // dimensionless
  Fraction,    // dimensionless, 0 to 1
  AngleRad,
  AngleDeg,
  Index,     // a count or an index: no unit
  Category,  // a code: drawn with categorical colours
};

// A case's unit system, as far as its `units` note tells it.
struct UnitSystem {
  std::string note;           // the note as written
  std::string length, force;  // e.g. "ft", "lbf"; empty when the note does not say
  std::string time = "s";     // "s" unless the note names another
  bool known() const { return !length.empty() && !force.empty(); }
};

// Reads a `units` note: the first length (m, mm, cm, km, ft, in), force (N, kN, mN, lbf) and
// time (s, ms) named in it; anything else is ignored.
UnitSystem parseUnits(const std::string& note);

// The unit of q in u ("psf", "Pa", "ft lbf", "N/m", "-", "deg"), or "" when u does not give it
// (and for indices and categories).
std::string unitOf(Quantity q, const UnitSystem& u);

// The name of the kind of quantity ("length", "force", ...), for an axis that shows several
// measurements of one kind.
std::string quantityName(Quantity q);

// "title (unit)", or just the title when there is no unit.
std::string withUnit(const std::string& title, Quantity q, const UnitSystem& u);

// One category of a categorical field: its code and its name.
struct Category {
  double code;
  std::string name;
};

// A VTU field as an engineer reads it.
struct FieldInfo {
  std::string name;   // as in the .vtu
  std::string title;  // display name ("membrane stress", "line force")
  Quantity quantity = Quantity::Unknown;
  std::vector<std::string> components;  // names of the components ("S1", "S2"); empty: x, y, z
  std::vector<Category> categories;     // for Quantity::Category
  double notApplicable = -1.0;          // the code of cells the field does not apply to (or NaN)
};

// The field's entry of the table, or a generic one (its name, unknown quantity).
FieldInfo vtuField(const std::string& name);

// A probe column as an engineer reads it: what is measured and its quantity.
struct ColumnInfo {
  std::string title;  // e.g. "skirt radius", "line force", "energy"
  Quantity quantity = Quantity::Unknown;
};

// The quantity of column `column` ("skirt.mean") of a probes.csv whose header is `header` (the
// kind of its probe is recognised by the set of columns the probe has).
ColumnInfo probeColumn(const std::string& column, const std::vector<std::string>& header);

// The probe kinds the table knows and their columns, in order (tested against ProbeSpec).
std::vector<std::pair<std::string, std::vector<std::string>>> probeKindColumns();

}  // namespace chute::render
