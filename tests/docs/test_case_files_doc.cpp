// docs/case-files.md against the case reader, so the page cannot rot: the reader records every
// key it asks for (TomlTable's key recorder) while it reads every shipped case; each of those
// keys must have a row in the page, and each row must name a key the reader asked for.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>

#include "case/CaseSpec.hpp"
#include "case/TomlTable.hpp"

namespace fs = std::filesystem;
using namespace chute;

namespace {

// The case files the reader is run on: every case in cases/, the mesh-import example, and the
// scenes in tests/docs/scenes/ (keys no shipped case uses).
std::vector<fs::path> shippedCases() {
  std::vector<fs::path> files;
  for (const char* dir : {CHUTE_SOURCE_DIR "/cases", CHUTE_SOURCE_DIR "/tests/docs/scenes"})
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".toml") files.push_back(e.path());
  files.push_back(CHUTE_SOURCE_DIR "/mesh/examples/flat_canopy.toml");
  std::sort(files.begin(), files.end());
  return files;
}

// Keys the reader asks for while reading all shipped cases, by schema path.
std::set<std::string> keysAskedByTheReader() {
  std::set<std::string> asked;
  TomlTable::recordKeysInto(&asked);
  for (const auto& f : shippedCases()) {
    SCOPED_TRACE(f.string());
    EXPECT_NO_THROW(readCase(f.string()));
  }
  TomlTable::recordKeysInto(nullptr);
  return asked;
}

// Keys documented in the page: the first cell of a table row, when it is one backticked path.
std::set<std::string> keysDocumented() {
  std::ifstream in(CHUTE_SOURCE_DIR "/docs/case-files.md");
  EXPECT_TRUE(in) << "docs/case-files.md is missing";
  const std::regex row(R"(^\|\s*`([^`]+)`\s*\|)");
  std::set<std::string> keys;
  std::string line;
  std::smatch m;
  while (std::getline(in, line))
    if (std::regex_search(line, m, row)) keys.insert(m[1]);
  return keys;
}

}  // namespace

TEST(CaseFilesDoc, EveryKeyTheReaderAsksForIsDocumentedAndNoOther) {
  const auto asked = keysAskedByTheReader();
  const auto documented = keysDocumented();
  std::printf(
      "%zu case files (cases/, the mesh example, tests/docs/scenes/); the reader asked for %zu "
      "distinct keys; the page documents %zu\n",
      shippedCases().size(), asked.size(), documented.size());
  for (const auto& k : asked)
    EXPECT_TRUE(documented.count(k)) << "docs/case-files.md has no row for `" << k << "`";
  for (const auto& k : documented)
    EXPECT_TRUE(asked.count(k)) << "docs/case-files.md documents `" << k
                                << "`, which the reader never asked for in any case read";
  EXPECT_GT(asked.size(), 50u);  // the recorder is on: a real case reads dozens of keys
}

TEST(CaseFilesDoc, TheRecorderNamesArraysAndNamedTablesBySchema) {
  std::set<std::string> asked;
  TomlTable::recordKeysInto(&asked);
  readCaseFromString(R"(
[nodes]
a = [0.0, 0.0, 0.0]
b = [1.0, 0.0, 0.0]
[materials.rope]
kind = "cable"
E = 1.0e6
area = 1.0e-4
density = 1.0
[[cables]]
name = "c"
material = "rope"
path = ["a", "b"]
[boundary]
fixed = ["a"]
[solver]
dt = 0.01
t_end = 0.02
)",
                     "inline.toml");
  TomlTable::recordKeysInto(nullptr);
  for (const char* k : {"nodes.<name>", "materials.<name>.E", "cables[].path", "solver.dt"})
    EXPECT_TRUE(asked.count(k)) << k;
  for (const auto& k : asked) EXPECT_EQ(k.find("rope"), std::string::npos) << k;
  for (const auto& k : asked) EXPECT_EQ(k.find("[0]"), std::string::npos) << k;
}
