#include "VtuVtkFrame.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <stdexcept>

namespace chute {

namespace {
vtkSmartPointer<vtkDataArray> toVtk(const FieldArray& a) {
  vtkSmartPointer<vtkDataArray> arr;
  if (a.integer)
    arr = vtkSmartPointer<vtkIntArray>::New();
  else
    arr = vtkSmartPointer<vtkDoubleArray>::New();
  arr->SetName(a.name.c_str());
  arr->SetNumberOfComponents(a.components);
  const vtkIdType n = static_cast<vtkIdType>(a.values.size()) / a.components;
  arr->SetNumberOfTuples(n);
  for (size_t c = 0; c < a.componentNames.size(); ++c)
    arr->SetComponentName(static_cast<vtkIdType>(c), a.componentNames[c].c_str());
  if (a.integer) {
    auto* ia = static_cast<vtkIntArray*>(arr.Get());
    for (size_t i = 0; i < a.values.size(); ++i) ia->SetValue(i, static_cast<int>(a.values[i]));
  } else {
    auto* da = static_cast<vtkDoubleArray*>(arr.Get());
    std::copy(a.values.begin(), a.values.end(), da->GetPointer(0));
  }
  return arr;
}
}  // namespace

std::string vtuVtkText(const SceneFrame& f, VtkCompression compression) {
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkDoubleArray> coords;
  coords->SetNumberOfComponents(3);
  coords->SetNumberOfTuples(static_cast<vtkIdType>(f.points.size() / 3));
  std::copy(f.points.begin(), f.points.end(), coords->GetPointer(0));
  vtkNew<vtkPoints> points;
  points->SetData(coords);
  grid->SetPoints(points);

  vtkNew<vtkIdTypeArray> offsets, conn;
  offsets->SetNumberOfTuples(f.numCells() + 1);
  offsets->SetValue(0, 0);
  for (int c = 0; c < f.numCells(); ++c) offsets->SetValue(c + 1, f.offsets[c]);
  conn->SetNumberOfTuples(static_cast<vtkIdType>(f.connectivity.size()));
  for (size_t i = 0; i < f.connectivity.size(); ++i) conn->SetValue(i, f.connectivity[i]);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, conn);
  vtkNew<vtkUnsignedCharArray> types;
  types->SetNumberOfTuples(f.numCells());
  for (int c = 0; c < f.numCells(); ++c)
    types->SetValue(c, static_cast<unsigned char>(f.shapes[c]));
  grid->SetCells(types, cells);

  for (const auto& a : f.pointData) grid->GetPointData()->AddArray(toVtk(a));
  for (const auto& a : f.cellData) grid->GetCellData()->AddArray(toVtk(a));
  vtkNew<vtkDoubleArray> time;
  time->SetName("TimeValue");
  time->InsertNextValue(f.t);
  grid->GetFieldData()->AddArray(time);
  vtkNew<vtkStringArray> parts;
  parts->SetName("part_names");
  for (const auto& n : f.partNames) parts->InsertNextValue(n);
  grid->GetFieldData()->AddArray(parts);

  vtkNew<vtkXMLUnstructuredGridWriter> w;
  w->SetDataModeToAppended();
  w->EncodeAppendedDataOff();  // raw binary
  // LZ4, not zlib: VTK 9.1's zlib compressor allocates and clears large buffers for every array
  // (~30 ms a frame measured on a 15-node scene).
  if (compression == VtkCompression::LZ4)
    w->SetCompressorTypeToLZ4();
  else
    w->SetCompressorTypeToNone();
  // Into memory, then one write by the caller: the XML writer otherwise makes hundreds of small
  // writes and seeks per file.
  w->WriteToOutputStringOn();
  w->SetInputData(grid);
  if (w->Write() != 1) throw std::runtime_error("VTK's XML writer failed");
  return w->GetOutputString();
}

}  // namespace chute
