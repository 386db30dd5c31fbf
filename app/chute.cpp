// chute: command-line front end (docs/cli.md). A thin layer over the libraries;
// each verb is in app/cli/<Verb>Command.cpp.
#include <fmt/core.h>
#include <vtkLogger.h>
#include <vtkObject.h>

#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <exception>
#include <string_view>
#include <vector>

#include "app/StopSignals.hpp"
#include "app/cli/Command.hpp"
#include "app/cli/Dispatch.hpp"
#include "app/cli/RenderPlugin.hpp"
#include "app/cli/VersionText.hpp"
#include "solver/LinearSolver.hpp"

int main(int argc, char** argv) {
  using namespace chute::cli;
  chute::releaseBlasThreads();
  // `chute run` handles SIGINT / SIGTERM from its first instruction (checkpoint, valid output);
  // the other verbs keep the default (they end at once).
  if (argc > 1 && std::string_view(argv[1]) == "run") chute::installStopHandlers();
  // A file size limit (ulimit -f) is a full disk: a write past it fails with EFBIG and is
  // reported as any failed write (docs/exit-codes.md), instead of the signal ending chute.
  std::signal(SIGXFSZ, SIG_IGN);
  // VTK's own messages (warnings, its logger) are not chute's one-line errors: verbs check
  // what VTK produced and report it themselves.
  vtkObject::GlobalWarningDisplayOff();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  CLI::App app{"chute: structural finite elements for parachute systems"};
  app.set_version_flag("--version", versionText(),
                       "print chute's version, build, compiler and library versions and exit");
  app.require_subcommand(1);
  std::vector<Command> commands = {addRunCommand(app)};
  addRenderForwardCommands(app, commands);  // in the render plugin (RenderPlugin.hpp)
  commands.push_back(addCoupleCommand(app));
  commands.push_back(addMeshForwardCommand(app));
  return dispatch(app, commands, argc, argv);
}
