#include "case/TomlDepth.hpp"

namespace chute {

std::optional<TomlDepthProblem> tomlNestingProblem(const std::string& text, int maxDepth) {
  int depth = 0;
  long line = 1;
  const std::size_t n = text.size();
  auto startsWith = [&](std::size_t i, const char* s) { return text.compare(i, 3, s) == 0; };
  for (std::size_t i = 0; i < n; ++i) {
    const char ch = text[i];
    if (ch == '\n') {
      ++line;
    } else if (ch == '#') {  // comment to the end of the line
      while (i + 1 < n && text[i + 1] != '\n') ++i;
    } else if (ch == '"' || ch == '\'') {
      // Strings: multi-line ("""/''') or one line; backslash escapes in basic strings only.
      const char* delim = ch == '"' ? "\"\"\"" : "'''";
      const bool multi = startsWith(i, delim);
      const std::size_t open = multi ? 3 : 1;
      std::size_t j = i + open;
      while (j < n) {
        const char c = text[j];
        if (c == '\n') {
          if (!multi) break;  // unterminated: the parser reports it; the newline is counted below
          ++line;
          ++j;
          continue;
        }
        if (ch == '"' && c == '\\') {
          j += j + 1 < n && text[j + 1] != '\n' ? 2 : 1;
          continue;
        }
        if (c == ch && (!multi || startsWith(j, delim))) {
          j += open;
          break;
        }
        ++j;
      }
      i = j - 1;  // the main loop goes on after the string
    } else if (ch == '[' || ch == '{') {
      if (++depth > maxDepth) return TomlDepthProblem{line, depth};
    } else if (ch == ']' || ch == '}') {
      if (depth > 0) --depth;
    }
  }
  return std::nullopt;
}

}  // namespace chute
