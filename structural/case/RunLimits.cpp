#include "case/RunLimits.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "case/CaseError.hpp"
#include "case/SolverSetup.hpp"
#include "solver/StableStep.hpp"
#include "solver/StructuralSystem.hpp"

namespace chute {

namespace {

// The material of an element at node n (lines first, then membranes), for messages: its key in
// the case, E and density.
struct MaterialAt {
  std::string key;  // "materials.<name>"
  double E = 0.0, density = 0.0;
};
std::optional<MaterialAt> materialAt(const Model& m, int n) {
  auto line = [&](int k) {
    return MaterialAt{"materials." + m.materialName[k], m.materials[k].E, m.materials[k].density};
  };
  for (const auto& c : m.cables)
    if (c.a == n || c.b == n) return line(c.material);
  for (const auto& g : m.groups) {
    if (std::find(g.chain.begin(), g.chain.end(), n) != g.chain.end() ||
        std::find(g.sliders.begin(), g.sliders.end(), n) != g.sliders.end())
      return line(g.material);
  }
  for (const auto& e : m.membranes)
    for (int k = 0; k < e.numNodes; ++k)
      if (e.nodes[k] == n)
        return MaterialAt{"materials." + m.membraneMaterialName[e.material],
                          m.membraneMaterials[e.material].E,
                          m.membraneMaterials[e.material].density};
  return std::nullopt;
}

std::string nodeLabel(const Model& m, int n) {
  if (n < 0) return "a node";
  return m.nodeName[n].empty() ? "node " + std::to_string(n + 1) : "node '" + m.nodeName[n] + "'";
}

std::string g3(double x) {
  return fmt::format("{:.3g}", x);
}

}  // namespace

void checkRunSize(const CaseSpec& spec, TimeIntegrator& integrator, const StructuralState& from,
                  long stepsSoFar, int* limitingNode) {
  if (spec.solver.type == AnalysisType::Static) return;
  const auto est = integrator.estimateStep(from);
  if (!est) return;  // an implicit run: its steps were judged with the case (Solver.cpp)
  if (limitingNode) *limitingNode = est->limitingNode;
  const SolverSpec& sv = spec.solver;
  const Model& m = spec.model;
  const double left = std::max(0.0, sv.tEnd - from.t);
  const double steps = est->dt > 0.0 ? left / est->dt : std::numeric_limits<double>::infinity();
  auto where = [&](const std::string& key) { return whereIn(spec.settings, spec.file, key); };
  if (static_cast<double>(stepsSoFar) + steps > kMaxRunSteps) {
    // What makes the step so short: the material where it is shortest, or the safety factor or
    // the damping that shrink it further.
    const double undampedSteps = est->undamped > 0.0 ? left / (0.9 * est->undamped)
                                                     : std::numeric_limits<double>::infinity();
    std::string key, why;
    const auto mat = materialAt(m, est->limitingNode);
    if (undampedSteps > kMaxRunSteps || !(est->undamped > 0.0)) {
      if (mat) {
        // The key to name: the one of the two the command line overrode, if just one was (the
        // likelier slip), else the density where the case gives it, else E.
        auto overridden = [&](const std::string& k) {
          const auto it = spec.settings.find(k);
          return it != spec.settings.end() && it->second.origin.rfind("--set", 0) == 0;
        };
        const std::string E = mat->key + ".E", density = mat->key + ".density";
        if (overridden(E) != overridden(density))
          key = overridden(E) ? E : density;
        else
          key = spec.settings.count(density) ? density : E;
        why = fmt::format(
            "the stable step at {} (E = {}, density = {}) is {} before any safety "
            "factor: E or the density is out of scale",
            nodeLabel(m, est->limitingNode), g3(mat->E), g3(mat->density), g3(est->undamped));
      } else {
        key = "solver.integrator";
        why = fmt::format("the stable step at {} is {}", nodeLabel(m, est->limitingNode),
                          g3(est->undamped));
      }
    } else {
      const double damping = dampedStableStep(est->undamped, sv.stiffnessDamping) / est->undamped;
      if (damping < sv.safetyFactor) {
        key = "solver.stiffness_damping";
        why = fmt::format("stiffness_damping = {} shrinks the stable step {} (at {}) to {}",
                          g3(sv.stiffnessDamping), g3(est->undamped),
                          nodeLabel(m, est->limitingNode), g3(damping * est->undamped));
      } else {
        key = "solver.safety_factor";
        why = fmt::format("safety_factor = {} makes the step {} (the stable step {} at {})",
                          g3(sv.safetyFactor), g3(est->dt), g3(est->undamped),
                          nodeLabel(m, est->limitingNode));
      }
    }
    throw CaseError(fmt::format(
        "{}: central differences would take steps of {} from t = {}: {} steps to t_end = {}, "
        "more than the {} a run may take (docs/limits.md); {}",
        where(key), g3(est->dt), g3(from.t), g3(steps), g3(sv.tEnd), g3(kMaxRunSteps), why));
  }
  // Rows and frames every N steps at that step (interval-driven ones were judged with the case).
  const auto& out = spec.output;
  if (out.interval <= 0.0) {
    const double rows = steps / out.everySteps + 1.0;
    if (rows > static_cast<double>(out.maxRows))
      throw CaseError(
          fmt::format("{}: a row every {} steps of about {} is {} probe rows to t_end, more than "
                      "output.max_rows = {} (raise it, or give output.interval)",
                      where("output.every"), out.everySteps, g3(est->dt), g3(rows), out.maxRows));
  }
  if (out.vtu.write && out.vtu.interval <= 0.0) {
    const double frames = steps / out.vtu.everySteps + 1.0;
    if (frames > static_cast<double>(out.vtu.maxFrames))
      throw CaseError(
          fmt::format("{}: a frame every {} steps of about {} is {} VTU frames to t_end, more than "
                      "output.vtu.max_frames = {} (raise it, or give output.vtu.interval)",
                      where("output.vtu.every"), out.vtu.everySteps, g3(est->dt), g3(frames),
                      out.vtu.maxFrames));
  }
}

std::string stopReason(const CaseSpec& spec, const TimeIntegrator& integrator,
                       const StructuralState& s, long steps, long rows, long frames) {
  if (static_cast<double>(steps) >= kMaxRunSteps)
    return fmt::format(
        "stopped at t = {:.9g} after {} steps, the most a run may take "
        "(docs/limits.md)",
        s.t, steps);
  if (!integrator.takesNominalStep()) {
    const double left = (spec.solver.tEnd - s.t) / s.control.dt;
    if (!(s.control.dt > 0.0) || static_cast<double>(steps) + left > kMaxRunSteps)
      return fmt::format(
          "stopped at t = {:.9g}: the stable step has shrunk to {}, and the {} "
          "steps left to t_end would take the run past the {} a run may take "
          "(docs/limits.md)",
          s.t, g3(s.control.dt), g3(left), g3(kMaxRunSteps));
  }
  if (rows >= spec.output.maxRows)
    return fmt::format(
        "stopped at t = {:.9g}: {} probe rows written, output.max_rows "
        "(docs/limits.md)",
        s.t, rows);
  if (spec.output.vtu.write && frames >= spec.output.vtu.maxFrames)
    return fmt::format(
        "stopped at t = {:.9g}: {} VTU frames written, output.vtu.max_frames "
        "(docs/limits.md)",
        s.t, frames);
  return "";
}

void checkRunCanStart(const CaseSpec& spec, int* limitingNode) {
  if (spec.solver.type != AnalysisType::Dynamic) return;
  StructuralSystem sys(spec.model, spec.solver.search);
  const auto integrator = makeIntegrator(sys, spec.solver, spec.model, false);
  checkRunSize(spec, *integrator, sys.initialState(), 0, limitingNode);
}

}  // namespace chute
