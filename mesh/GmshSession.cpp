#include "GmshSession.hpp"

#include <gmsh.h>

#include "GmshMesh.hpp"

namespace chute::mesh {

namespace {
// Initialises gmsh on first use and finalises it when the process exits.
struct GmshProcess {
  std::mutex mutex;
  GmshProcess() {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 1);  // errors only, into the logger
  }
  ~GmshProcess() { gmsh::finalize(); }
};

GmshProcess& process() {
  static GmshProcess p;
  return p;
}

}  // namespace

GmshScope::GmshScope() : lock_(process().mutex) {
  gmsh::clear();
  gmsh::logger::start();
}

GmshScope::~GmshScope() {
  gmsh::logger::stop();
  gmsh::clear();
}

std::string gmshLastError() {
  std::string e;
  try {
    gmsh::logger::getLastError(e);
  } catch (...) {
    e.clear();
  }
  return e;
}

}  // namespace chute::mesh
