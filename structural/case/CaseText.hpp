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

}  // namespace chute::caseio
