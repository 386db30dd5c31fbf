#pragma once
// nlohmann::json::from_cbor reads nested arrays and maps by recursion, one stack frame per
// level: a file of a few hundred thousand bytes 0x81 ("an array of one element", nested)
// overflows the stack before any field is looked at. This walk is iterative and checks the
// bytes before that reader sees them: well-formed definite-length CBOR, no deeper than
// `maxDepth`, every length within the buffer. A checkpoint nests 4 levels deep.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace chute {

// Empty when the bytes pass; otherwise why they do not (for the error message).
std::string cborNestingProblem(const std::vector<std::uint8_t>& bytes, int maxDepth);

}  // namespace chute
