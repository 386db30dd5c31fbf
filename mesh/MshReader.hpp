#pragma once
// chute's own reader of gmsh .msh files, formats 2.2 and 4.1, ASCII and binary (little-endian,
// 8-byte size_t). It returns what the gmsh API path returned (GmshMesh.hpp: physical groups in
// gmsh's order, the nodes they use, 3-component NodeData views at step 0) without running any
// gmsh code on the file: every count and index is checked against the bytes left in the file and
// against MshLimits before anything is allocated, and every coordinate must be finite and within
// +-1e100. Errors are MeshError "file:line: reason" (binary data: the line of its section header
// and the byte offset).
#include <cstddef>
#include <cstdint>
#include <string>

#include "GmshMesh.hpp"

namespace chute::mesh {

// Documented in docs/limits.md; a case overrides them with [mesh] max_nodes / max_elements.
struct MshLimits {
  std::size_t maxNodes = 1000000;            // nodes in $Nodes (and values in one $NodeData)
  std::size_t maxElements = 4000000;         // elements in $Elements
  std::uintmax_t maxFileBytes = 1ull << 30;  // 1 GiB: a 1e6-node mesh is about 100 MB of text
};

// Reads a .msh file. Throws MeshError naming the file (and line) on anything it cannot promise
// to read exactly: not a regular file, another format version, counts that do not match the
// data, unknown nodes, non-finite coordinates, element types other than first-order points,
// lines, triangles and quadrangles inside a physical group.
GmshMesh readMsh(const std::string& file, const MshLimits& limits = {});

// The same, from bytes already in memory (`name` is used in messages).
GmshMesh parseMsh(const std::string& bytes, const std::string& name, const MshLimits& limits = {});

}  // namespace chute::mesh
