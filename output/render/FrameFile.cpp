#include "render/FrameFile.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "SceneFrame.hpp"
#include "io/InputFile.hpp"
#include "render/FrameXml.hpp"

namespace chute::render {

namespace {

// Points of each cell type a chute frame holds; -1 for any other type.
int pointsOf(int type) {
  switch (type) {
    case VTK_VERTEX:
      return 1;
    case VTK_LINE:
      return 2;
    case VTK_TRIANGLE:
      return 3;
    case VTK_QUAD:
      return 4;
    default:
      return -1;
  }
}

std::string count(double x) {
  return std::abs(x) < 1e15 && x == std::floor(x) ? std::to_string(static_cast<long long>(x))
                                                  : std::to_string(x);
}

[[noreturn]] void fail(const std::string& path, const std::string& why) {
  throw std::runtime_error(path + ": " + why + " (not a frame chute wrote)");
}

}  // namespace

void checkFrame(vtkUnstructuredGrid* g, const std::string& path) {
  const vtkIdType nPoints = g->GetNumberOfPoints(), nCells = g->GetNumberOfCells();
  if (nPoints == 0) fail(path, "no points");
  for (vtkIdType i = 0; i < nPoints; ++i) {
    double x[3];
    g->GetPoints()->GetPoint(i, x);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
      fail(path, "point " + std::to_string(i) + " is not finite");
  }
  // The raw cell arrays, read without VTK's cell accessors (which trust them).
  vtkCellArray* cells = g->GetCells();
  vtkUnsignedCharArray* types = g->GetCellTypesArray();
  if (!cells || !types) fail(path, "no cells");
  vtkDataArray* offsets = cells->GetOffsetsArray();
  vtkDataArray* connectivity = cells->GetConnectivityArray();
  if (types->GetNumberOfTuples() != nCells || !offsets ||
      offsets->GetNumberOfTuples() != nCells + 1 || !connectivity)
    fail(path, "the cell types, offsets and cells do not match in number");
  const vtkIdType nIds = connectivity->GetNumberOfTuples();
  if (offsets->GetComponent(0, 0) != 0.0) fail(path, "the first cell does not start at 0");
  for (vtkIdType c = 0; c < nCells; ++c) {
    const int type = types->GetValue(c);
    const double begin = offsets->GetComponent(c, 0), end = offsets->GetComponent(c + 1, 0);
    if (pointsOf(type) < 0)
      fail(path, "cell " + std::to_string(c) + " is of VTK type " + std::to_string(type) +
                     " (chute draws vertices, lines, triangles and quadrangles)");
    if (!(end - begin == pointsOf(type)) || end > double(nIds))
      fail(path, "cell " + std::to_string(c) + " has " + count(end - begin) +
                     " points for its type " + std::to_string(type));
    for (auto k = static_cast<vtkIdType>(begin); k < static_cast<vtkIdType>(end); ++k) {
      const double id = connectivity->GetComponent(k, 0);
      if (!(id >= 0.0 && id < double(nPoints)))
        fail(path, "cell " + std::to_string(c) + " names point " + count(id) + " of " +
                       std::to_string(nPoints));
    }
  }
  for (int i = 0; i < g->GetPointData()->GetNumberOfArrays(); ++i) {
    vtkDataArray* a = g->GetPointData()->GetArray(i);
    if (a && a->GetNumberOfTuples() != nPoints)
      fail(path, std::string("point field '") + (a->GetName() ? a->GetName() : "?") + "' has " +
                     std::to_string(a->GetNumberOfTuples()) + " values for " +
                     std::to_string(nPoints) + " points");
  }
  for (int i = 0; i < g->GetCellData()->GetNumberOfArrays(); ++i) {
    vtkDataArray* a = g->GetCellData()->GetArray(i);
    if (a && a->GetNumberOfTuples() != nCells)
      fail(path, std::string("cell field '") + (a->GetName() ? a->GetName() : "?") + "' has " +
                     std::to_string(a->GetNumberOfTuples()) + " values for " +
                     std::to_string(nCells) + " cells");
  }
  vtkDataArray* kind = g->GetCellData()->GetArray("kind");
  if (!kind || kind->GetNumberOfComponents() != 1) fail(path, "no cell field 'kind'");
  for (vtkIdType c = 0; c < nCells; ++c) {
    const double k = kind->GetComponent(c, 0);
    if (!(k >= static_cast<int>(CellKind::Cable) && k <= static_cast<int>(CellKind::PointMass)))
      fail(path, "cell " + std::to_string(c) + " has kind " + count(k));
  }
}

vtkSmartPointer<vtkUnstructuredGrid> readFrame(const std::string& path) {
  std::string bytes = io::readInputFile(path, kMaxFrameBytes);
  const std::vector<std::string> parts = checkFrameXml(bytes, path);
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->ReadFromInputStringOn();
  reader->SetInputString(withoutFieldData(std::move(bytes)));
  bytes = std::string();  // the reader holds its own copy
  reader->Update();
  auto* out = reader->GetOutput();
  if (!out || out->GetNumberOfPoints() == 0)
    throw std::runtime_error(path + ": cannot read (not a VTK unstructured grid)");
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->ShallowCopy(out);
  if (!parts.empty()) {
    vtkNew<vtkStringArray> names;
    names->SetName("part_names");
    for (const auto& n : parts) names->InsertNextValue(n);
    grid->GetFieldData()->AddArray(names);
  }
  checkFrame(grid, path);
  return grid;
}

}  // namespace chute::render
