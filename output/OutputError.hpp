#pragma once
// A write of a run's output failed (a full disk, a removed directory): the run stops, says what
// it had written whole, and `chute run` exits with its own status (docs/exit-codes.md).
#include <stdexcept>

namespace chute {

class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace chute
