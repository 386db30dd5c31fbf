#pragma once
// Every key a case file gives (after --set), as text and with where it was given: the
// fingerprint a restart is held to (app/CheckpointFile.hpp: only the keys docs/cli.md names may
// differ from the checkpointed run's), and the origin ("file:line" or "--set k=v") that messages
// given after reading name (run limits, sanity notes).
#include <map>
#include <string>
#include <toml.hpp>

namespace chute {

struct CaseSetting {
  std::string value;   // the value as TOML text ("0.001", "\"bossak\"", "[0.0, 0.0, -9.81]")
  std::string origin;  // "file:line", or "--set k=v" for a command-line override
};

// By dotted path: tables by key, arrays of tables by index ("membranes.0.rings"); an array of
// values is one entry ("loads.gravity").
using CaseSettings = std::map<std::string, CaseSetting>;

namespace caseio {
// The settings of a parsed case document; `file` names it in origins.
CaseSettings settingsOf(const toml::value& root, const std::string& file);
}  // namespace caseio

// "origin: key" for a key of the case ("case.toml:12: solver.dt"), or "file: key" when the case
// does not give it (a default).
std::string whereIn(const CaseSettings& settings, const std::string& file, const std::string& key);

}  // namespace chute
