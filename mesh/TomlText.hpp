#pragma once
// Text a generator writes into a TOML case: strings escaped so that a path or name with a quote,
// a backslash or a newline is the value it is (a quote or newline in `--out` ended the string and
// broke the generated case), and comment text that stays one line.
#include <string>

namespace chute::mesh {

// s as a TOML basic string ("..." with \", \\ and \uXXXX escapes). Throws std::invalid_argument
// "option: not UTF-8 text; ..." when s is not UTF-8 (TOML text must be).
std::string tomlString(const std::string& s, const std::string& option);

// s for a comment line: control characters (a newline would end the comment) shown as '?'.
std::string commentText(std::string s);

// The name of a case written to `caseFile` (its default output directory): the file's stem with
// control characters and backslashes, which the case reader refuses in a name, made '_'
// (`fallback` for an empty stem, "." or "..").
std::string caseNameOf(const std::string& caseFile, const std::string& fallback);

}  // namespace chute::mesh
