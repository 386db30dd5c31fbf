#include "case/CaseSettings.hpp"

#include <charconv>

namespace chute {

namespace caseio {
namespace {
std::string originOf(const toml::value& v, const std::string& file) {
  const auto loc = v.location();
  if (loc.file_name().rfind("--set ", 0) == 0) return loc.file_name();
  return file + ":" + std::to_string(loc.line());
}

std::string textOf(const toml::value& v) {
  if (v.is_floating()) {
    // Shortest text that reads back to the same double: 1e-3 given as 0.001 or 1.0e-3 is one
    // setting.
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v.as_floating());
    return std::string(buf, r.ptr);
  }
  if (v.is_array()) {
    std::string out = "[";
    for (const auto& e : v.as_array()) out += (out.size() > 1 ? ", " : "") + textOf(e);
    return out + "]";
  }
  if (v.is_table()) {
    std::string out = "{";
    for (const auto& [k, e] : v.as_table())
      out += (out.size() > 1 ? ", " : "") + k + " = " + textOf(e);
    return out + "}";
  }
  return toml::format(v);
}

void walk(const toml::value& v, const std::string& path, const std::string& file,
          CaseSettings& out) {
  if (v.is_table()) {
    for (const auto& [k, e] : v.as_table()) walk(e, path.empty() ? k : path + "." + k, file, out);
    return;
  }
  const bool ofTables = v.is_array() && !v.as_array().empty() && v.as_array().front().is_table();
  if (ofTables) {
    const auto& a = v.as_array();
    for (size_t i = 0; i < a.size(); ++i) walk(a[i], path + "." + std::to_string(i), file, out);
    return;
  }
  out[path] = {textOf(v), originOf(v, file)};
}
}  // namespace

CaseSettings settingsOf(const toml::value& root, const std::string& file) {
  CaseSettings out;
  walk(root, "", file, out);
  return out;
}
}  // namespace caseio

std::string whereIn(const CaseSettings& settings, const std::string& file, const std::string& key) {
  const auto it = settings.find(key);
  return (it != settings.end() ? it->second.origin : file) + ": " + key;
}

}  // namespace chute
