#pragma once
// The render plugin (libchute_render.so): the verbs that draw or read frames back, `chute
// render`, `chute plot` and `chute intersections`, with VTK's rendering and chart libraries
// linked in, loaded with dlopen when one of them runs. The other verbs, a run above all, then do
// not map those libraries (about 60, with OpenGL, X11 and MPI) at start: `chute --version` took
// 53 ms with them and about 20 ms without (docs/performance.md, "Start-up").
#include <vector>

#include "app/cli/Command.hpp"

namespace chute::cli {

constexpr int kRenderPluginVersion = 1;

struct RenderPluginApi {
  int version = kRenderPluginVersion;
  // `chute VERB ...` (argv[0] = "chute", argv[1] = the verb); returns the exit status.
  int (*command)(int argc, char** argv) = nullptr;
};

// The loaded plugin: $CHUTE_RENDER_PLUGIN, else libchute_render.so next to the executable, else
// the build tree's. Throws std::runtime_error naming the path if it cannot be loaded.
const RenderPluginApi& renderPlugin();

// The plugin's verbs in the executable: each hands its arguments, untouched, to the plugin.
void addRenderForwardCommands(CLI::App& app, std::vector<Command>& commands);
// The plugin's verbs themselves (in the plugin).
Command addRenderCommand(CLI::App& app);
Command addPlotCommand(CLI::App& app);
Command addIntersectionsCommand(CLI::App& app);

}  // namespace chute::cli

// The plugin's one exported symbol.
extern "C" const chute::cli::RenderPluginApi* chute_render_plugin();
