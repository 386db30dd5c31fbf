// One verb of the `chute` command line. Each verb lives in its own file and registers itself with
// the CLI11 application; main() runs the one the user chose.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace chute::cli {

// Exit statuses, documented in docs/exit-codes.md.
constexpr int kExitInternal = 1;       // an unexpected error or out of memory: a one-line message
constexpr int kExitBadInput = 2;       // case file, mesh or command line wrong: nothing written
constexpr int kExitRunFailed = 3;      // the run stopped early: last good state written
constexpr int kExitInterrupted = 4;    // SIGINT/SIGTERM: checkpoint and valid output written
constexpr int kExitOutputFailed = 5;   // a write failed (disk full): output whole up to a time
constexpr int kExitIntersections = 6;  // `chute intersections --expect-none` found some

// An output path given empty is refused by name: an unset shell variable in `--out "$DIR"` would
// otherwise fall back to the default in silence (docs/cli.md).
inline CLI::Validator notEmptyPath() {
  return CLI::Validator(
      [](std::string& s) {
        return s.empty() ? std::string("an empty path (leave the option out for its default)")
                         : std::string();
      },
      "");
}

struct Command {
  CLI::App* sub = nullptr;   // the CLI11 subcommand (owned by the application)
  std::function<int()> run;  // runs it once the command line is parsed; returns the exit status
};

Command addRunCommand(CLI::App& app);
Command addCoupleCommand(CLI::App& app);
// render, plot and intersections: in the render plugin (RenderPlugin.hpp).
Command addMeshCommand(CLI::App& app);                   // in the gmsh plugin
std::function<int()> addMeshGeoCommand(CLI::App& mesh);  // `chute mesh geo`, in the plugin
Command addMeshForwardCommand(CLI::App& app);            // in `chute`: forwards to the plugin
// A verb of a plugin, in `chute`: everything after the verb (--help included) goes, untouched, to
// run(argc, argv) with argv = {"chute", verb, ...} (MeshForwardCommand.cpp).
Command addForwardCommand(CLI::App& app, const char* verb, const char* description,
                          std::function<int(int, char**)> run);

}  // namespace chute::cli
