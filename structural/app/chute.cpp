// chute: command-line front end (interfaces.md "Command line"). A thin layer over the libraries.
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>

#include "app/Simulation.hpp"
#include "case/CaseError.hpp"
#include "case/CaseSpec.hpp"

namespace {

constexpr int kExitBadInput = 2;
constexpr int kExitRunFailed = 3;

int runCommand(const std::string& caseFile, std::string outDir,
               const std::vector<std::string>& sets, bool quiet, bool verboseNewton) {
  chute::CaseSpec spec;
  try {
    spec = chute::readCase(caseFile, sets);
  } catch (const chute::CaseError& e) {
    fmt::print(stderr, "chute: {}\n", e.what());
    return kExitBadInput;
  }
  if (outDir.empty()) outDir = "out/" + spec.name;
  chute::RunOptions opt;
  opt.outDir = outDir;
  opt.progress = !quiet;
  opt.verboseNewton = verboseNewton;
  const auto r = chute::runCase(spec, opt);
  if (!quiet) {
    fmt::print(
        "{}: {} at t = {:.6g}: {} steps, {} rejected, {:.2f} Newton iterations/step, "
        "{:.3f} s wall\n",
        spec.name, r.status, r.finalTime, r.steps, r.rejectedSteps, r.newtonPerStep(), r.wallTime);
    if (r.reference)
      fmt::print("  reference {} ({}): max error {:.3e}, {:.4f} % of the motion ({:.4g})\n",
                 r.reference->kind, r.reference->probe, r.reference->maxError,
                 100 * r.reference->relative(), r.reference->motionSize);
    fmt::print("  output in {}\n", outDir);
  }
  if (r.status != "completed") {
    fmt::print(stderr, "chute: {}: {}\n", spec.name, r.reason);
    return kExitRunFailed;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"chute: structural finite elements for parachute systems"};
  app.require_subcommand(1);

  auto* run = app.add_subcommand("run", "run a case file");
  std::string caseFile, outDir;
  std::vector<std::string> sets;
  bool quiet = false, verboseNewton = false;
  run->add_option("case", caseFile, "case file (TOML)")->required();
  run->add_option("--out", outDir, "output directory (default out/<case name>/)");
  run->add_option("--set", sets, "override a scalar by its dotted path, e.g. solver.dt=1e-4")
      ->take_all();
  run->add_flag("--quiet", quiet, "no progress or report on the terminal");
  run->add_flag("--newton-log", verboseNewton, "print the residual of every Newton iteration");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : kExitBadInput;
  }
  try {
    if (*run) return runCommand(caseFile, outDir, sets, quiet, verboseNewton);
  } catch (const std::exception& e) {
    fmt::print(stderr, "chute: {}\n", e.what());
    return 1;
  }
  return 0;
}
