#include "case/TomlTable.hpp"

#include <algorithm>
#include <cmath>

#include "case/CaseText.hpp"

namespace chute {

namespace {
std::string typeName(const toml::value& v) {
  if (v.is_integer()) return "an integer";
  if (v.is_floating()) return "a float";
  if (v.is_string()) return "a string";
  if (v.is_boolean()) return "a boolean";
  if (v.is_array()) return "an array";
  if (v.is_table()) return "a table";
  return "a date/time";
}
// Where a value came from: "file:line", or "--set key=value" for a command-line override
// (parsed under that name by the case reader).
std::string originOf(const toml::value& v, const std::string& file) {
  const auto loc = v.location();
  if (loc.file_name().rfind("--set ", 0) == 0) return loc.file_name();
  return file + ":" + std::to_string(loc.line());
}
// Allowed edit distance for a did-you-mean: about a third of the key, at least one.
int typoDistance(const std::string& key) {
  return std::max<int>(1, static_cast<int>(key.size()) / 3);
}
}  // namespace

int editDistance(const std::string& a, const std::string& b) {
  std::vector<int> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = static_cast<int>(j);
  for (size_t i = 1; i <= a.size(); ++i) {
    int prev = row[0];
    row[0] = static_cast<int>(i);
    for (size_t j = 1; j <= b.size(); ++j) {
      const int cur = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, prev + (a[i - 1] != b[j - 1] ? 1 : 0)});
      prev = cur;
    }
  }
  return row[b.size()];
}

TomlTable::TomlTable(const toml::value& table, std::string path, std::string file)
    : table_(&table), path_(std::move(path)), file_(std::move(file)), schema_(path_) {
  if (!table.is_table()) failAt(table, "", "expected a table, found " + typeName(table));
}

std::string TomlTable::schemaOf(const std::string& key) const {
  const std::string k = namedKeys_ ? "<name>" : key;
  return schema_.empty() ? k : schema_ + "." + k;
}

void TomlTable::ask(const std::string& key) const {
  asked_.insert(key);
  if (recorder_) recorder_->insert(schemaOf(key));
}

std::string TomlTable::dotted(const std::string& key) const {
  if (key.empty()) return path_.empty() ? "(top level)" : path_;
  return path_.empty() ? key : path_ + "." + key;
}

std::string TomlTable::where(const std::string& key) const {
  const auto& t = table_->as_table();
  auto it = t.find(key);
  return originOf(it != t.end() ? it->second : *table_, file_) + ": " + dotted(key);
}

void TomlTable::fail(const std::string& key, const std::string& message) const {
  throw CaseError(where(key) + ": " + message);
}

void TomlTable::failAt(const toml::value& v, const std::string& key,
                       const std::string& message) const {
  throw CaseError(originOf(v, file_) + ": " + dotted(key) + ": " + message);
}

bool TomlTable::has(const std::string& key) const {
  ask(key);
  return table_->as_table().count(key) > 0;
}

const toml::value& TomlTable::at(const std::string& key) const {
  ask(key);
  const auto& t = table_->as_table();
  auto it = t.find(key);
  if (it == t.end()) {
    // A required key that is missing is most often misspelt: point at the misspelling.
    for (const auto& [other, v] : t)
      if (!asked_.count(other) && editDistance(other, key) <= typoDistance(key))
        failAt(v, other, "unknown key (did you mean '" + key + "'? it is required)");
    fail(key, "required key is missing");
  }
  return it->second;
}

std::vector<std::string> TomlTable::keys() const {
  std::vector<std::string> k;
  for (const auto& [name, v] : table_->as_table()) k.push_back(name);
  std::sort(k.begin(), k.end());
  namedKeys_ = true;
  for (const auto& name : k) ask(name);
  return k;
}

double TomlTable::number(const std::string& key) {
  const auto& v = at(key);
  double x;
  if (v.is_integer())
    x = static_cast<double>(v.as_integer());
  else if (v.is_floating())
    x = v.as_floating();
  else
    failAt(v, key, "expected a number, found " + typeName(v));
  if (!std::isfinite(x)) failAt(v, key, "must be finite (found " + std::to_string(x) + ")");
  return x;
}

double TomlTable::number(const std::string& key, double fallback) {
  return has(key) ? number(key) : fallback;
}

double TomlTable::positive(const std::string& key) {
  const double x = number(key);
  if (x <= 0.0) failAt(at(key), key, "must be > 0 (found " + std::to_string(x) + ")");
  return x;
}

double TomlTable::positive(const std::string& key, double fallback) {
  return has(key) ? positive(key) : fallback;
}

double TomlTable::nonNegative(const std::string& key, double fallback) {
  if (!has(key)) return fallback;
  const double x = number(key);
  if (x < 0.0) failAt(at(key), key, "must be >= 0 (found " + std::to_string(x) + ")");
  return x;
}

long TomlTable::integer(const std::string& key, long fallback, long min, long max) {
  if (!has(key)) return fallback;
  const auto& v = at(key);
  if (!v.is_integer()) failAt(v, key, "expected an integer, found " + typeName(v));
  const long x = static_cast<long>(v.as_integer());
  if (x < min || x > max)
    failAt(v, key,
           "must be in [" + std::to_string(min) + ", " + std::to_string(max) + "] (found " +
               std::to_string(x) + ")");
  return x;
}

bool TomlTable::boolean(const std::string& key, bool fallback) {
  if (!has(key)) return fallback;
  const auto& v = at(key);
  if (!v.is_boolean()) failAt(v, key, "expected true or false, found " + typeName(v));
  return v.as_boolean();
}

std::string TomlTable::string(const std::string& key) {
  const auto& v = at(key);
  if (!v.is_string()) failAt(v, key, "expected a string, found " + typeName(v));
  return v.as_string().str;
}

std::string TomlTable::string(const std::string& key, const std::string& fallback) {
  return has(key) ? string(key) : fallback;
}

std::string TomlTable::choice(const std::string& key, const std::string& fallback,
                              const std::vector<std::string>& allowed) {
  const std::string s = string(key, fallback);
  if (std::find(allowed.begin(), allowed.end(), s) == allowed.end()) {
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + ("\"" + a + "\"");
    // A near miss is named first (integrator = "bosak"); the list follows, it is short.
    const std::string near = caseio::didYouMean(s, allowed);
    fail(key, "\"" + s + "\" is not one of " + list + near);
  }
  return s;
}

Eigen::Vector3d TomlTable::vec3(const std::string& key) {
  const auto& v = at(key);
  if (!v.is_array() || v.as_array().size() != 3)
    failAt(v, key, "expected an array of 3 numbers, found " + typeName(v));
  Eigen::Vector3d out;
  for (int k = 0; k < 3; ++k) {
    const auto& e = v.as_array()[k];
    if (e.is_integer())
      out[k] = static_cast<double>(e.as_integer());
    else if (e.is_floating())
      out[k] = e.as_floating();
    else
      failAt(e, key, "expected a number, found " + typeName(e));
    if (!std::isfinite(out[k])) failAt(e, key, "must be finite");
  }
  return out;
}

Eigen::Vector3d TomlTable::vec3(const std::string& key, const Eigen::Vector3d& fallback) {
  return has(key) ? vec3(key) : fallback;
}

std::vector<std::string> TomlTable::strings(const std::string& key) {
  const auto& v = at(key);
  if (!v.is_array()) failAt(v, key, "expected an array of strings, found " + typeName(v));
  std::vector<std::string> out;
  for (const auto& e : v.as_array()) {
    if (!e.is_string()) failAt(e, key, "expected a string, found " + typeName(e));
    out.push_back(e.as_string().str);
  }
  return out;
}

std::vector<std::string> TomlTable::strings(const std::string& key,
                                            const std::vector<std::string>& fallback) {
  return has(key) ? strings(key) : fallback;
}

std::vector<long> TomlTable::integers(const std::string& key) {
  const auto& v = at(key);
  if (!v.is_array()) failAt(v, key, "expected an array of integers, found " + typeName(v));
  std::vector<long> out;
  for (const auto& e : v.as_array()) {
    if (!e.is_integer()) failAt(e, key, "expected an integer, found " + typeName(e));
    out.push_back(static_cast<long>(e.as_integer()));
  }
  return out;
}

TomlTable TomlTable::table(const std::string& key) {
  const auto& v = at(key);
  if (!v.is_table()) failAt(v, key, "expected a table, found " + typeName(v));
  TomlTable child(v, dotted(key), file_);
  child.schema_ = schemaOf(key);
  return child;
}

std::vector<TomlTable> TomlTable::tables(const std::string& key) {
  std::vector<TomlTable> out;
  if (!has(key)) return out;
  const auto& v = at(key);
  if (!v.is_array()) failAt(v, key, "expected an array of tables ([[" + key + "]])");
  int i = 0;
  for (const auto& e : v.as_array()) {
    if (!e.is_table()) failAt(e, key, "expected a table, found " + typeName(e));
    out.emplace_back(e, dotted(key) + "[" + std::to_string(i++) + "]", file_);
    out.back().schema_ = schemaOf(key) + "[]";
  }
  return out;
}

void TomlTable::notUsed(const std::vector<std::string>& keys, const std::string& why) const {
  const auto& t = table_->as_table();
  for (const auto& key : keys) {
    if (recorder_) recorder_->insert(schemaOf(key));
    auto it = t.find(key);
    if (it != t.end()) failAt(it->second, key, "not used " + why);
  }
}

void TomlTable::finish(const std::vector<std::string>& known) const {
  for (const auto& k : known) ask(k);
  finish();
}

void TomlTable::finish() const {
  for (const auto& [key, v] : table_->as_table()) {
    if (asked_.count(key)) continue;
    std::string best;
    int bestD = 1 << 30;
    for (const auto& known : asked_) {
      const int d = editDistance(key, known);
      if (d < bestD) bestD = d, best = known;
    }
    std::string msg = "unknown key";
    if (!best.empty() && bestD <= std::max({2, typoDistance(key), typoDistance(best)}))
      msg += " (did you mean '" + best + "'?)";
    failAt(v, key, msg);
  }
}

}  // namespace chute
