#include "IntersectionFrames.hpp"

#include <vtkCellType.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <filesystem>
#include <stdexcept>

namespace chute {

namespace {

// Adds one cell of VTK type `type` with vertices ids; false for a cell of another kind.
bool addCell(mesh::IntersectionMesh& m, int type, const int* ids) {
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

}  // namespace

mesh::IntersectionMesh intersectionMesh(const SceneFrame& f) {
  mesh::IntersectionMesh m;
  const size_t n = f.points.size() / 3;
  m.points.reserve(n);
  for (size_t i = 0; i < n; ++i)
    m.points.emplace_back(f.points[3 * i], f.points[3 * i + 1], f.points[3 * i + 2]);
  int begin = 0;
  for (int c = 0; c < f.numCells(); ++c) {
    addCell(m, static_cast<int>(f.shapes[c]), f.connectivity.data() + begin);
    begin = f.offsets[c];
  }
  return m;
}

mesh::IntersectionMesh readIntersectionMesh(const std::string& file) {
  if (!std::filesystem::is_regular_file(file)) throw std::runtime_error(file + ": no such file");
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  if (reader->GetErrorCode() != 0 || !grid || grid->GetNumberOfPoints() == 0)
    throw std::runtime_error(file + ": cannot read the frame (not a VTU file, or empty)");
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
    if (!addCell(m, grid->GetCellType(c), v))
      throw std::runtime_error(file + ": cell " + std::to_string(c) + " has VTK type " +
                               std::to_string(grid->GetCellType(c)) +
                               " (only vertices, lines, triangles and quadrilaterals are checked)");
  }
  return m;
}

}  // namespace chute
