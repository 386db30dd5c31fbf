// `chute mesh ...` in the `chute` executable: the arguments go, untouched, to the gmsh plugin
// (GmshPlugin.hpp), so that gmsh is loaded only when meshing (MeshCommand.cpp is the verb).
#include <fmt/core.h>

#include <string>
#include <vector>

#include "GmshPlugin.hpp"
#include "app/cli/Command.hpp"

namespace chute::cli {

Command addMeshForwardCommand(CLI::App& app) {
  auto* sub = app.add_subcommand("mesh", "build meshes with gmsh (chute mesh --help)");
  sub->prefix_command();  // everything after `mesh` is the plugin's, --help included
  sub->set_help_flag("");
  return {sub, [sub] {
            std::vector<std::string> args = {"chute", "mesh"};
            for (const auto& a : sub->remaining()) args.push_back(a);
            std::vector<char*> argv;
            for (auto& a : args) argv.push_back(a.data());
            argv.push_back(nullptr);
            return mesh::gmshPlugin().meshCommand(static_cast<int>(args.size()), argv.data());
          }};
}

}  // namespace chute::cli
