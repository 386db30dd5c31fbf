#pragma once
#include <stdexcept>

namespace chute::mesh {

// A mesh that cannot be read or built (bad file, bad geometry, a group that is not a chain):
// the message names the file and, for gmsh failures, ends with gmsh's last error.
class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace chute::mesh
