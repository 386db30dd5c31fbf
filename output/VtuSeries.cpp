#include "VtuSeries.hpp"

#include <fcntl.h>
#include <fmt/core.h>
#include <unistd.h>
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
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace chute {

namespace {
constexpr const char* kHeader =
    "<?xml version=\"1.0\"?>\n"
    "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
    "  <Collection>\n";
constexpr size_t kCompressAbove = 64 * 1024;  // bytes of array data in a frame
constexpr const char* kFooter = "  </Collection>\n</VTKFile>\n";

std::string entryLine(double t, const std::string& file) {
  return fmt::format("    <DataSet timestep=\"{:.17g}\" group=\"\" part=\"0\" file=\"{}\"/>\n", t,
                     file);
}

void writeAllAt(int fd, const std::string& text, long offset, const std::string& path) {
  const char* p = text.data();
  size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::pwrite(fd, p, left, offset);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
    }
    p += n, left -= static_cast<size_t>(n), offset += n;
  }
}

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

struct VtuSeries::Vtk {
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
};

VtuSeries::VtuSeries(std::string dir, std::string name)
    : dir_(std::move(dir)), name_(std::move(name)), vtk_(std::make_unique<Vtk>()) {
  std::filesystem::create_directories(dir_);
  // Frames of an earlier run of this case in this directory go first: they would be stale, and
  // writing over them costs more than writing new files (ext4 flushes a file truncated on open).
  const std::string prefix = name_ + "_";
  for (const auto& e : std::filesystem::directory_iterator(dir_)) {
    const std::string f = e.path().filename().string();
    if (f.size() == prefix.size() + 10 && f.starts_with(prefix) && f.ends_with(".vtu"))
      std::filesystem::remove(e.path());
  }
  start({});
}

VtuSeries::VtuSeries(std::string dir, std::string name, double resumeAfter)
    : dir_(std::move(dir)), name_(std::move(name)), vtk_(std::make_unique<Vtk>()) {
  std::filesystem::create_directories(dir_);
  std::vector<PvdEntry> kept;
  if (std::filesystem::exists(pvdPath())) {
    for (const auto& e : readPvd(pvdPath())) {
      if (e.t <= resumeAfter)
        kept.push_back(e);
      else
        std::filesystem::remove(std::filesystem::path(dir_) / e.file);
    }
  }
  frames_ = static_cast<int>(kept.size());
  start(kept);
}

void VtuSeries::start(const std::vector<PvdEntry>& kept) {
  const std::string path = pvdPath();
  std::string text = kHeader;
  for (const auto& e : kept) text += entryLine(e.t, e.file);
  footerAt_ = static_cast<long>(text.size());
  text += kFooter;
  // A new file: written whole under a temporary name, then renamed over the old collection.
  const std::string tmp = path + ".tmp";
  fd_ = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) throw std::runtime_error("cannot create " + tmp + ": " + std::strerror(errno));
  writeAllAt(fd_, text, 0, tmp);
  std::filesystem::rename(tmp, path);
  auto& w = vtk_->writer;
  w->SetDataModeToAppended();
  w->EncodeAppendedDataOff();  // raw binary
  // LZ4 for frames worth compressing (see write()): VTK 9.1's zlib compressor allocates and
  // clears large buffers for every array (~30 ms a frame measured on a 15-node scene).
  w->SetCompressorTypeToLZ4();
  // Into memory, then one write: the XML writer otherwise makes hundreds of small writes and
  // seeks per file.
  w->WriteToOutputStringOn();
}

VtuSeries::~VtuSeries() {
  if (fd_ >= 0) ::close(fd_);
}

void VtuSeries::appendEntry(double t, const std::string& file) {
  // One write: the new entry followed by the closing tags, at the old closing tags.
  const std::string entry = entryLine(t, file);
  writeAllAt(fd_, entry + kFooter, footerAt_, pvdPath());
  footerAt_ += static_cast<long>(entry.size());
}

void VtuSeries::write(const SceneFrame& f) {
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

  const std::string file = fmt::format("{}_{:06d}.vtu", name_, frames_);
  const std::string path = dir_ + "/" + file;
  auto& w = vtk_->writer;
  // LZ4 clears a 16 KiB state for every array it compresses: on a small frame that costs more
  // than the bytes it saves (callgrind: a third of a pulley frame), so small frames go raw.
  size_t rawBytes = f.points.size() * sizeof(double) + f.connectivity.size() * sizeof(vtkIdType);
  for (const auto& a : f.pointData) rawBytes += a.values.size() * sizeof(double);
  for (const auto& a : f.cellData) rawBytes += a.values.size() * sizeof(double);
  if (rawBytes < kCompressAbove)
    w->SetCompressorTypeToNone();
  else
    w->SetCompressorTypeToLZ4();
  w->SetFileName(path.c_str());
  w->SetInputData(grid);
  if (w->Write() != 1) throw std::runtime_error("cannot write " + path);
  w->SetInputData(nullptr);
  {
    const std::string& text = w->GetOutputString();
    const int fd =
        ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);  // new file
    if (fd < 0) throw std::runtime_error("cannot create " + path + ": " + std::strerror(errno));
    writeAllAt(fd, text, 0, path);
    ::close(fd);
  }
  appendEntry(f.t, file);
  ++frames_;
}

std::vector<PvdEntry> readPvd(const std::string& path) {
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(path.c_str());
  if (!parser->Parse()) throw std::runtime_error(path + ": not a readable .pvd collection");
  vtkXMLDataElement* root = parser->GetRootElement();
  vtkXMLDataElement* coll = root ? root->FindNestedElementWithName("Collection") : nullptr;
  if (!coll) throw std::runtime_error(path + ": no <Collection> element");
  std::vector<PvdEntry> out;
  for (int i = 0; i < coll->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* e = coll->GetNestedElement(i);
    if (std::strcmp(e->GetName(), "DataSet") != 0) continue;
    PvdEntry p;
    if (!e->GetScalarAttribute("timestep", p.t) || !e->GetAttribute("file"))
      throw std::runtime_error(path + ": a DataSet without timestep or file");
    p.file = e->GetAttribute("file");
    out.push_back(p);
  }
  return out;
}

}  // namespace chute
