#include "render/IntersectionFrameFile.hpp"

#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <stdexcept>

#include "IntersectionFrames.hpp"
#include "render/FrameFile.hpp"

namespace chute::render {

mesh::IntersectionMesh readIntersectionMesh(const std::string& file) {
  const vtkSmartPointer<vtkUnstructuredGrid> grid = readFrame(file);
  mesh::IntersectionMesh m;
  const vtkIdType n = grid->GetNumberOfPoints();
  m.points.resize(n);
  for (vtkIdType i = 0; i < n; ++i) {
    double p[3];
    grid->GetPoint(i, p);
    m.points[i] = Vec3(p[0], p[1], p[2]);
  }
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    grid->GetCellPoints(c, ids);
    int v[4] = {0, 0, 0, 0};
    for (vtkIdType k = 0; k < std::min<vtkIdType>(ids->GetNumberOfIds(), 4); ++k)
      v[k] = static_cast<int>(ids->GetId(k));
    if (!addIntersectionCell(m, grid->GetCellType(c), v))
      throw std::runtime_error(file + ": cell " + std::to_string(c) + " has VTK type " +
                               std::to_string(grid->GetCellType(c)) +
                               " (only vertices, lines, triangles and quadrilaterals are checked)");
  }
  return m;
}

}  // namespace chute::render
