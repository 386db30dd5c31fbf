#pragma once
#include <stdexcept>
#include <string>

namespace chute {

// Bad input: the message names the file, the line and the key ("case.toml:12: solver.dt: ...").
class CaseError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace chute
