#pragma once
// Parses the command line and runs the chosen verb, with the exit statuses of Command.hpp:
// shared by the `chute` executable and the gmsh plugin's `chute mesh`.
#include <vector>

#include "app/cli/Command.hpp"

namespace chute::cli {

int dispatch(CLI::App& app, const std::vector<Command>& commands, int argc, char** argv);

}  // namespace chute::cli
