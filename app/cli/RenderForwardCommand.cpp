// `chute render`, `chute plot` and `chute intersections` in the `chute` executable: the arguments
// go, untouched, to the render plugin (RenderPlugin.hpp), which is loaded only for these verbs.
#include <dlfcn.h>

#include <stdexcept>
#include <string>

#include "app/cli/RenderPlugin.hpp"
#include "io/PluginPath.hpp"

namespace chute::cli {

namespace {

Command forward(CLI::App& app, const char* verb, const char* description) {
  auto* sub = app.add_subcommand(verb, description);
  sub->prefix_command();  // everything after the verb is the plugin's, --help included
  sub->set_help_flag("");
  return {sub, [sub, verb] {
            std::vector<std::string> args = {"chute", verb};
            for (const auto& a : sub->remaining()) args.push_back(a);
            std::vector<char*> argv;
            for (auto& a : args) argv.push_back(a.data());
            argv.push_back(nullptr);
            return renderPlugin().command(static_cast<int>(args.size()), argv.data());
          }};
}

}  // namespace

const RenderPluginApi& renderPlugin() {
  static const RenderPluginApi* api = nullptr;
  if (api) return *api;
  const std::string path =
      pluginPath("CHUTE_RENDER_PLUGIN", "libchute_render.so", CHUTE_RENDER_PLUGIN_PATH);
  // Never unloaded: VTK's factories and the virtual display live until exit.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) throw std::runtime_error("cannot load chute's rendering " + path + ": " + dlerror());
  using Entry = const RenderPluginApi* (*)();
  const auto entry = reinterpret_cast<Entry>(dlsym(handle, "chute_render_plugin"));
  if (!entry)
    throw std::runtime_error(path + " is not chute's render plugin (no chute_render_plugin)");
  const RenderPluginApi* loaded = entry();
  if (!loaded || loaded->version != kRenderPluginVersion)
    throw std::runtime_error(path + ": render plugin of another version of chute (rebuild)");
  api = loaded;
  return *api;
}

void addRenderForwardCommands(CLI::App& app, std::vector<Command>& commands) {
  commands.push_back(forward(app, "render", "render PNG snapshots of a run's VTU series"));
  commands.push_back(forward(app, "plot", "plot probe columns of one or several runs to a PNG"));
  commands.push_back(forward(app, "intersections",
                             "count intersecting pairs of non-adjacent triangles and of line "
                             "segments and triangles in a run's frames (exact tests, independent "
                             "of contact)"));
}

}  // namespace chute::cli
