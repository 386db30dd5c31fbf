// `chute run CASE [--out DIR] [--set k=v ...] [--quiet] [--newton-log]` (docs/cli.md).
#include <fmt/core.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "OutputError.hpp"
#include "app/RunCase.hpp"
#include "app/SanityNotes.hpp"
#include "app/cli/Command.hpp"
#include "case/CaseError.hpp"
#include "case/CaseSpec.hpp"

namespace chute::cli {
namespace {

struct RunArgs {
  std::string caseFile, outDir;
  std::vector<std::string> sets;
  bool quiet = false, verboseNewton = false;
  long checkpointEvery = 0;
  std::string restart;
};

int runCase(const RunArgs& a) {
  CaseSpec spec;
  try {
    spec = readCase(a.caseFile, a.sets);
  } catch (const CaseError& e) {
    fmt::print(stderr, "chute: {}\n", e.what());
    return kExitBadInput;
  }
  RunOptions opt;
  opt.outDir = a.outDir.empty() ? "out/" + spec.name : a.outDir;
  opt.progress = !a.quiet;
  opt.verboseNewton = a.verboseNewton;
  opt.checkpointEvery = a.checkpointEvery;
  opt.restartFile = a.restart;
  opt.handleSignals = true;
  // Notes on the case (values outside their physical range, settings much slower than the
  // alternative) as the run starts, on stdout; on stderr once it has completed (summary.json too).
  if (!a.quiet)
    for (const auto& note : sanityNotes(spec))
      fmt::print("{}: note: {}\n", spec.name, oneLineMessage(note));
  RunResult r;
  try {
    r = chute::runCase(spec, opt);
  } catch (const OutputError& e) {  // a full disk: what was written before is whole
    fmt::print(stderr, "chute: run: {}\n", oneLineMessage(e.what()));
    return kExitOutputFailed;
  } catch (const std::runtime_error& e) {  // a checkpoint that does not fit, an unwritable dir
    fmt::print(stderr, "chute: {}\n", oneLineMessage(e.what()));
    return kExitBadInput;
  }
  if (!a.quiet) {
    // An explicit run solves nothing: its rate in steps per second, not Newton iterations.
    const std::string work =
        r.explicitRun ? fmt::format("{:.0f} steps/s", r.wallTime > 0 ? r.steps / r.wallTime : 0.0)
                      : fmt::format("{} rejected, {:.2f} Newton iterations/step", r.rejectedSteps,
                                    r.newtonPerStep());
    fmt::print("{}: {} at t = {:.6g}: {} steps, {}, {:.3f} s wall\n", spec.name,
               runStatusName(r.status), r.finalTime, r.steps, work, r.wallTime);
    if (r.reference)
      fmt::print("  reference {} ({}): max error {:.3e}, {:.4f} % of the motion ({:.4g})\n",
                 r.reference->kind, r.reference->probe, r.reference->maxError,
                 100 * r.reference->relative(), r.reference->motionSize);
    fmt::print("  output in {}\n", opt.outDir);
  }
  // A run that failed says so in one line (docs/exit-codes.md); its notes are in summary.json.
  if (r.status != RunStatus::Completed) {
    fmt::print(stderr, "chute: {}: {}{}\n", spec.name, oneLineMessage(r.reason),
               r.notes.empty() ? ""
                               : fmt::format(" ({} note{} in summary.json)", r.notes.size(),
                                             r.notes.size() > 1 ? "s" : ""));
    return r.status == RunStatus::Interrupted ? kExitInterrupted : kExitRunFailed;
  }
  for (const auto& note : r.notes)
    fmt::print(stderr, "chute: {}: note: {}\n", spec.name, oneLineMessage(note));
  return 0;
}

}  // namespace

Command addRunCommand(CLI::App& app) {
  auto a = std::make_shared<RunArgs>();
  auto* run = app.add_subcommand("run", "run a case file");
  run->add_option("case", a->caseFile, "case file (TOML)")->required();
  run->add_option("--out", a->outDir, "output directory (default out/<case name>/)")
      ->check(notEmptyPath());
  run->add_option(
         "--set", a->sets,
         "override a value of the case by its dotted path, e.g. solver.dt=1e-4 (docs/cli.md)")
      ->take_all();
  run->add_flag("--quiet", a->quiet, "no progress or report on the terminal");
  run->add_flag("--newton-log", a->verboseNewton, "print the residual of every Newton iteration");
  run->add_option("--checkpoint-every", a->checkpointEvery,
                  "write OUT/checkpoint.cbor every N steps (and on SIGINT/SIGTERM)")
      ->check(CLI::Validator(
          [](const std::string& v) -> std::string {
            return !v.empty() && v.size() < 19 &&
                           v.find_first_not_of("0123456789") == std::string::npos &&
                           std::stol(v) > 0
                       ? ""
                       : "expected a positive number of steps, found '" + v + "'";
          },
          "N"));
  run->add_option("--restart", a->restart, "continue a run from its checkpoint, bit for bit");
  return {run, [a] { return runCase(*a); }};
}

}  // namespace chute::cli
