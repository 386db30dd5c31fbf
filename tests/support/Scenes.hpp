#pragma once
// Inline scenes of the tests: the TOML text a test spells out is written to a case file under
// gtest's temporary directory, to be read like any case.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <string>

namespace chute::testing {

// temp/<name>_<pid>.toml holding `text`; returns its path. The process id keeps tests that
// ctest runs in parallel (one process per test) from writing one file at the same time.
inline std::string writeCase(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name + "_" + std::to_string(::getpid()) + ".toml";
  std::ofstream(path) << text;
  return path;
}

}  // namespace chute::testing
