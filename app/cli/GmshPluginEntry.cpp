// The gmsh plugin's entry point (libchute_gmsh.so, GmshPlugin.hpp): the `chute mesh` command, with
// gmsh linked in. Errors cross the boundary as messages and exit codes, not exceptions.
#include <exception>

#include "GmshPlugin.hpp"
#include "app/cli/Command.hpp"
#include "app/cli/Dispatch.hpp"

namespace {
int meshCommandEntry(int argc, char** argv) {
  CLI::App app{"chute: structural finite elements for parachute systems"};
  app.require_subcommand(1);
  return chute::cli::dispatch(app, {chute::cli::addMeshCommand(app)}, argc, argv);
}
}  // namespace

extern "C" __attribute__((visibility("default"))) const chute::mesh::GmshPluginApi*
chute_gmsh_plugin() {
  static const chute::mesh::GmshPluginApi api{chute::mesh::kGmshPluginVersion, &meshCommandEntry};
  return &api;
}
