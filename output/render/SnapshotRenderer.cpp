#include "render/SnapshotRenderer.hpp"

#include <fmt/core.h>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkGeometryFilter.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTubeFilter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkWindowToImageFilter.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "VtuSeries.hpp"
#include "render/VirtualDisplay.hpp"

namespace chute::render {

namespace fs = std::filesystem;

namespace {

struct Run {
  std::string dir, name;
  std::vector<PvdEntry> frames;
};

Run openRun(const std::string& dir) {
  if (!fs::is_directory(dir)) throw std::runtime_error(dir + ": no such run directory");
  Run r;
  r.dir = dir;
  std::vector<fs::path> pvds;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".pvd") pvds.push_back(e.path());
  if (pvds.empty())
    throw std::runtime_error(dir + ": no .pvd series (ask for one with [output.vtu] in the case)");
  if (pvds.size() > 1) throw std::runtime_error(dir + ": more than one .pvd series");
  r.name = pvds[0].stem().string();
  r.frames = readPvd(pvds[0].string());
  if (r.frames.empty()) throw std::runtime_error(pvds[0].string() + ": the series is empty");
  return r;
}

// Indices of the frames nearest to the requested times (the last frame if none).
std::vector<int> pickFrames(const Run& r, const SnapshotOptions& o) {
  std::vector<int> idx;
  if (o.allFrames) {
    for (size_t i = 0; i < r.frames.size(); ++i) idx.push_back(static_cast<int>(i));
    return idx;
  }
  if (o.times.empty()) return {static_cast<int>(r.frames.size()) - 1};
  for (double t : o.times) {
    int best = 0;
    for (size_t i = 1; i < r.frames.size(); ++i)
      if (std::abs(r.frames[i].t - t) < std::abs(r.frames[best].t - t)) best = static_cast<int>(i);
    idx.push_back(best);
  }
  return idx;
}

vtkSmartPointer<vtkUnstructuredGrid> load(const Run& r, int frame) {
  const std::string path = (fs::path(r.dir) / r.frames[frame].file).string();
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  auto* out = reader->GetOutput();
  if (!out || out->GetNumberOfPoints() == 0) throw std::runtime_error(path + ": cannot read");
  vtkSmartPointer<vtkUnstructuredGrid> grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->DeepCopy(out);
  return grid;
}

// Where the colour field lives: 1 point data, 2 cell data.
int fieldLocation(vtkUnstructuredGrid* g, const std::string& name) {
  if (g->GetPointData()->GetArray(name.c_str())) return 1;
  if (g->GetCellData()->GetArray(name.c_str())) return 2;
  std::string known;
  for (int i = 0; i < g->GetPointData()->GetNumberOfArrays(); ++i)
    known += std::string(known.empty() ? "" : ", ") + g->GetPointData()->GetArrayName(i);
  for (int i = 0; i < g->GetCellData()->GetNumberOfArrays(); ++i)
    known += std::string(known.empty() ? "" : ", ") + g->GetCellData()->GetArrayName(i);
  throw std::runtime_error("no field '" + name + "' in the run (fields: " + known + ")");
}

vtkDataArray* fieldArray(vtkUnstructuredGrid* g, const std::string& name) {
  return fieldLocation(g, name) == 1 ? g->GetPointData()->GetArray(name.c_str())
                                     : g->GetCellData()->GetArray(name.c_str());
}

struct Scene {
  vtkSmartPointer<vtkActor> surface, tubes;
  vtkSmartPointer<vtkTextActor> label;
};

Scene buildScene(vtkUnstructuredGrid* grid, const std::string& field, vtkLookupTable* lut,
                 const std::array<double, 2>& range, double tubeRadius, const std::string& text,
                 int fontSize) {
  Scene s;
  vtkNew<vtkGeometryFilter> geometry;
  geometry->SetInputData(grid);
  const bool onPoints = fieldLocation(grid, field) == 1;
  auto colour = [&](vtkPolyDataMapper* m) {
    if (onPoints)
      m->SetScalarModeToUsePointFieldData();
    else
      m->SetScalarModeToUseCellFieldData();
    m->SelectColorArray(field.c_str());
    m->SetLookupTable(lut);
    m->SetUseLookupTableScalarRange(true);
    m->SetColorModeToMapScalars();
    m->ScalarVisibilityOn();
  };
  vtkNew<vtkPolyDataMapper> surfaceMapper;
  surfaceMapper->SetInputConnection(geometry->GetOutputPort());
  colour(surfaceMapper);
  s.surface = vtkSmartPointer<vtkActor>::New();
  s.surface->SetMapper(surfaceMapper);
  s.surface->GetProperty()->SetPointSize(10.0);
  s.surface->GetProperty()->SetRenderPointsAsSpheres(true);
  s.surface->GetProperty()->SetSpecular(0.2);

  vtkNew<vtkTubeFilter> tubes;
  tubes->SetInputConnection(geometry->GetOutputPort());
  tubes->SetRadius(tubeRadius);
  tubes->SetNumberOfSides(10);
  tubes->CappingOn();
  vtkNew<vtkPolyDataMapper> tubeMapper;
  tubeMapper->SetInputConnection(tubes->GetOutputPort());
  colour(tubeMapper);
  s.tubes = vtkSmartPointer<vtkActor>::New();
  s.tubes->SetMapper(tubeMapper);
  (void)range;

  s.label = vtkSmartPointer<vtkTextActor>::New();
  s.label->SetInput(text.c_str());
  s.label->GetTextProperty()->SetFontSize(fontSize);
  s.label->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
  s.label->SetDisplayPosition(12, 12);
  return s;
}

void placeCamera(vtkCamera* cam, const std::array<double, 6>& b, const std::string& view,
                 double aspect) {
  const double c[3] = {(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2};
  const double diag =
      std::max(1e-12, std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
                                (b[5] - b[4]) * (b[5] - b[4])));
  double d[3] = {0, 1, 0}, up[3] = {0, 0, 1};  // side: looking along +y, z up
  if (view == "below") d[0] = 0, d[1] = 0, d[2] = 1, up[0] = 0, up[1] = 1, up[2] = 0;
  if (view == "iso") {
    const double n = std::sqrt(1 + 1 + 0.64);
    d[0] = 1 / n, d[1] = 1 / n, d[2] = -0.8 / n;
  }
  // Far enough that the bounding sphere fits the 30-degree view in both directions.
  const double fit = 0.5 * diag / std::tan(15.0 * M_PI / 180.0) / std::min(1.0, aspect) * 1.05;
  cam->SetFocalPoint(c);
  cam->SetPosition(c[0] - fit * d[0], c[1] - fit * d[1], c[2] - fit * d[2]);
  cam->SetViewUp(up);
  cam->SetViewAngle(30.0);
}

}  // namespace

std::vector<std::string> renderSnapshots(const SnapshotOptions& o) {
  if (o.view != "side" && o.view != "below" && o.view != "iso")
    throw std::runtime_error("--view must be side, below or iso (got '" + o.view + "')");
  if (o.width < 16 || o.height < 16 || o.width > 8192 || o.height > 8192)
    throw std::runtime_error("image size must be between 16 and 8192 pixels");
  std::vector<Run> runs = {openRun(o.runDir)};
  if (!o.compareDir.empty()) runs.push_back(openRun(o.compareDir));

  // Load every frame first: the camera and colour range are common to all images.
  std::vector<std::vector<vtkSmartPointer<vtkUnstructuredGrid>>> grids(runs.size());
  std::vector<std::vector<double>> times(runs.size());
  const auto picks = pickFrames(runs[0], o);
  std::array<double, 6> bounds = {1e300, -1e300, 1e300, -1e300, 1e300, -1e300};
  std::array<double, 2> range = {std::numeric_limits<double>::infinity(),
                                 -std::numeric_limits<double>::infinity()};
  for (size_t r = 0; r < runs.size(); ++r) {
    for (int p : picks) {
      // A compared run: the frame nearest to the first run's time.
      const double t = runs[0].frames[p].t;
      int f = p;
      if (r > 0) {
        SnapshotOptions one = o;
        one.allFrames = false;
        one.times = {t};
        f = pickFrames(runs[r], one)[0];
      }
      auto g = load(runs[r], f);
      double b[6];
      g->GetBounds(b);
      for (int k = 0; k < 3; ++k)
        bounds[2 * k] = std::min(bounds[2 * k], b[2 * k]),
                   bounds[2 * k + 1] = std::max(bounds[2 * k + 1], b[2 * k + 1]);
      double fr[2];
      fieldArray(g, o.color)->GetFiniteRange(fr, -1);
      if (std::isfinite(fr[0])) range[0] = std::min(range[0], fr[0]);
      if (std::isfinite(fr[1])) range[1] = std::max(range[1], fr[1]);
      grids[r].push_back(g);
      times[r].push_back(runs[r].frames[f].t);
    }
  }
  if (!(range[0] <= range[1])) range = {0.0, 1.0};
  if (range[1] - range[0] < 1e-300) range[1] = range[0] + 1.0;

  VirtualDisplay display;  // only now: errors above need no display
  fs::create_directories(o.outDir);
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.0);
  lut->SetVectorModeToMagnitude();
  lut->SetTableRange(range[0], range[1]);
  lut->SetNanColor(0.6, 0.6, 0.6, 1.0);
  lut->Build();

  const double diag = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
                                (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
                                (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  const double tube = std::max(1e-6, 0.003 * diag);
  const int fontSize = std::max(12, o.height / 36);
  const double panelAspect = double(o.width) / runs.size() / o.height;

  std::vector<std::string> written;
  for (size_t i = 0; i < picks.size(); ++i) {
    vtkNew<vtkRenderWindow> window;
    window->SetOffScreenRendering(1);
    window->SetSize(o.width, o.height);
    vtkSmartPointer<vtkCamera> camera = vtkSmartPointer<vtkCamera>::New();
    placeCamera(camera, bounds, o.view, panelAspect);
    for (size_t r = 0; r < runs.size(); ++r) {
      vtkNew<vtkRenderer> ren;
      ren->SetViewport(double(r) / runs.size(), 0.0, double(r + 1) / runs.size(), 1.0);
      ren->SetBackground(1.0, 1.0, 1.0);
      ren->SetActiveCamera(camera);
      const std::string text = fmt::format(
          "{}   t = {:.4g}",
          runs[r].name +
              (runs.size() > 1 ? " (" + fs::path(runs[r].dir).filename().string() + ")" : ""),
          times[r][i]);
      const Scene s = buildScene(grids[r][i], o.color, lut, range, tube, text, fontSize);
      ren->AddActor(s.surface);
      ren->AddActor(s.tubes);
      ren->AddActor2D(s.label);
      if (r + 1 == runs.size()) {
        vtkNew<vtkScalarBarActor> bar;
        bar->SetLookupTable(lut);
        const bool vector = fieldArray(grids[r][i], o.color)->GetNumberOfComponents() > 1;
        bar->SetTitle((vector ? "|" + o.color + "|" : o.color).c_str());
        bar->SetNumberOfLabels(5);
        bar->SetWidth(0.08 * runs.size());
        bar->SetHeight(0.6);
        // Its title is centred over it and wider than the bar: the bar's centre at 0.86 of the
        // view leaves the title room to the right edge.
        bar->SetPosition(0.86 - 0.04 * runs.size(), 0.2);
        bar->GetTitleTextProperty()->SetColor(0.1, 0.1, 0.1);
        bar->GetLabelTextProperty()->SetColor(0.1, 0.1, 0.1);
        bar->UnconstrainedFontSizeOn();
        bar->GetTitleTextProperty()->SetFontSize(fontSize);
        bar->GetLabelTextProperty()->SetFontSize(fontSize * 4 / 5);
        ren->AddActor2D(bar);
      }
      ren->ResetCameraClippingRange();
      window->AddRenderer(ren);
    }
    window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    grab->ReadFrontBufferOff();
    grab->Update();
    const std::string file =
        (fs::path(o.outDir) / fmt::format("{}{}_{}_t{:.6f}.png", runs[0].name,
                                          runs.size() > 1 ? "_compare" : "", o.view, times[0][i]))
            .string();
    vtkNew<vtkPNGWriter> png;
    png->SetFileName(file.c_str());
    png->SetInputConnection(grab->GetOutputPort());
    png->Write();
    if (!fs::exists(file)) throw std::runtime_error("cannot write " + file);
    written.push_back(file);
  }
  return written;
}

}  // namespace chute::render
