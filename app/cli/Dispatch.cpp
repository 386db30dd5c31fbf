#include "app/cli/Dispatch.hpp"

#include <fmt/core.h>

#include <cstdio>
#include <exception>

#include "case/CaseError.hpp"

namespace chute::cli {

int dispatch(CLI::App& app, const std::vector<Command>& commands, int argc, char** argv) {
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

}  // namespace chute::cli
