#include "solver/IntegratorKind.hpp"

#include <array>

namespace chute {

namespace {
constexpr std::array<std::pair<IntegratorKind, std::string_view>, 4> kNames{{
    {IntegratorKind::Bossak, "bossak"},
    {IntegratorKind::GeneralizedAlpha, "generalized_alpha"},
    {IntegratorKind::EnergyMomentum, "energy_momentum"},
    {IntegratorKind::CentralDifference, "central_difference"},
}};
}  // namespace

std::string_view integratorName(IntegratorKind k) {
  for (const auto& [kind, name] : kNames)
    if (kind == k) return name;
  return "unknown";
}

std::optional<IntegratorKind> integratorFromName(std::string_view name) {
  for (const auto& [kind, n] : kNames)
    if (n == name) return kind;
  return std::nullopt;
}

std::string_view analysisName(AnalysisType t) {
  return t == AnalysisType::Static ? "static" : "dynamic";
}

const std::vector<IntegratorKind>& integratorKinds() {
  static const std::vector<IntegratorKind> all{
      IntegratorKind::Bossak, IntegratorKind::GeneralizedAlpha, IntegratorKind::EnergyMomentum,
      IntegratorKind::CentralDifference};
  return all;
}

}  // namespace chute
