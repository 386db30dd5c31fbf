// libFuzzer target: the case-file reader (issue 9, item 4). Any input must either read or give
// a CaseError; anything else escaping (another exception, a crash, a leak, a sanitizer report,
// a hang) is a finding. Leading lines "#set key=value" become --set overrides, so the fuzzer also
// explores command-line overrides while every corpus file stays a valid TOML file.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "case/CaseError.hpp"
#include "case/CaseSpec.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> sets;
  size_t pos = 0;
  while (text.compare(pos, 5, "#set ") == 0) {
    const size_t end = text.find('\n', pos);
    sets.push_back(text.substr(pos + 5, end == std::string::npos ? end : end - pos - 5));
    if (end == std::string::npos) break;
    pos = end + 1;
  }
  try {
    chute::readCaseFromString(text, "fuzz.toml", sets);
  } catch (const chute::CaseError&) {
    // Bad input, reported: the expected outcome for almost every input.
  }
  return 0;
}
