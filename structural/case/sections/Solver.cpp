// [solver]: static or dynamic, integrator, steps and Newton settings.
#include <string>

#include "case/sections/SectionLookup.hpp"
#include "case/sections/Sections.hpp"
#include "terms/sliding/SlidingGroupTerm.hpp"

namespace chute::caseio {

namespace {

// Most steps a dynamic run may ask for (t_end / dt), and the least step relative to t_end that
// still advances time (a few ulps of t_end).
constexpr double kMaxSteps = 1e9;
constexpr double kMaxMassDamping = 1e12;  // 1/s
constexpr double kLeastRelativeStep = 1e-15;

// The terms the energy-momentum scheme has discrete gradients for (docs/formulation.md section
// 10): any other strain energy would be integrated by the plain midpoint rule, which conserves
// neither energy nor, for stiff parts, stability. Refused rather than run silently otherwise.
void checkEnergyMomentumModel(const Model& m, TomlTable& s) {
  std::string what;
  if (m.contact.enabled) what = "fabric contact ([contact]: no discrete gradient of its penalty)";
  for (size_t gi = 0; gi < m.groups.size() && what.empty(); ++gi) {
    const auto& g = m.groups[gi];
    for (size_t k = 0; k < g.sliders.size() && what.empty(); ++k)
      if (g.frictionOf(static_cast<int>(k)))
        what = "friction, lock or one-way flow at the sliders of sliding group '" + g.name + "'";
    // A massless chain of several elements is condensed to one polyline (EM12): its inner nodes
    // must be the chain's alone; with mass the hand-overs are located as events (EM13).
    if (what.empty() && m.materials[g.material].density == 0.0 && g.numElements() > 1 &&
        !SlidingGroupTerm(m, static_cast<int>(gi), SliderSearch::MaterialCoordinate).condensable())
      what = "a massless sliding group '" + g.name +
             "' of several elements whose inner nodes carry something else (a point mass, "
             "another element, drag or a support: EM12 needs them to be the line's alone)";
    if (what.empty() && g.sliders.size() > 5)
      what = "more than 5 sliders on sliding group '" + g.name + "'";
  }
  if (!what.empty())
    s.fail("integrator",
           "\"energy_momentum\" does not support " + what + " (docs/formulation.md section 10)");
}

}  // namespace

void readSolver(CaseSpec& c, TomlTable s) {
  Model& m = c.model;
  auto& sv = c.solver;
  sv.type = s.choice("type", "dynamic", {"dynamic", "static"}) == "static" ? AnalysisType::Static
                                                                           : AnalysisType::Dynamic;
  if (sv.type == AnalysisType::Dynamic) {
    sv.dt = s.positive("dt");
    sv.tEnd = s.positive("t_end");
    sv.rhoInf = s.number("rho_inf", 0.9);
    std::vector<std::string> names;
    for (const auto k : integratorKinds()) names.emplace_back(integratorName(k));
    sv.integrator = *integratorFromName(s.choice("integrator", "bossak", names));
    if (sv.integrator == IntegratorKind::EnergyMomentum) {
      sv.emDissipation = s.nonNegative("em_dissipation", 0.0);
      checkEnergyMomentumModel(m, s);
      sv.emOrder = static_cast<int>(s.integer("em_order", 2, 2, 4));
      if (sv.emOrder == 3) s.fail("em_order", "must be 2 or 4");
      if (sv.emOrder == 4) {
        // EM14's middle step runs backwards in time: an event located inside a step has no
        // time to be cut at, and the dissipative variant is the opposite of its purpose.
        if (sv.emDissipation > 0.0)
          s.fail("em_order", "4 conserves energy: it takes em_dissipation = 0");
        for (const auto& g : m.groups)
          if (g.numElements() > 1 && !SlidingGroupTerm(m, static_cast<int>(&g - m.groups.data()),
                                                       SliderSearch::MaterialCoordinate)
                                          .condensable())
            s.fail("em_order", "4 cannot locate the hand-overs of sliding group '" + g.name +
                                   "' (a line with mass, EM13): use em_order = 2");
      }
    } else {
      s.notUsed({"em_dissipation", "em_order"}, "without integrator = \"energy_momentum\"");
    }
    // Explicit (docs/formulation.md EX1-EX8; dt is then the largest step allowed). Read and checked
    // whatever the integrator, as the implicit integrators' keys are under central_difference: a
    // case carries both sets and changes integrator with one --set (the C-9 cases do).
    sv.safetyFactor = s.positive("safety_factor", 0.9);
    if (sv.safetyFactor > 1.0) s.fail("safety_factor", "must be in (0, 1]");
    sv.targetDt = s.nonNegative("target_dt", 0.0);
    sv.massScalingQuantile = s.nonNegative("mass_scaling_quantile", 0.0);
    if (sv.massScalingQuantile > 0.5) s.fail("mass_scaling_quantile", "must be in [0, 0.5]");
    if (sv.massScalingQuantile > 0.0 && sv.targetDt > 0.0)
      s.fail("mass_scaling_quantile",
             "is given with target_dt: both ask for mass scaling, give one");
    sv.stiffnessDamping = s.nonNegative("stiffness_damping", 0.0);
    m.massDamping = s.nonNegative("mass_damping", 0.0);
    // alpha M overflowed at 1.8e308 and was refused as "mass not finite", naming no key; 1e12 /s
    // damps a mode of 1e-12 s critically, beyond any step a run takes (docs/case-files.md).
    if (m.massDamping > kMaxMassDamping) s.fail("mass_damping", "must be at most 1e12 (1/s)");
    sv.energyTolerance = s.nonNegative("energy_tolerance", sv.energyTolerance);
    if (sv.rhoInf < 0.0 || sv.rhoInf > 1.0) s.fail("rho_inf", "must be in [0, 1]");
    sv.dtMin = s.positive("dt_min", sv.dt * 1e-6);
    if (sv.dtMin > sv.dt) s.fail("dt_min", "must not exceed dt");
    // Steps a run can take (docs/limits.md): dt within t_end, at most kMaxSteps of it, and a
    // least step that still moves time near t_end (t + dt_min == t would loop forever).
    if (sv.dt > sv.tEnd) s.fail("dt", "is larger than t_end: not one step fits");
    if (sv.tEnd / sv.dt > kMaxSteps)
      s.fail("dt", "t_end / dt is " + shortNumber(sv.tEnd / sv.dt) + " steps, more than " +
                       shortNumber(kMaxSteps));
    if (sv.dtMin < kLeastRelativeStep * sv.tEnd)
      s.fail(s.has("dt_min") ? "dt_min" : "dt",
             "the least step (dt_min = " + shortNumber(sv.dtMin) +
                 ") is lost in rounding near t_end: keep it above t_end * 1e-15");
    // Load stepping is the static solve's (a dynamic run's loads follow time and their ramps).
    s.notUsed({"load_steps", "initial_load_factor"},
              "by dynamic runs (load steps are the static solve's: type = \"static\")");
  } else {
    s.notUsed({"dt", "t_end", "rho_inf", "integrator", "mass_damping", "dt_min", "em_dissipation",
               "safety_factor", "target_dt", "mass_scaling_quantile", "stiffness_damping",
               "energy_tolerance"},
              "by static runs (type = \"static\")");
    sv.loadSteps = static_cast<int>(s.integer("load_steps", 1, 1, 1000000));
    sv.initialLoadFactor = s.positive("initial_load_factor", 0.0 + 1.0);
    if (sv.initialLoadFactor > 1.0) s.fail("initial_load_factor", "must be in (0, 1]");
  }
  m.massKind = s.choice("mass", "lumped", {"lumped", "consistent"}) == "lumped"
                   ? kernels::MassKind::Lumped
                   : kernels::MassKind::Consistent;
  sv.search = s.choice("search", "material_coordinate",
                       {"nearest_length", "material_coordinate"}) == "nearest_length"
                  ? SliderSearch::NearestLength
                  : SliderSearch::MaterialCoordinate;
  sv.maxNewton = static_cast<int>(s.integer("newton_max_iterations", 25, 1, 1000));
  sv.maxEquations = s.integer("max_equations", sv.maxEquations, 1, 100000000);
  if (s.has("newton_tolerance")) sv.tolDisplacement = s.positive("newton_tolerance");
  // EM14 (em_order = 4) crosses slack / taut kinks inside its steps (EM4 is exact there).
  sv.slackTautEvents = s.boolean("slack_events", sv.emOrder != 4);
  if (sv.emOrder == 4 && sv.slackTautEvents)
    s.fail("slack_events", "true cannot be located inside em_order = 4's steps (EM14)");
  sv.sliderEvents = s.boolean("slider_events", true);
  sv.reuseTangent = s.boolean("reuse_tangent", false);
  sv.symmetricPartSolver =
      s.choice("linear_solver", "auto", {"auto", "symmetric_part"}) == "symmetric_part";
  // FL: the captured air couples every face of a canopy through its volume (a dense Jacobian):
  // loads from the airflow are stepped by the explicit integrator only (docs/flight.md).
  if (!m.canopyFlows.empty() &&
      (sv.type == AnalysisType::Static || sv.integrator != IntegratorKind::CentralDifference))
    s.fail(sv.type == AnalysisType::Static ? "type" : "integrator",
           "loads from the airflow ([[loads.canopy_flow]]) need type = \"dynamic\" and "
           "integrator = \"central_difference\" (the captured air couples every face of the "
           "canopy through its volume)");
  // Slider hand-over inside a step needs the forces at the step's end: Bossak, or explicit
  // (which always hands over inside the step).
  if (!sv.sliderEvents && sv.integrator != IntegratorKind::Bossak &&
      sv.integrator != IntegratorKind::CentralDifference)
    s.fail("slider_events",
           "false needs integrator = \"bossak\" (forces at the step's end, where a slider "
           "crossed inside the step is in its new element)");
  s.finish();
}

}  // namespace chute::caseio
