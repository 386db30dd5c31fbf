#pragma once
// The elements the intersection check (mesh/IntersectionCheck.hpp) looks at, taken from a frame
// of a run: membrane triangles and quadrilaterals (as two triangles) and 2-node line cells
// (cables, trusses, sliding elements and their parts through a slider); vertices are ignored.
// Either from a state (SceneFrame, as the run writes it) or from a .vtu file on disk
// (render/IntersectionFrameFile.hpp: the frame checked as `chute render` checks it).
#include "IntersectionCheck.hpp"
#include "SceneFrame.hpp"

namespace chute {

mesh::IntersectionMesh intersectionMesh(const SceneFrame& frame);

// Adds a cell of VTK type `vtkType` with point indices ids (a vertex adds nothing); false for a
// cell of another kind (polygons, volumes).
bool addIntersectionCell(mesh::IntersectionMesh& m, int vtkType, const int* ids);

}  // namespace chute
