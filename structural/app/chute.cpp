// chute: command-line front end (interfaces.md "Command line"). A thin layer over the libraries;
// each verb is in app/cli/<Verb>Command.cpp.
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <vector>

#include "app/cli/Command.hpp"
#include "case/CaseError.hpp"

int main(int argc, char** argv) {
  using namespace chute::cli;
  CLI::App app{"chute: structural finite elements for parachute systems"};
  app.require_subcommand(1);
  const std::vector<Command> commands = {addRunCommand(app), addRenderCommand(app),
                                         addPlotCommand(app), addCoupleCommand(app),
                                         addMeshCommand(app)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);              // --help
    fmt::print(stderr, "chute: {} (chute --help)\n", e.what());  // bad input: one line, status 2
    return kExitBadInput;
  }
  try {
    for (const auto& c : commands)
      if (*c.sub) return c.run();
  } catch (const chute::CaseError& e) {  // bad input found outside the case reader
    fmt::print(stderr, "chute: {}\n", e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    fmt::print(stderr, "chute: {}\n", e.what());
    return 1;
  }
  return 0;
}
