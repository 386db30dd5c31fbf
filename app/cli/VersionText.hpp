#pragma once
// `chute --version`: chute's version, its build type and compiler, and the versions of the
// libraries it was built against, from their headers' version macros (docs/cli.md).
#include <string>

namespace chute::cli {

std::string versionText();

}  // namespace chute::cli
