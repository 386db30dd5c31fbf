#include "app/cli/Dispatch.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>
#include <string>

#include "case/CaseError.hpp"
#include "case/CaseText.hpp"

namespace chute::cli {

namespace {
// One line: a message that spans several (toml11, VTK) is cut at its first newline.
std::string firstLine(const char* what) {
  const std::string s = what ? what : "";
  return s.substr(0, s.find('\n'));
}

// The first option value of `app` (and its chosen subcommands) that is a number but not a finite
// one ("nan", "inf", "1e999"): CLI11's range checks let NaN through. "" if none.
std::string nonFiniteOption(const CLI::App* app) {
  for (const CLI::Option* o : app->get_options()) {
    // Numeric options only (CLI11 names their type FLOAT, INT, UINT): a title may be "inf".
    const std::string type = o->get_type_name();
    if (type.find("FLOAT") == std::string::npos && type.find("INT") == std::string::npos) continue;
    for (const std::string& r : o->results()) {
      char* end = nullptr;
      const double v = std::strtod(r.c_str(), &end);
      if (!r.empty() && end == r.c_str() + r.size() && !std::isfinite(v))
        return o->get_name() + ": '" + r + "' is not a finite number";
    }
  }
  for (const CLI::App* sub : app->get_subcommands())
    if (const std::string e = nonFiniteOption(sub); !e.empty()) return e;
  return "";
}

// A first word that is no verb ("runn", "version"): CLI11 says only that a subcommand is
// required; name the word and the closest verb. "" if the first word is a verb or an option.
std::string unknownVerb(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return "";
  const std::string word = argv[1];
  std::vector<std::string> verbs;
  for (const CLI::App* sub : app.get_subcommands({})) verbs.push_back(sub->get_name());
  if (std::find(verbs.begin(), verbs.end(), word) != verbs.end()) return "";
  std::string hint = caseio::didYouMean(word, verbs);
  if (word == "version" || word == "help") hint = " (did you mean '--" + word + "'?)";
  std::string list;
  for (const auto& v : verbs) list += (list.empty() ? "" : ", ") + v;
  return "unknown command '" + word + "'" + hint + "; the commands are " + list;
}
}  // namespace

int dispatch(CLI::App& app, const std::vector<Command>& commands, int argc, char** argv) {
  if (const std::string bad = unknownVerb(app, argc, argv); !bad.empty()) {
    fmt::print(stderr, "chute: {} (chute --help)\n", bad);
    return kExitBadInput;
  }
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
    if (const std::string bad = nonFiniteOption(c.sub); !bad.empty()) {
      fmt::print(stderr, "chute: {}: {}\n", verb, bad);
      return kExitBadInput;
    }
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
