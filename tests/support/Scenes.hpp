#pragma once
// Inline scenes of the tests: the TOML text a test spells out is written to a case file under
// gtest's temporary directory, to be read like any case.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace chute::testing {

// temp/<name>.toml holding `text`; returns its path.
inline std::string writeCase(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name + ".toml";
  std::ofstream(path) << text;
  return path;
}

}  // namespace chute::testing
