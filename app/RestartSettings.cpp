#include "app/RestartSettings.hpp"

#include <stdexcept>

namespace chute {

namespace {
// Values quoted in messages, cut short: an array of node names may be long.
std::string shown(const std::string& v) {
  return v.size() > 60 ? v.substr(0, 57) + "..." : v;
}
}  // namespace

bool restartMayChange(const std::string& key) {
  // The end time, the description, and the limits a run is held to (they change nothing it
  // computes or writes, only how far it may go: docs/limits.md).
  static const char* const kMay[] = {
      "solver.t_end",         "description",    "output.max_rows",  "output.vtu.max_frames",
      "solver.max_equations", "mesh.max_nodes", "mesh.max_elements"};
  for (const char* k : kMay)
    if (key == k) return true;
  return false;
}

std::map<std::string, std::string> restartFingerprint(const CaseSpec& spec) {
  std::map<std::string, std::string> out;
  for (const auto& [key, s] : spec.settings)
    if (!restartMayChange(key)) out[key] = s.value;
  return out;
}

void checkRestartSettings(const CaseSpec& spec, const std::map<std::string, std::string>& saved,
                          const std::string& file) {
  const auto now = restartFingerprint(spec);
  const std::string rule =
      ": a restart continues the checkpointed run with its settings (only solver.t_end and the "
      "limits may change; docs/cli.md)";
  for (const auto& [key, value] : now) {
    const auto it = saved.find(key);
    if (it == saved.end())
      throw std::runtime_error(whereIn(spec.settings, spec.file, key) + ": is " + shown(value) +
                               " here but not given in the run of " + file + rule);
    if (it->second != value)
      throw std::runtime_error(whereIn(spec.settings, spec.file, key) + ": is " + shown(value) +
                               " here but " + shown(it->second) + " in the run of " + file + rule);
  }
  for (const auto& [key, value] : saved)
    if (!restartMayChange(key) && !now.count(key))
      throw std::runtime_error(spec.file + ": " + key + ": not given here but " + shown(value) +
                               " in the run of " + file + rule);
}

}  // namespace chute
