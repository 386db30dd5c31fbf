#pragma once
// toml11 parses nested arrays and inline tables recursively: about 6,000 levels overflow the
// stack and kill the process (a host program too, through the coupling library). TOML text is
// therefore scanned for its nesting depth before it is parsed.
#include <optional>
#include <string>

namespace chute {

constexpr int kMaxTomlDepth = 64;  // docs/limits.md; no case needs more than 3

struct TomlDepthProblem {
  long line = 0;  // 1-based line where the nesting passes the limit
  int depth = 0;  // deepest nesting seen (== the limit + 1: the scan stops there)
};

// Where `text` nests arrays / inline tables ([ and { outside strings and comments) deeper than
// maxDepth, or nullopt. The scan is linear and keeps no stack.
std::optional<TomlDepthProblem> tomlNestingProblem(const std::string& text,
                                                   int maxDepth = kMaxTomlDepth);

}  // namespace chute
