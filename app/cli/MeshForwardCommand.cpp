// `chute mesh ...` in the `chute` executable: the arguments go, untouched, to the gmsh plugin
// (GmshPlugin.hpp), so that gmsh is loaded only when meshing (MeshCommand.cpp is the verb); and
// the forwarding any plugin's verb uses (addForwardCommand).
#include <string>
#include <vector>

#include "GmshPlugin.hpp"
#include "app/cli/Command.hpp"

namespace chute::cli {

Command addForwardCommand(CLI::App& app, const char* verb, const char* description,
                          std::function<int(int, char**)> run) {
  auto* sub = app.add_subcommand(verb, description);
  sub->prefix_command();  // everything after the verb is the plugin's, --help included
  sub->set_help_flag("");
  return {sub, [sub, verb, run = std::move(run)] {
            std::vector<std::string> args = {"chute", verb};
            for (const auto& a : sub->remaining()) args.push_back(a);
            std::vector<char*> argv;
            for (auto& a : args) argv.push_back(a.data());
            argv.push_back(nullptr);
            return run(static_cast<int>(args.size()), argv.data());
          }};
}

Command addMeshForwardCommand(CLI::App& app) {
  return addForwardCommand(
      app, "mesh", "build meshes with gmsh (chute mesh --help)",
      [](int argc, char** argv) { return mesh::gmshPlugin().meshCommand(argc, argv); });
}

}  // namespace chute::cli
