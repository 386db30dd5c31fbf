// libFuzzer target: chute's .msh reader (mesh/MshReader, the reader of every case's mesh). The
// bytes are written to a temporary .msh file and read; a MeshError (bad mesh, reported) is the
// expected outcome for most inputs, anything else escaping or a sanitizer report is a finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include "MeshError.hpp"
#include "MshReader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string file = "/tmp/chute_fuzz_msh_" + std::to_string(getpid()) + ".msh";
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    chute::mesh::readMsh(file);
  } catch (const chute::mesh::MeshError&) {
    // A bad mesh, reported.
  }
  return 0;
}
