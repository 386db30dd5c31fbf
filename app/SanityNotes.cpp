#include "app/SanityNotes.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <set>
#include <sstream>

namespace chute {

namespace {

// SI values of a case's units (NIST SP 811: 1 ft = 0.3048 m, 1 lbf = 4.4482216152605 N,
// 1 slug = 1 lbf s^2 / ft).
struct Scales {
  double length = 1.0, mass = 1.0, force = 1.0;
};

// The ranges (docs/sanity.md has their sources).
constexpr double kArealMassMin = 0.010, kArealMassMax = 1.0;   // kg/m^2 of fabric
constexpr double kFabricEtMin = 1e3, kFabricEtMax = 1e7;       // N/m
constexpr double kLineEAMin = 10.0, kLineEAMax = 1e8;          // N
constexpr double kAirDensityMin = 0.01, kAirDensityMax = 2.0;  // kg/m^3

std::string g3(double x) {
  return fmt::format("{:.3g}", x);
}

}  // namespace

UnitSystem unitSystemOf(const std::string& units) {
  std::set<std::string> tokens;
  std::string word;
  for (const char c : units + ",") {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '^' || c == '/') {
      word += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    } else if (!word.empty()) {
      tokens.insert(word);
      word.clear();
    }
  }
  if (tokens.count("ft") && tokens.count("slug")) return UnitSystem::FootSlug;
  if (tokens.count("m") && tokens.count("kg")) return UnitSystem::SI;
  return UnitSystem::Unknown;
}

std::vector<std::string> sanityNotes(const CaseSpec& spec) {
  std::vector<std::string> notes;
  const Model& m = spec.model;
  auto where = [&](const std::string& key) { return whereIn(spec.settings, spec.file, key); };
  const UnitSystem system = unitSystemOf(spec.units);
  if (system != UnitSystem::Unknown) {
    Scales u;
    if (system == UnitSystem::FootSlug) {
      u.length = 0.3048, u.force = 4.4482216152605, u.mass = u.force / u.length;
    }
    const std::string siNote =
        system == UnitSystem::FootSlug ? " (in SI; the case is in ft, slug, s, lbf)" : "";
    // Fabric: areal mass and E t.
    for (size_t k = 0; k < m.membraneMaterials.size(); ++k) {
      const auto& mat = m.membraneMaterials[k];
      const std::string key = "materials." + m.membraneMaterialName[k];
      // The key a slip is likely in: the thickness when it is no cloth's (0.01 to 2 mm).
      const double thicknessSI = mat.thickness * u.length;
      const bool oddThickness = thicknessSI < 1e-5 || thicknessSI > 2e-3;
      const double areal = mat.density * mat.thickness * u.mass / (u.length * u.length);
      if (mat.density > 0.0 && (areal < kArealMassMin || areal > kArealMassMax))
        notes.push_back(fmt::format(
            "{}: density x thickness is {} kg/m^2 of fabric{}, outside {} to {} kg/m^2 "
            "(parachute cloth 0.03 to 0.5: docs/sanity.md): a slip in density or thickness?",
            where(key + (oddThickness ? ".thickness" : ".density")), g3(areal), siNote,
            g3(kArealMassMin), g3(kArealMassMax)));
      const double Et = mat.E * mat.thickness * u.force / u.length;  // (F/L^2) L = F/L
      if (Et < kFabricEtMin || Et > kFabricEtMax)
        notes.push_back(fmt::format(
            "{}: E x thickness is {} N/m{}, outside {} to {} N/m for fabrics (docs/sanity.md): "
            "a slip in E or thickness?",
            where(key + (oddThickness ? ".thickness" : ".E")), g3(Et), siNote, g3(kFabricEtMin),
            g3(kFabricEtMax)));
    }
    // Lines: E A (the force of a unit strain).
    for (size_t k = 0; k < m.materials.size(); ++k) {
      const auto& mat = m.materials[k];
      const std::string key = "materials." + m.materialName[k];
      const double EA = mat.E * mat.area * u.force;
      if (EA < kLineEAMin || EA > kLineEAMax)
        notes.push_back(
            fmt::format("{}: E x area is {} N{}, outside {} to {} N for lines, cords and risers "
                        "(docs/sanity.md): a slip in E or area?",
                        where(key + ".E"), g3(EA), siNote, g3(kLineEAMin), g3(kLineEAMax)));
    }
    // Air density of drag loads.
    const double rhoScale = u.mass / (u.length * u.length * u.length);
    auto airNote = [&](const std::string& key, double rho) {
      const double si = rho * rhoScale;
      if (si < kAirDensityMin || si > kAirDensityMax)
        notes.push_back(fmt::format(
            "{}: {} kg/m^3{}, outside {} to {} kg/m^3 (the standard atmosphere from sea level to "
            "30 km: docs/sanity.md)",
            where(key), g3(si), siNote, g3(kAirDensityMin), g3(kAirDensityMax)));
    };
    for (const auto& [key, s] : spec.settings) {
      const bool air = key.ends_with(".air_density") &&
                       (key.starts_with("loads.drag.") || key.starts_with("loads.face_drag."));
      double value = 0.0;
      if (air && std::istringstream(s.value) >> value) airNote(key, value);
    }
  }
  // An implicit integrator chosen on the command line for a case set up for central
  // differences (it gives their keys): measured several times slower (docs/sanity.md).
  const auto integrator = spec.settings.find("solver.integrator");
  if (spec.solver.type == AnalysisType::Dynamic &&
      spec.solver.integrator != IntegratorKind::CentralDifference &&
      integrator != spec.settings.end() && integrator->second.origin.rfind("--set ", 0) == 0) {
    for (const char* k : {"solver.stiffness_damping", "solver.safety_factor", "solver.target_dt",
                          "solver.mass_scaling_quantile"}) {
      const auto it = spec.settings.find(k);
      if (it == spec.settings.end() || it->second.origin.rfind("--set ", 0) == 0) continue;
      notes.push_back(fmt::format(
          "{}: solver.integrator = {} on a case set up for central differences ({} given at {}): "
          "implicit steps took 3.9x the wall time on the C-9 and 8.0x on a 5 m, 20-gore parachute "
          "under "
          "a given pressure "
          "(docs/sanity.md)",
          integrator->second.origin, integrator->second.value, k, it->second.origin));
      break;
    }
  }
  return notes;
}

}  // namespace chute
