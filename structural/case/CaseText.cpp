// Case text: reading, parsing and --set overrides (see CaseText.hpp).
#include "case/CaseText.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "case/CaseError.hpp"
#include "case/TomlDepth.hpp"
#include "case/TomlTable.hpp"
#include "case/UnitSuggestion.hpp"
#include "io/InputFile.hpp"

namespace chute::caseio {

namespace {

// An array none of whose entries is a table or an array: what --set may replace whole.
bool arrayOfValues(const toml::value& v) {
  return v.is_array() &&
         std::none_of(v.as_array().begin(), v.as_array().end(),
                      [](const toml::value& e) { return e.is_table() || e.is_array(); });
}

// The number a text begins with when the rest is a unit ("1s" -> "1", "9.81 m/s2" -> "9.81"),
// else "". The number is the longest prefix TOML reads as one; the rest, after spaces, must begin
// with a letter and not be a lone exponent mark ("1e" is a number cut short, not metres of e).
std::string numberBeforeUnit(const std::string& text) {
  for (size_t n = std::min<size_t>(text.size(), 64); n-- > 1;) {
    size_t rest = n;
    while (rest < text.size() && text[rest] == ' ') ++rest;
    if (rest >= text.size() || !std::isalpha(static_cast<unsigned char>(text[rest]))) continue;
    const bool exponent =
        (text[rest] == 'e' || text[rest] == 'E') &&
        (rest + 1 == text.size() || text[rest + 1] == '+' || text[rest + 1] == '-' ||
         std::isdigit(static_cast<unsigned char>(text[rest + 1])));
    if (exponent) continue;
    const std::string head = text.substr(0, n);
    if (head.find_first_not_of("0123456789+-._eE") != std::string::npos) continue;
    try {
      std::istringstream in("v = " + head);
      const toml::value v = toml::parse(in, "number").as_table().at("v");
      if (v.is_integer() || v.is_floating()) return head;
    } catch (const std::exception&) {
    }
  }
  return "";
}

// Why a --set value is not TOML, in the words a shell user needs: an array's unquoted strings
// shown quoted, a decimal comma, an array left open; else the parser's own reason.
std::string notTomlReason(const std::string& text, const std::string& parserMessage) {
  if (!text.empty() && text.front() == '[') {
    if (text.back() != ']') return "an array needs its closing ']'";
    // Quote the bare words; if that reads, it is what was meant.
    std::string quoted;
    bool inString = false;
    for (size_t i = 0; i < text.size();) {
      const char c = text[i];
      if (c == '"') inString = !inString;
      if (!inString && std::isalpha(static_cast<unsigned char>(c))) {
        size_t j = i;
        while (j < text.size() && (std::isalnum(static_cast<unsigned char>(text[j])) ||
                                   text[j] == '_' || text[j] == '-' || text[j] == '.'))
          ++j;
        const std::string word = text.substr(i, j - i);
        const bool keyword = word == "true" || word == "false" || word == "inf" || word == "nan";
        quoted += keyword ? word : "\"" + word + "\"";
        i = j;
        continue;
      }
      quoted += c;
      ++i;
    }
    try {
      std::istringstream in("v = " + quoted);
      toml::parse(in, "quoted");
      return "strings in an array are quoted: '" + quoted + "'";
    } catch (const std::exception&) {
    }
  }
  const auto comma = text.find(',');
  if (comma != std::string::npos && comma > 0 && comma + 1 < text.size() &&
      std::isdigit(static_cast<unsigned char>(text[comma - 1])) &&
      std::isdigit(static_cast<unsigned char>(text[comma + 1])) && text.front() != '[') {
    std::string point = text;
    point[comma] = '.';
    return "a decimal point, not a comma (" + point + ")";
  }
  // A number whose exponent has no digits ("1e", "2.5E-").
  const auto mark = text.find_first_of("eE");
  if (mark != std::string::npos && mark > 0 && text.find_first_not_of("0123456789+-._") == mark &&
      text.find_first_not_of("+-", mark + 1) == std::string::npos)
    return "the exponent after '" + text.substr(0, mark + 1) + "' has no digits (e.g. " +
           text.substr(0, mark + 1) + "-3)";
  return oneLine(parserMessage);
}

// Case files are read whole, regular files only (a FIFO or /dev/zero never ends), at most
// kMaxCaseBytes (docs/limits.md).
constexpr std::uintmax_t kMaxCaseBytes = 64ull << 20;

}  // namespace

// toml11 reports a syntax error over several lines (message, source line, caret); chute reports
// bad input in one: "file:line: malformed TOML: message (annotation)".
std::string oneLine(const std::string& what) {
  std::string first = what.substr(0, what.find('\n'));
  for (const std::string prefix : {"[error] "})
    if (first.rfind(prefix, 0) == 0) first = first.substr(prefix.size());
  if (first.rfind("toml::", 0) == 0 || first.rfind("parse_", 0) == 0) {
    const auto colon = first.find(": ");
    if (colon != std::string::npos) first = first.substr(colon + 2);
  }
  // The last caret annotation ("^--- expected value, but got nothing") says what was wrong.
  std::string note;
  for (const std::string mark : {"^--- ", "~~~ "}) {
    const auto at = what.rfind(mark);
    if (at != std::string::npos) {
      note = what.substr(at + mark.size());
      note = note.substr(0, note.find('\n'));
      break;
    }
  }
  if (!note.empty() && note != "here") first += " (" + note + ")";
  return first;
}

toml::value parseText(const std::string& text, const std::string& file) {
  if (const auto deep = tomlNestingProblem(text))
    throw CaseError(file + ":" + std::to_string(deep->line) + ": arrays or inline tables nested " +
                    "deeper than " + std::to_string(kMaxTomlDepth) + " levels");
  try {
    std::istringstream in(text);
    return toml::parse(in, file);
  } catch (const toml::exception& e) {
    throw CaseError(file + ":" + std::to_string(e.location().line()) +
                    ": malformed TOML: " + oneLine(e.what()));
  } catch (const std::exception& e) {
    throw CaseError(file + ": malformed TOML: " + oneLine(e.what()));
  }
}

std::string readText(const std::string& file) {
  try {
    return io::readInputFile(file, kMaxCaseBytes);
  } catch (const std::runtime_error& e) {
    throw CaseError(std::string(e.what()));
  }
}

// The closest of `known` to `key`, as " (did you mean 'x'?)", or "".
std::string didYouMean(const std::string& key, const std::vector<std::string>& known) {
  std::string best;
  int bestD = 1 << 30;
  for (const auto& k : known) {
    const int d = editDistance(key, k);
    if (d < bestD) bestD = d, best = k;
  }
  if (best.empty() || bestD > std::max<int>(2, static_cast<int>(key.size()) / 3)) return "";
  return " (did you mean '" + best + "'?)";
}

std::string nameSuggestion(const std::string& name, const std::vector<std::string>& known,
                           const std::string& plural) {
  if (known.empty()) return " (there are no " + plural + ")";
  auto lower = [](std::string s) {
    for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
  };
  const std::string key = lower(name);
  // Distance with case ignored, ties broken by the exact spelling's distance.
  std::vector<std::pair<std::pair<int, int>, const std::string*>> ranked;
  const int reach = std::max<int>(1, static_cast<int>(name.size()) / 3);
  for (const auto& k : known) {
    // A name far longer or shorter cannot be within reach: skip the distance (a mesh may have
    // a million node names).
    if (std::abs(static_cast<long>(k.size()) - static_cast<long>(name.size())) > reach) continue;
    const int d = editDistance(key, lower(k));
    if (d <= reach) ranked.push_back({{d, editDistance(name, k)}, &k});
  }
  std::sort(ranked.begin(), ranked.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::string close;
  const size_t shown = std::min<size_t>(ranked.size(), 3);
  for (size_t i = 0; i < shown; ++i)
    close += (i == 0 ? "'" : i + 1 == shown ? " or '" : ", '") + *ranked[i].second + "'";
  constexpr size_t kListAll = 6;  // up to this many are named in full
  std::string all;
  if (known.size() <= kListAll)
    for (const auto& k : known) all += (all.empty() ? "" : ", ") + k;
  if (!close.empty())
    return " (did you mean " + close + "? " +
           (all.empty() ? std::to_string(known.size()) + " " + plural : "known: " + all) + ")";
  if (!all.empty()) return " (known: " + all + ")";
  return " (none of the " + std::to_string(known.size()) + " " + plural + " is close)";
}

void applyOverride(toml::value& root, const std::string& file, const std::string& assignment) {
  // Messages quote the assignment, cut short: it may be kilobytes long.
  const std::string where =
      "--set " + (assignment.size() > 80 ? assignment.substr(0, 60) + "..." : assignment);
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) throw CaseError(where + ": expected key=value");
  const std::string path = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  const std::string shown = path.size() > 80 ? path.substr(0, 60) + "..." : path;
  std::vector<std::string> keys;
  std::stringstream ss(path);
  for (std::string k; std::getline(ss, k, '.');) {
    if (k.empty()) throw CaseError(where + ": empty key in '" + path + "'");
    keys.push_back(k);
  }
  if (path.back() == '.') throw CaseError(where + ": empty key in '" + path + "'");
  // Each step is a table key, or an index into an array of tables ("membranes.0.rings").
  toml::value* node = &root;
  std::string walked;
  for (size_t i = 0; i + 1 < keys.size(); ++i) {
    if (node->is_array()) {
      auto& arr = node->as_array();
      const bool numeric =
          keys[i].size() <= 9 && keys[i].find_first_not_of("0123456789") == std::string::npos;
      const size_t idx = numeric ? std::stoul(keys[i]) : arr.size();
      if (idx >= arr.size())
        throw CaseError(where + ": " + walked + ": '" + keys[i] + "' is not an index of its " +
                        std::to_string(arr.size()) + " entries");
      node = &arr[idx];
    } else if (!node->is_table()) {
      throw CaseError(where + ": " + walked + ": is a value, not a table");
    } else {
      auto& t = node->as_table();
      auto it = t.find(keys[i]);
      if (it == t.end()) {
        std::vector<std::string> known;
        for (const auto& [k, v] : t)
          if (v.is_table() || v.is_array()) known.push_back(k);
        throw CaseError(where + ": " + (walked.empty() ? "" : walked + ".") + keys[i] + ": " +
                        file + " has no such table" + didYouMean(keys[i], known));
      }
      if (!it->second.is_table() && !it->second.is_array())
        throw CaseError(where + ": " + (walked.empty() ? "" : walked + ".") + keys[i] +
                        ": is not a table");
      node = &it->second;
    }
    walked += (walked.empty() ? "" : ".") + keys[i];
  }
  // An array of values takes an index as its last key (membranes.0.divisions.0=16); an array of
  // tables needs one before the key; a value has no keys.
  const bool valueArray =
      node->is_array() &&
      std::none_of(node->as_array().begin(), node->as_array().end(),
                   [](const toml::value& v) { return v.is_table() || v.is_array(); });
  toml::value* element = nullptr;
  if (valueArray) {
    auto& arr = node->as_array();
    const std::string& k = keys.back();
    const bool numeric = k.size() <= 9 && k.find_first_not_of("0123456789") == std::string::npos;
    const size_t idx = numeric ? std::stoul(k) : arr.size();
    if (idx >= arr.size())
      throw CaseError(where + ": " + walked + ": '" + k + "' is not an index of its " +
                      std::to_string(arr.size()) + " values");
    element = &arr[idx];
  } else if (node->is_array()) {
    throw CaseError(where + ": " + walked + ": an array of tables: give an index (" + walked +
                    ".0." + keys.back() + ")");
  } else if (!node->is_table()) {
    throw CaseError(where + ": " + walked + ": is a value, not a table");
  }
  toml::value parsed;
  if (tomlNestingProblem(text))
    throw CaseError(where + ": " + shown + ": nested deeper than " + std::to_string(kMaxTomlDepth) +
                    " levels");
  try {
    std::istringstream in("v = " + text);
    parsed = toml::parse(in, where).as_table().at("v");
  } catch (const std::exception& e) {
    // A number with a unit ("1s", "9.81 m/s2", "5 kg"): the case's numbers are plain, in its
    // units. Judged only once the text is not TOML, so "1e" (an exponent cut short) stays a
    // malformed number and no TOML value is misread as a unit.
    const std::string number = numberBeforeUnit(text);
    if (!number.empty()) {
      std::string units;
      if (root.is_table() && root.as_table().count("units") &&
          root.as_table().at("units").is_string())
        units = root.as_table().at("units").as_string().str;
      std::string unit = text.substr(number.size());
      unit.erase(0, unit.find_first_not_of(' '));
      std::string plain = number;
      plain.erase(std::remove(plain.begin(), plain.end(), '_'), plain.end());
      const auto converted = inCaseUnits(std::strtod(plain.c_str(), nullptr), unit, units);
      std::ostringstream give;
      if (converted)
        give << "give " << std::setprecision(6) << *converted << " for " << text;
      else
        give << "give the number";
      throw CaseError(where + ": " + shown + ": numbers take no units (" + give.str() +
                      " in the case's units" + (units.empty() ? "" : ", " + units) + ")");
    }
    // A bare word is a string (--set solver.mass=consistent), as a user types it in a shell.
    const bool bareWord =
        !text.empty() && std::isalpha(static_cast<unsigned char>(text[0])) &&
        text.find_first_not_of(
            "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-.") ==
            std::string::npos;
    if (!bareWord)
      throw CaseError(where + ": " + shown +
                      ": not a TOML value: " + notTomlReason(text, e.what()));
    std::istringstream quoted("v = \"" + text + "\"");  // keeps the --set as its origin
    parsed = toml::parse(quoted, where).as_table().at("v");
  }
  // A value or an array of values (output.vtu.fields=["velocity"], loads.gravity=[0, 0, -1]);
  // the reader then judges its type as it judges the file's. A table is set key by key.
  if (parsed.is_table() || (parsed.is_array() && !arrayOfValues(parsed)))
    throw CaseError(where + ": " + shown + ": a table is set one key at a time (" + shown +
                    ".key=value)");
  if (element) {
    if (parsed.is_array())
      throw CaseError(where + ": " + shown + ": an entry of an array takes a value, not an array");
    *element = parsed;
    return;
  }
  auto& t = node->as_table();
  auto it = t.find(keys.back());
  if (it != t.end() &&
      (it->second.is_table() || (it->second.is_array() && !arrayOfValues(it->second))))
    throw CaseError(where + ": " + shown + ": is a table in " + file +
                    ", set its keys one at a time (" + shown + ".key=value)");
  // A key the file does not have is added; the reader rejects it (with a did-you-mean) if the
  // case has no such key.
  t[keys.back()] = parsed;
}

}  // namespace chute::caseio
