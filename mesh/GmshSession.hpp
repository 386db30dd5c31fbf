#pragma once
// gmsh is one global, non-thread-safe state per process: it is initialised once (on first use,
// quietly: General.Terminal = 0) and finalised at exit. A GmshScope serialises users and gives
// each a fresh, empty gmsh model, cleared again when the scope ends.
#include <mutex>
#include <stdexcept>
#include <string>

#include "MeshError.hpp"

namespace chute::mesh {

class GmshScope {
 public:
  GmshScope();
  ~GmshScope();
  GmshScope(const GmshScope&) = delete;
  GmshScope& operator=(const GmshScope&) = delete;

 private:
  std::unique_lock<std::mutex> lock_;
};

// Runs f (a call into the gmsh API); turns whatever gmsh throws into a MeshError that starts with
// `what` and ends with gmsh's last error message. chute's own std::invalid_argument (a bad option
// found while building) passes unchanged: it is bad input, not a failure of gmsh.
template <class F>
auto callGmsh(const std::string& what, F&& f) -> decltype(f());

std::string gmshLastError();

template <class F>
auto callGmsh(const std::string& what, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const MeshError&) {
    throw;
  } catch (const std::invalid_argument&) {  // chute's own refusal of a bad option inside f
    throw;
  } catch (...) {
    const std::string e = gmshLastError();
    throw MeshError(what + (e.empty() ? std::string() : ": " + e));
  }
}

}  // namespace chute::mesh
