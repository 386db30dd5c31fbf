// The render plugin's entry point (libchute_render.so, RenderPlugin.hpp): `chute render`,
// `chute plot` and `chute intersections`, with VTK's rendering linked in. Errors cross the
// boundary as messages and exit codes, not exceptions.
#include "app/cli/Dispatch.hpp"
#include "app/cli/RenderPlugin.hpp"

namespace {
int commandEntry(int argc, char** argv) {
  CLI::App app{"chute: structural finite elements for parachute systems"};
  app.require_subcommand(1);
  return chute::cli::dispatch(app,
                              {chute::cli::addRenderCommand(app), chute::cli::addPlotCommand(app),
                               chute::cli::addIntersectionsCommand(app)},
                              argc, argv);
}
}  // namespace

extern "C" __attribute__((visibility("default"))) const chute::cli::RenderPluginApi*
chute_render_plugin() {
  static const chute::cli::RenderPluginApi api{chute::cli::kRenderPluginVersion, &commandEntry};
  return &api;
}
