// `chute render`, `chute plot` and `chute intersections` in the `chute` executable: the arguments
// go, untouched, to the render plugin (RenderPlugin.hpp), which is loaded only for these verbs.
#include <stdexcept>
#include <string>

#include "app/cli/RenderPlugin.hpp"
#include "io/Plugin.hpp"

namespace chute::cli {

const RenderPluginApi& renderPlugin() {
  static const RenderPluginApi* api = nullptr;
  if (api) return *api;
  const std::string path =
      pluginPath("CHUTE_RENDER_PLUGIN", "libchute_render.so", CHUTE_RENDER_PLUGIN_PATH);
  // Never unloaded: VTK's factories and the virtual display live until exit.
  std::string why;
  api = loadPlugin<RenderPluginApi>(path, "chute_render_plugin", kRenderPluginVersion,
                                    "chute's rendering", "render plugin", why);
  if (!api) throw std::runtime_error(why);
  return *api;
}

void addRenderForwardCommands(CLI::App& app, std::vector<Command>& commands) {
  auto forward = [&](const char* verb, const char* description) {
    commands.push_back(addForwardCommand(app, verb, description, [](int argc, char** argv) {
      return renderPlugin().command(argc, argv);
    }));
  };
  forward("render", "render PNG snapshots of a run's VTU series");
  forward("plot", "plot probe columns of one or several runs to a PNG");
  forward("intersections",
          "count intersecting pairs of non-adjacent triangles and of line segments and triangles "
          "in a run's frames (exact tests, independent of contact)");
}

}  // namespace chute::cli
