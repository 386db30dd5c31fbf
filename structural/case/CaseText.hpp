#pragma once
// A case file's text: reading it, parsing it as TOML (syntax errors in one line) and applying
// --set overrides to the parsed document.
#include <string>
#include <toml.hpp>
#include <vector>

namespace chute::caseio {

// The whole file (regular files only, up to a size limit, docs/limits.md); CaseError otherwise.
std::string readText(const std::string& file);
// Parses `text`; `file` names it in messages. CaseError on bad syntax or too deep nesting.
toml::value parseText(const std::string& text, const std::string& file);
// toml11's multi-line error message as one line: "message (annotation)".
std::string oneLine(const std::string& what);
// Applies one --set "dotted.key=value" to the parsed case `file`.
void applyOverride(toml::value& root, const std::string& file, const std::string& assignment);
// The closest of `known` to `key`, as " (did you mean 'x'?)", or "".
std::string didYouMean(const std::string& key, const std::vector<std::string>& known);
// For a name a case refers to that does not exist: the closest few of `known` within a typo's
// reach (edit distance, case ignored first), and how many there are, never the whole list when
// it is long: " (did you mean 'lines_17'? 75 groups)", " (did you mean 'canopy'? known: canopy,
// slider)", " (none of the 75 groups is close)", " (there are none)". `plural` names the kind
// ("groups", "membrane sets").
std::string nameSuggestion(const std::string& name, const std::vector<std::string>& known,
                           const std::string& plural);

}  // namespace chute::caseio
