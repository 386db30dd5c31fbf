// `chute couple CASE [--scheme explicit|implicit] [--relaxation constant|aitken] ...`: the coupled
// demo. The case's structure (CouplingInterface) and a quasi-steady flow model (a separate
// participant that sees only the interface data) exchange pressure and motion every time window;
// one line per window shows the sub-iterations and the final relative residual.
#include <fmt/core.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "app/cli/Command.hpp"
#include "case/CaseError.hpp"
#include "case/CaseSpec.hpp"
#include "coupling/CouplingDriver.hpp"

namespace chute::cli {
namespace {

struct CoupleArgs {
  std::string caseFile, outDir, scheme = "implicit", relaxation = "aitken";
  std::vector<std::string> sets, surface;
  double omega = 0.5, tolerance = 1e-8, window = 0.0, tEnd = 0.0;
  int maxIterations = 100;
  double q = 60.0, ramp = 0.02, airDensity = 1.2, cn = 1.0, addedMass = 0.03;
  std::vector<double> wind = {0.0, 0.0, 0.0};
  bool quiet = false;
};

int couple(const CoupleArgs& a) {
  using namespace chute::coupling;
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
  } catch (const std::invalid_argument& e) {
    fmt::print(stderr, "chute: {}: {}\n", a.caseFile, e.what());
    return kExitBadInput;
  }
  QuasiSteadyFlowLaw law;
  law.stagnationPressure = a.q, law.rampTime = a.ramp, law.airDensity = a.airDensity;
  law.normalDragCoefficient = a.cn, law.addedMassLength = a.addedMass;
  law.wind = Vec3(a.wind[0], a.wind[1], a.wind[2]);
  const QuasiSteadyFlow flow(structure->surface(), law);
  CouplingSettings cs;
  cs.scheme = a.scheme == "explicit" ? CouplingScheme::Explicit : CouplingScheme::Implicit;
  cs.relaxation = a.relaxation == "constant" ? Relaxation::Constant : Relaxation::Aitken;
  cs.omega = a.omega, cs.tolerance = a.tolerance, cs.maxIterations = a.maxIterations;
  cs.window = a.window, cs.tEnd = a.tEnd;

  // The apex: the wet vertex farthest from the rim's plane at the end, reported per window.
  const int apexNode = spec.model.nodeByName.count("canopy.center")
                           ? spec.model.nodeId("canopy.center")
                           : structure->surface().node[structure->numVertices() / 2];
  std::unique_ptr<std::ofstream> csv;
  if (!a.outDir.empty()) {
    std::filesystem::create_directories(a.outDir);
    csv = std::make_unique<std::ofstream>(a.outDir + "/coupling.csv");
    *csv << "t,iterations,residual,apex_z,mean_pressure\n";
  }
  const double mass =
      spec.model.membraneMaterials.empty()
          ? 0.0
          : spec.model.membraneMaterials[0].density * spec.model.membraneMaterials[0].thickness;
  if (!a.quiet)
    fmt::print(
        "{}: {} coupling, {} relaxation (omega {}), {} faces, {} vertices; flow: q = {} Pa, "
        "rho_air = {}, C_n = {}, added mass rho_air L_a = {:.3g} kg/m^2 (fabric {:.3g} kg/m^2)\n",
        spec.name, a.scheme, a.relaxation, a.omega, structure->numFaces(), structure->numVertices(),
        a.q, a.airDensity, a.cn, a.airDensity * a.addedMass, mass);
  long windows = 0;
  const auto rep = runCoupled(
      *structure, [&](const InterfaceData& d) { return flow.facePressures(d); }, cs,
      [&](const WindowReport& w) {
        ++windows;
        const double z = structure->state().x[3 * apexNode + 2] - spec.model.X[apexNode].z();
        const double pm = structure->loads().facePressures().mean();
        if (!a.quiet)
          fmt::print(
              "  window {:4d}  t = {:.5f}  sub-iterations {:3d}  residual {:.3e}  "
              "apex {:+.5f} m  mean p {:.3f} Pa\n",
              windows, w.t, w.iterations, w.residual, z, pm);
        if (csv) *csv << fmt::format("{},{},{},{},{}\n", w.t, w.iterations, w.residual, z, pm);
      });
  const auto& c = structure->counters();
  if (!a.quiet)
    fmt::print(
        "{}: {} windows, {} structural solves ({:.2f} per window), {} steps, {} Newton "
        "iterations, {} rejected steps\n",
        rep.converged ? "completed" : "failed", rep.windows.size(), rep.iterations(),
        rep.iterationsPerWindow(), c.steps, c.newtonIterations, c.rejectedSteps);
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
  cmd->add_option("--max-iterations", a->maxIterations, "sub-iterations per window (100)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--window", a->window, "time-window size (default solver.dt)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--t-end", a->tEnd, "end time (default solver.t_end)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--surface", a->surface, "wet membrane sets (default: all)")->take_all();
  cmd->add_option("--q", a->q, "flow: stagnation pressure q [Pa] (60)");
  cmd->add_option("--ramp", a->ramp, "flow: q ramps up over this time (0.02 s)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--air-density", a->airDensity, "flow: rho_air (1.2)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--cn", a->cn, "flow: normal drag coefficient C_n (1)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--added-mass", a->addedMass, "flow: added-mass length L_a [m] (0.03)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--wind", a->wind, "flow: air velocity w (3 numbers)")->expected(3);
  cmd->add_option("--set", a->sets, "override a scalar of the case, e.g. solver.dt=1e-4")
      ->take_all();
  cmd->add_option("--out", a->outDir, "write OUT/coupling.csv (one row per window)");
  cmd->add_flag("--quiet", a->quiet, "no report on the terminal");
  return {cmd, [a] { return couple(*a); }};
}

}  // namespace chute::cli
