// Units a user may type by habit, with their size in SI and their dimension (length, mass, time
// exponents); the foot-slug system's base units from the same exact definitions (NIST SP 811).
#include "case/UnitSuggestion.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <set>

namespace chute::caseio {

namespace {

struct Unit {
  const char* name;
  double si;  // its size in SI units of its dimension
  int L, M, T;
};

constexpr double kFoot = 0.3048, kPoundForce = 4.4482216152605, kPound = 0.45359237;
constexpr double kSlug = kPoundForce / kFoot;  // lbf s^2 / ft

constexpr std::array kUnits{
    Unit{"m", 1.0, 1, 0, 0},
    Unit{"cm", 1e-2, 1, 0, 0},
    Unit{"mm", 1e-3, 1, 0, 0},
    Unit{"km", 1e3, 1, 0, 0},
    Unit{"ft", kFoot, 1, 0, 0},
    Unit{"in", 0.0254, 1, 0, 0},
    Unit{"s", 1.0, 0, 0, 1},
    Unit{"ms", 1e-3, 0, 0, 1},
    Unit{"min", 60.0, 0, 0, 1},
    Unit{"h", 3600.0, 0, 0, 1},
    Unit{"kg", 1.0, 0, 1, 0},
    Unit{"g", 1e-3, 0, 1, 0},
    Unit{"lb", kPound, 0, 1, 0},
    Unit{"slug", kSlug, 0, 1, 0},
    Unit{"N", 1.0, 1, 1, -2},
    Unit{"kN", 1e3, 1, 1, -2},
    Unit{"lbf", kPoundForce, 1, 1, -2},
    Unit{"Pa", 1.0, -1, 1, -2},
    Unit{"kPa", 1e3, -1, 1, -2},
    Unit{"MPa", 1e6, -1, 1, -2},
    Unit{"GPa", 1e9, -1, 1, -2},
    Unit{"psf", kPoundForce / (kFoot * kFoot), -1, 1, -2},
    Unit{"psi", kPoundForce / (0.0254 * 0.0254), -1, 1, -2},
    Unit{"m/s", 1.0, 1, 0, -1},
    Unit{"ft/s", kFoot, 1, 0, -1},
    Unit{"km/h", 1.0 / 3.6, 1, 0, -1},
    Unit{"kt", 1852.0 / 3600.0, 1, 0, -1},
    Unit{"m/s2", 1.0, 1, 0, -2},
    Unit{"m/s^2", 1.0, 1, 0, -2},
    Unit{"ft/s2", kFoot, 1, 0, -2},
    Unit{"ft/s^2", kFoot, 1, 0, -2},
    Unit{"kg/m3", 1.0, -3, 1, 0},
    Unit{"kg/m^3", 1.0, -3, 1, 0},
    Unit{"slug/ft3", kSlug / (kFoot * kFoot * kFoot), -3, 1, 0},
    Unit{"slug/ft^3", kSlug / (kFoot * kFoot * kFoot), -3, 1, 0},
    Unit{"N/m", 1.0, 0, 1, -2},
    Unit{"lbf/ft", kPoundForce / kFoot, 0, 1, -2},
    Unit{"lbf/in", kPoundForce / 0.0254, 0, 1, -2},
    Unit{"m2", 1.0, 2, 0, 0},
    Unit{"m^2", 1.0, 2, 0, 0},
    Unit{"ft2", kFoot* kFoot, 2, 0, 0},
    Unit{"ft^2", kFoot* kFoot, 2, 0, 0},
};

}  // namespace

std::optional<double> inCaseUnits(double value, const std::string& unit,
                                  const std::string& caseUnits) {
  std::set<std::string> tokens;
  std::string word;
  for (const char c : caseUnits + ",") {
    if (std::isalnum(static_cast<unsigned char>(c))) {
      word += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    } else if (!word.empty()) {
      tokens.insert(word);
      word.clear();
    }
  }
  double length = 0.0, mass = 0.0;
  if (tokens.count("ft") && tokens.count("slug") && tokens.count("s"))
    length = kFoot, mass = kSlug;
  else if (tokens.count("m") && tokens.count("kg") && tokens.count("s"))
    length = 1.0, mass = 1.0;
  else
    return std::nullopt;
  for (const Unit& u : kUnits)
    if (unit == u.name) return value * u.si / (std::pow(length, u.L) * std::pow(mass, u.M));
  return std::nullopt;
}

}  // namespace chute::caseio
