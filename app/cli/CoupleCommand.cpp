// `chute couple CASE [--scheme explicit|implicit] [--relaxation constant|aitken] ...`: the coupled
// demo. The case's structure (CouplingInterface) and a quasi-steady flow model (a separate
// participant that sees only the interface data) exchange pressure and motion every time window;
// one line per window shows the sub-iterations and the final relative residual. It writes what
// `chute run` writes (probes, VTU series, summary), with any integrator the case names.
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "OutputError.hpp"
#include "app/RunCase.hpp"
#include "app/RunOutput.hpp"
#include "app/cli/Command.hpp"
#include "case/CaseError.hpp"
#include "case/CaseSpec.hpp"
#include "case/UnitSuggestion.hpp"
#include "coupling/CouplingDriver.hpp"

namespace chute::cli {
namespace {

struct CoupleArgs {
  std::string caseFile, outDir, scheme = "implicit", relaxation = "aitken";
  std::vector<std::string> sets, surface;
  double omega = 0.5, tolerance = 1e-8, window = 0.0, tEnd = 0.0;
  int maxIterations = 100;
  // NaN: not given, the SI default (60 Pa, 1.2 kg/m^3, 0.03 m) in the case's units.
  double q = std::numeric_limits<double>::quiet_NaN(), ramp = 0.02,
         airDensity = std::numeric_limits<double>::quiet_NaN(), cn = 1.0,
         addedMass = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> wind = {0.0, 0.0, 0.0};
  bool quiet = false;
};

// As many windows as a run may take steps (limits.md).
constexpr double kMaxWindows = 1e9;

// What a coupled run reports in summary.json beside a run's figures.
void countWindows(const coupling::CouplingReport& rep, RunResult& r) {
  r.notes.push_back(fmt::format("coupled run: {} windows, {} structural solves ({:.2f} per window)",
                                rep.windows.size(), rep.iterations(), rep.iterationsPerWindow()));
}

int couple(const CoupleArgs& a) {
  using namespace chute::coupling;
  const auto wall0 = std::chrono::steady_clock::now();
  CaseSpec spec;
  try {
    spec = readCase(a.caseFile, a.sets);
  } catch (const CaseError& e) {
    fmt::print(stderr, "chute: {}\n", e.what());
    return kExitBadInput;
  }
  std::unique_ptr<CouplingInterface> structure;
  try {
    structure = std::make_unique<CouplingInterface>(spec, a.surface);
  } catch (const std::exception& e) {  // a static case, an unknown set, massless explicit nodes
    fmt::print(stderr, "chute: {}: {}\n", a.caseFile, e.what());
    return kExitBadInput;
  }
  // The flow's defaults are SI figures; a case in ft, slug, s, lbf gets them in its units, and
  // every figure is labelled in the case's units.
  const bool feet = caseio::inCaseUnits(1.0, "ft", spec.units).value_or(0.0) == 1.0;
  const auto inCase = [&](double given, double si, const char* unit) {
    return std::isnan(given) ? caseio::inCaseUnits(si, unit, spec.units).value_or(si) : given;
  };
  const double q = inCase(a.q, 60.0, "Pa"), airDensity = inCase(a.airDensity, 1.2, "kg/m3"),
               addedMass = inCase(a.addedMass, 0.03, "m");
  const char* lengthUnit = feet ? "ft" : "m";
  const char* pressureUnit = feet ? "psf" : "Pa";
  const char* arealMassUnit = feet ? "slug/ft^2" : "kg/m^2";
  QuasiSteadyFlowLaw law;
  law.stagnationPressure = q, law.rampTime = a.ramp, law.airDensity = airDensity;
  law.normalDragCoefficient = a.cn, law.addedMassLength = addedMass;
  law.wind = Vec3(a.wind[0], a.wind[1], a.wind[2]);
  const QuasiSteadyFlow flow(structure->surface(), law);
  CouplingSettings cs;
  cs.scheme = a.scheme == "explicit" ? CouplingScheme::Explicit : CouplingScheme::Implicit;
  cs.relaxation = a.relaxation == "constant" ? Relaxation::Constant : Relaxation::Aitken;
  cs.omega = a.omega, cs.tolerance = a.tolerance, cs.maxIterations = a.maxIterations;
  cs.window = a.window, cs.tEnd = a.tEnd;
  const double tEnd = a.tEnd > 0.0 ? a.tEnd : spec.solver.tEnd;
  // The windows, checked before anything is written (exit-codes.md): a window or an end time
  // shorter than the case's least step cannot be stepped, and the windows to the end are bounded
  // as a run's steps are (limits.md).
  for (const auto& [option, given] : {std::pair{"--window", a.window}, {"--t-end", a.tEnd}})
    if (given > 0.0 && given < spec.solver.dtMin) {
      fmt::print(stderr,
                 "chute: couple: {}: {:g} is shorter than the case's least step "
                 "(solver.dt_min = {:g})\n",
                 option, given, spec.solver.dtMin);
      return kExitBadInput;
    }
  if (const double window = a.window > 0.0 ? a.window : spec.solver.dt;
      tEnd / std::min(window, tEnd) > kMaxWindows) {
    fmt::print(stderr, "chute: couple: --window: {:g} windows to t = {:g}, more than {:g}\n",
               tEnd / window, tEnd, kMaxWindows);
    return kExitBadInput;
  }

  // The output of `chute run` (probes, VTU series, summary), written at the ends of the accepted
  // windows that reach an output time (docs/coupling.md).
  const std::string outDir = a.outDir.empty() ? "out/" + spec.name : a.outDir;
  // The flow's answer to the start, checked before anything is written: a finite but huge wind or
  // q overflows the law's pressures (--wind 1e200: infinite), bad input naming the options.
  const Eigen::VectorXd startPressures = flow.facePressures(writeInterfaceData(*structure));
  if (!startPressures.allFinite()) {
    fmt::print(stderr,
               "chute: couple: --wind, --q, --air-density: the flow's pressures on the start are "
               "not finite (values out of scale)\n");
    return kExitBadInput;
  }
  RunResult r;
  std::unique_ptr<RunOutput> out;
  std::unique_ptr<std::ofstream> csv;
  try {
    std::filesystem::create_directories(outDir);
    out = std::make_unique<RunOutput>(structure->spec(), structure->system(), outDir, nullptr, r);
    out->setEquilibrium(
        [&](const StructuralState& s) { return structure->integrator().equilibrium(s); });
    // The flow's loads on the start act from t = 0 (initial data), then the start is written.
    structure->setFacePressures(startPressures);
    structure->initializeWithLoads();
    out->record(structure->state());
    out->frame(structure->state());
    csv = std::make_unique<std::ofstream>(outDir + "/coupling.csv");
    *csv << "t,iterations,residual,apex_z,mean_pressure\n";
  } catch (const OutputError& e) {
    fmt::print(stderr, "chute: couple: {}\n", e.what());
    return kExitOutputFailed;
  } catch (const std::exception& e) {
    fmt::print(stderr, "chute: {}\n", e.what());
    return kExitBadInput;
  }

  // The apex: the wet vertex farthest from the rim's plane at the end, reported per window.
  const int apexNode = spec.model.nodeByName.count("canopy.center")
                           ? spec.model.nodeId("canopy.center")
                           : structure->surface().node[structure->numVertices() / 2];
  const double mass =
      spec.model.membraneMaterials.empty()
          ? 0.0
          : spec.model.membraneMaterials[0].density * spec.model.membraneMaterials[0].thickness;
  if (!a.quiet)
    fmt::print(
        "{}: {} coupling, {} relaxation (omega {}), {} faces, {} vertices, {}; flow: q = {:.4g} "
        "{}, rho_air = {:.4g}, C_n = {}, added mass rho_air L_a = {:.3g} {} (fabric {:.3g} {})\n",
        spec.name, a.scheme, a.relaxation, a.omega, structure->numFaces(), structure->numVertices(),
        structure->integrator().name(), q, pressureUnit, airDensity, a.cn, airDensity * addedMass,
        arealMassUnit, mass, arealMassUnit);
  long windows = 0;
  coupling::CouplingReport rep;
  try {
    rep = runCoupled(
        *structure, [&](const InterfaceData& d) { return flow.facePressures(d); }, cs,
        [&](const WindowReport& w) {
          ++windows;
          const double z = structure->state().x[3 * apexNode + 2] - spec.model.X[apexNode].z();
          const double pm = structure->loads().facePressures().mean();
          if (!a.quiet)
            fmt::print(
                "  window {:4d}  t = {:.5f}  sub-iterations {:3d}  residual {:.3e}  "
                "apex {:+.5f} {}  mean p {:.4g} {}\n",
                windows, w.t, w.iterations, w.residual, z, lengthUnit, pm, pressureUnit);
          *csv << fmt::format("{},{},{},{},{}\n", w.t, w.iterations, w.residual, z, pm);
          if (w.accepted)
            out->afterStep(structure->state(), structure->counters().steps,
                           structure->stepper().reached(w.t, tEnd));
        });
  } catch (const OutputError& e) {
    fmt::print(stderr, "chute: couple: {}\n", e.what());
    return kExitOutputFailed;
  }
  const auto& c = structure->counters();
  if (!a.quiet)
    fmt::print(
        "{}: {} windows, {} structural solves ({:.2f} per window), {} steps, {} Newton "
        "iterations, {} rejected steps\n",
        rep.converged ? "completed" : "failed", rep.windows.size(), rep.iterations(),
        rep.iterationsPerWindow(), c.steps, c.newtonIterations, c.rejectedSteps);
  if (!rep.converged) {
    r.status = RunStatus::Diverged;
    r.reason = rep.failure;
    out->lastGoodState(structure->state());
  }
  countWindows(rep, r);
  r.finalTime = structure->time();
  r.steps = c.steps, r.rejectedSteps = c.rejectedSteps, r.eventRetries = c.eventRetries;
  r.newtonIterations = c.newtonIterations;
  out->flush();
  r.vtuFrames = out->vtuFrames();
  r.timings = structure->system().timings();
  r.work = structure->system().work();
  r.equations = structure->system().numEquations();
  const LinearSolver* ls = structure->integrator().linearSolver();
  r.linearSolver = ls ? ls->kindName() : "none";
  r.wallTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  try {
    writeSummary(outDir + "/summary.json", structure->spec(), r);
  } catch (const OutputError& e) {
    fmt::print(stderr, "chute: couple: {}\n", e.what());
    return kExitOutputFailed;
  }
  if (!rep.converged) {
    fmt::print(stderr, "chute: {}: {}\n", spec.name, rep.failure);
    return kExitRunFailed;
  }
  return 0;
}

}  // namespace

Command addCoupleCommand(CLI::App& app) {
  auto a = std::make_shared<CoupleArgs>();
  auto* cmd = app.add_subcommand(
      "couple", "run a case coupled to a quasi-steady flow model (partitioned FSI demo)");
  cmd->add_option("case", a->caseFile, "case file (TOML), dynamic, with membranes")->required();
  cmd->add_option("--scheme", a->scheme, "explicit (staggered) or implicit (sub-iterated)")
      ->check(CLI::IsMember({"explicit", "implicit"}));
  cmd->add_option("--relaxation", a->relaxation,
                  "under-relaxation of the pressure: constant|aitken")
      ->check(CLI::IsMember({"constant", "aitken"}));
  cmd->add_option("--omega", a->omega, "constant factor, or Aitken's initial one (default 0.5)")
      ->check(CLI::Range(1e-6, 1.0));
  cmd->add_option("--tolerance", a->tolerance, "relative residual ending a window (1e-8)")
      ->check(CLI::PositiveNumber);
  // Bounded (limits.md): each sub-iteration is a structural solve, and a typo (1e9 for 100) with
  // an unreachable --tolerance kept the first window going for hours.
  cmd->add_option("--max-iterations", a->maxIterations,
                  "sub-iterations per window (100; at most 10000)")
      ->check(CLI::Range(1, 10000));
  cmd->add_option("--window", a->window, "time-window size (default solver.dt)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--t-end", a->tEnd, "end time (default solver.t_end)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--surface", a->surface, "wet membrane sets (default: all)")->take_all();
  cmd->add_option("--q", a->q, "flow: stagnation pressure q, in the case's units (60 Pa)");
  cmd->add_option("--ramp", a->ramp, "flow: q ramps up over this time (0.02 s)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--air-density", a->airDensity, "flow: rho_air, in the case's units (1.2 kg/m^3)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--cn", a->cn, "flow: normal drag coefficient C_n (1)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--added-mass", a->addedMass,
                  "flow: added-mass length L_a, in the case's units (0.03 m)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--wind", a->wind, "flow: air velocity w (3 numbers)")->expected(3);
  cmd->add_option(
         "--set", a->sets,
         "override a value of the case by its dotted path, e.g. solver.dt=1e-4 (docs/cli.md)")
      ->take_all();
  cmd->add_option("--out", a->outDir,
                  "output directory (default out/<case name>): probes.csv, the VTU series, "
                  "summary.json, and coupling.csv (one row per window)")
      ->check(notEmptyPath());
  cmd->add_flag("--quiet", a->quiet, "no report on the terminal");
  return {cmd, [a] { return couple(*a); }};
}

}  // namespace chute::cli
