#include "IntersectionFrames.hpp"

#include <vtkCellType.h>

namespace chute {

bool addIntersectionCell(mesh::IntersectionMesh& m, int type, const int* ids) {
  switch (type) {
    case VTK_VERTEX:
      return true;
    case VTK_LINE:
      m.segments.push_back({ids[0], ids[1]});
      return true;
    case VTK_TRIANGLE:
      m.triangles.push_back({ids[0], ids[1], ids[2]});
      return true;
    case VTK_QUAD:
      m.addQuad(ids[0], ids[1], ids[2], ids[3]);
      return true;
    default:
      return false;
  }
}

mesh::IntersectionMesh intersectionMesh(const SceneFrame& f) {
  mesh::IntersectionMesh m;
  const size_t n = f.points.size() / 3;
  m.points.reserve(n);
  for (size_t i = 0; i < n; ++i)
    m.points.emplace_back(f.points[3 * i], f.points[3 * i + 1], f.points[3 * i + 2]);
  int begin = 0;
  for (int c = 0; c < f.numCells(); ++c) {
    addIntersectionCell(m, static_cast<int>(f.shapes[c]), f.connectivity.data() + begin);
    begin = f.offsets[c];
  }
  return m;
}

}  // namespace chute
