#include "app/CborNesting.hpp"

namespace chute {

std::string cborNestingProblem(const std::vector<std::uint8_t>& b, int maxDepth) {
  // remaining[k]: items still to read in the container open at depth k (a map counts 2 per
  // entry). The top level is one item.
  std::vector<std::uint64_t> remaining{1};
  size_t at = 0;
  const size_t n = b.size();
  while (!remaining.empty()) {
    if (remaining.back() == 0) {
      remaining.pop_back();
      continue;
    }
    --remaining.back();
    if (at >= n) return "ends inside an item";
    const int major = b[at] >> 5, info = b[at] & 31;
    ++at;
    std::uint64_t arg = 0;
    if (info < 24) {
      arg = static_cast<std::uint64_t>(info);
    } else if (info <= 27) {
      const size_t size = size_t{1} << (info - 24);
      if (n - at < size) return "ends inside an item's length";
      for (size_t k = 0; k < size; ++k) arg = arg << 8 | b[at + k];
      at += size;
    } else {
      return "indefinite length or reserved byte (not written by chute)";
    }
    switch (major) {
      case 0:
      case 1:
      case 7:
        break;  // integers, floats and simple values carry no content
      case 2:
      case 3:
        if (arg > n - at) return "a string longer than the file";
        at += static_cast<size_t>(arg);
        break;
      case 4:
      case 5: {
        const std::uint64_t items = major == 5 ? arg * 2 : arg;
        if ((major == 5 && arg > (n - at) / 2) || items > n - at)
          return "a container with more items than the file has bytes";
        if (static_cast<int>(remaining.size()) >= maxDepth)
          return "nested more than " + std::to_string(maxDepth) + " levels deep";
        remaining.push_back(items);
        break;
      }
      case 6:  // a tag prefixes one item: it nests like a container of one
        if (static_cast<int>(remaining.size()) >= maxDepth)
          return "nested more than " + std::to_string(maxDepth) + " levels deep";
        remaining.push_back(1);
        break;
    }
  }
  if (at != n) return "bytes after the end of the data";
  return {};
}

}  // namespace chute
