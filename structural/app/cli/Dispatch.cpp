#include "app/cli/Dispatch.hpp"

#include <fmt/core.h>

#include <cstdio>
#include <exception>
#include <new>
#include <string>

#include "case/CaseError.hpp"

namespace chute::cli {

namespace {
// One line: a message that spans several (toml11, VTK) is cut at its first newline.
std::string firstLine(const char* what) {
  const std::string s = what ? what : "";
  return s.substr(0, s.find('\n'));
}
}  // namespace

int dispatch(CLI::App& app, const std::vector<Command>& commands, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);                         // --help
    fmt::print(stderr, "chute: {} (chute --help)\n", firstLine(e.what()));  // bad input
    return kExitBadInput;
  } catch (const std::exception& e) {
    fmt::print(stderr, "chute: {}\n", firstLine(e.what()));
    return kExitBadInput;
  }
  // Nothing escapes a verb: every exception ends as "chute: verb: reason" and a documented exit
  // status (docs/exit-codes.md).
  for (const auto& c : commands) {
    if (!*c.sub) continue;
    const std::string verb = c.sub->get_name();
    try {
      return c.run();
    } catch (const chute::CaseError& e) {  // bad input found outside the case reader
      fmt::print(stderr, "chute: {}\n", firstLine(e.what()));
      return kExitBadInput;
    } catch (const std::bad_alloc&) {
      fmt::print(stderr, "chute: {}: out of memory\n", verb);
      return kExitInternal;
    } catch (const std::exception& e) {
      fmt::print(stderr, "chute: {}: {}\n", verb, firstLine(e.what()));
      return kExitInternal;
    } catch (...) {
      fmt::print(stderr, "chute: {}: unexpected error\n", verb);
      return kExitInternal;
    }
  }
  return 0;
}

}  // namespace chute::cli
