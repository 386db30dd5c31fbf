#pragma once
// The time integrators a case may ask for (solver.integrator), parsed once by the case reader.
#include <optional>
#include <string_view>
#include <vector>

namespace chute {

enum class IntegratorKind { Bossak, GeneralizedAlpha, EnergyMomentum, CentralDifference };
// The case-file spelling of each kind, and back (nullopt: unknown).
std::string_view integratorName(IntegratorKind k);
std::optional<IntegratorKind> integratorFromName(std::string_view name);
const std::vector<IntegratorKind>& integratorKinds();

// Statics (load stepping to equilibrium) or dynamics (time integration): solver.type.
enum class AnalysisType { Static, Dynamic };
std::string_view analysisName(AnalysisType t);

}  // namespace chute
