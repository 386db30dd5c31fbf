#pragma once
#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>

namespace chute {

// A message as one line: control characters a user's text may carry into it (a newline in a
// --set value, a file name or a node name) are written as escapes ("\n", "\x01"), so that
// every error is the one line docs/exit-codes.md promises.
inline std::string oneLineMessage(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else if (u < 0x20 || u == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", u);
      out += buf;
    } else {
      out += c;
    }
  }
  return out;
}

// Bad input: the message names the file, the line and the key ("case.toml:12: solver.dt: ...").
// Always one line (oneLineMessage).
class CaseError : public std::runtime_error {
 public:
  explicit CaseError(const std::string& message) : std::runtime_error(oneLineMessage(message)) {}
  explicit CaseError(const char* message) : CaseError(std::string(message)) {}
};

}  // namespace chute
