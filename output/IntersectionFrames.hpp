#pragma once
// The elements the intersection check (mesh/IntersectionCheck.hpp) looks at, taken from a frame
// of a run: membrane triangles and quadrilaterals (as two triangles) and 2-node line cells
// (cables, trusses, sliding elements and their parts through a slider); vertices are ignored.
// Either from a state (SceneFrame, as the run writes it) or from a .vtu file on disk (read with
// VTK's XML reader).
#include <string>

#include "IntersectionCheck.hpp"
#include "SceneFrame.hpp"

namespace chute {

mesh::IntersectionMesh intersectionMesh(const SceneFrame& frame);

// Throws std::runtime_error naming the file if it cannot be read or holds a cell of another kind
// (polygons, volumes).
mesh::IntersectionMesh readIntersectionMesh(const std::string& vtuFile);

}  // namespace chute
