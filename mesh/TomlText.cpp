#include "TomlText.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace chute::mesh {

namespace {

// Whether s is valid UTF-8 (TOML text must be; a path of other bytes cannot be named in a case).
bool validUtf8(const std::string& s) {
  for (size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const size_t extra = c < 0x80           ? 0
                         : (c >> 5) == 0x6  ? 1
                         : (c >> 4) == 0xe  ? 2
                         : (c >> 3) == 0x1e ? 3
                                            : 4;
    if (extra == 4 || i + extra >= s.size()) return false;
    for (size_t k = 1; k <= extra; ++k)
      if ((static_cast<unsigned char>(s[i + k]) >> 6) != 0x2) return false;
    i += 1 + extra;
  }
  return true;
}

}  // namespace

// A TOML basic string of s: quotes, backslashes and control characters escaped, so a path or name
// with a quote or a newline is the value it is, not the end of it (`option` names the source).
std::string tomlString(const std::string& s, const std::string& option) {
  if (!validUtf8(s))
    throw std::invalid_argument(option + ": not UTF-8 text; a TOML case cannot name it");
  std::string out = "\"";
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (ch == '"' || ch == '\\') {
      out += '\\';
      out += ch;
    } else if (c < 0x20 || c == 0x7f) {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\u%04X", static_cast<unsigned>(c));
      out += esc;
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

// Text for a comment line: control characters (a newline would end the comment) shown as '?'.
std::string commentText(std::string s) {
  for (char& ch : s)
    if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f) ch = '?';
  return s;
}

std::string caseNameOf(const std::string& caseFile, const std::string& fallback) {
  std::string name = std::filesystem::path(caseFile).stem().string();
  for (char& ch : name)
    if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f || ch == '\\') ch = '_';
  return name.empty() || name == "." || name == ".." ? fallback : name;
}

}  // namespace chute::mesh
