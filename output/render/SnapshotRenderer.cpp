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
#include <vtkThreshold.h>
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
#include "render/ColourLayers.hpp"
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

// One actor per layer and per drawing style: membranes as lit surfaces, lines as tubes, point
// masses as spheres. Each layer takes its cells by their "kind" and its own lookup table.
struct Scene {
  std::vector<vtkSmartPointer<vtkActor>> actors;
  vtkSmartPointer<vtkTextActor> label;
};

void colourBy(vtkPolyDataMapper* m, vtkUnstructuredGrid* grid, const ColourLayer& layer,
              vtkLookupTable* lut) {
  if (layer.field.empty()) {
    m->ScalarVisibilityOff();
    return;
  }
  if (grid->GetPointData()->GetArray(layer.field.c_str()))
    m->SetScalarModeToUsePointFieldData();
  else
    m->SetScalarModeToUseCellFieldData();
  m->SelectColorArray(layer.field.c_str());
  m->SetLookupTable(lut);
  m->SetUseLookupTableScalarRange(true);
  m->SetColorModeToMapScalars();
  m->ScalarVisibilityOn();
}

Scene buildScene(vtkUnstructuredGrid* grid, const std::vector<ColourLayer>& layers,
                 const std::vector<vtkSmartPointer<vtkLookupTable>>& luts, double tubeRadius,
                 const std::string& text, int fontSize) {
  Scene s;
  for (size_t i = 0; i < layers.size(); ++i) {
    const ColourLayer& layer = layers[i];
    vtkNew<vtkThreshold> cells;
    cells->SetInputData(grid);
    cells->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "kind");
    cells->SetLowerThreshold(layer.kindLo - 0.5);
    cells->SetUpperThreshold(layer.kindHi + 0.5);
    cells->SetThresholdFunction(vtkThreshold::THRESHOLD_BETWEEN);
    cells->Update();
    if (cells->GetOutput()->GetNumberOfCells() == 0) continue;
    vtkNew<vtkGeometryFilter> geometry;
    geometry->SetInputConnection(cells->GetOutputPort());

    vtkNew<vtkPolyDataMapper> surfaceMapper;
    surfaceMapper->SetInputConnection(geometry->GetOutputPort());
    colourBy(surfaceMapper, grid, layer, luts[i]);
    auto surface = vtkSmartPointer<vtkActor>::New();
    surface->SetMapper(surfaceMapper);
    surface->GetProperty()->SetPointSize(10.0);
    surface->GetProperty()->SetRenderPointsAsSpheres(true);
    surface->GetProperty()->SetSpecular(0.2);
    if (layer.field.empty()) surface->GetProperty()->SetColor(0.45, 0.45, 0.45);
    s.actors.push_back(surface);

    vtkNew<vtkTubeFilter> tubes;  // lines only: the filter passes no polygons
    tubes->SetInputConnection(geometry->GetOutputPort());
    tubes->SetRadius(tubeRadius);
    tubes->SetNumberOfSides(10);
    tubes->CappingOn();
    vtkNew<vtkPolyDataMapper> tubeMapper;
    tubeMapper->SetInputConnection(tubes->GetOutputPort());
    colourBy(tubeMapper, grid, layer, luts[i]);
    auto tube = vtkSmartPointer<vtkActor>::New();
    tube->SetMapper(tubeMapper);
    if (layer.field.empty()) tube->GetProperty()->SetColor(0.45, 0.45, 0.45);
    s.actors.push_back(tube);
  }
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
  // Far enough that the bounding sphere fits the 30-degree view in height and in the left
  // kModelWidth of the width; the camera then moves right so that the model stands there, clear
  // of the colour bars on the right.
  constexpr double kModelWidth = 0.62;
  const double t = std::tan(15.0 * M_PI / 180.0);
  const double fit = 1.05 * diag * std::max(0.5 / t, 1.0 / (2.0 * t * aspect * kModelWidth));
  const double shift = (0.5 - kModelWidth / 2) * 2.0 * fit * t * aspect;
  const double right[3] = {d[1] * up[2] - d[2] * up[1], d[2] * up[0] - d[0] * up[2],
                           d[0] * up[1] - d[1] * up[0]};
  const double rn = std::sqrt(right[0] * right[0] + right[1] * right[1] + right[2] * right[2]);
  double f[3];
  for (int k = 0; k < 3; ++k) f[k] = c[k] + shift * right[k] / rn;
  cam->SetFocalPoint(f);
  cam->SetPosition(f[0] - fit * d[0], f[1] - fit * d[1], f[2] - fit * d[2]);
  cam->SetViewUp(up);
  cam->SetViewAngle(30.0);
}

// One bar per coloured layer that has values, side by side at the right of the last panel.
void addColourBars(vtkRenderer* ren, const std::vector<ColourLayer>& layers,
                   const std::vector<vtkSmartPointer<vtkLookupTable>>& luts, size_t panels,
                   int fontSize) {
  std::vector<size_t> shown;
  for (size_t i = 0; i < layers.size(); ++i)
    if (!layers[i].field.empty() && layers[i].seen) shown.push_back(i);
  const double width = 0.08 * panels, step = 0.16 * panels;
  for (size_t j = 0; j < shown.size(); ++j) {
    const auto& layer = layers[shown[j]];
    vtkNew<vtkScalarBarActor> bar;
    bar->SetLookupTable(luts[shown[j]]);
    bar->SetTitle(layer.title.c_str());
    if (layer.above) {
      bar->DrawAboveRangeSwatchOn();
      bar->SetAboveRangeAnnotation(fmt::format("to {:.3g}", layer.largest).c_str());
    }
    bar->SetNumberOfLabels(5);
    bar->SetWidth(width);
    bar->SetHeight(0.6);
    // Its title is centred over it and wider than the bar: the last bar's centre at 0.86 of the
    // view leaves the title room to the right edge; others stand one step to its left.
    const double right = 0.86 - 0.04 * panels - step * (shown.size() - 1 - j);
    bar->SetPosition(right, 0.2);
    bar->GetTitleTextProperty()->SetColor(0.1, 0.1, 0.1);
    bar->GetLabelTextProperty()->SetColor(0.1, 0.1, 0.1);
    bar->UnconstrainedFontSizeOn();
    bar->GetTitleTextProperty()->SetFontSize(fontSize);
    bar->GetLabelTextProperty()->SetFontSize(fontSize * 4 / 5);
    ren->AddActor2D(bar);
  }
}

}  // namespace

std::vector<std::string> renderSnapshots(const SnapshotOptions& o) {
  if (o.view != "side" && o.view != "below" && o.view != "iso")
    throw std::runtime_error("--view must be side, below or iso (got '" + o.view + "')");
  if (o.width < 16 || o.height < 16 || o.width > 8192 || o.height > 8192)
    throw std::runtime_error("image size must be between 16 and 8192 pixels");
  std::vector<Run> runs = {openRun(o.runDir)};
  if (!o.compareDir.empty()) runs.push_back(openRun(o.compareDir));

  // Load the frames shown first: the camera is common to all images. The colour ranges are over
  // every frame of every run, shown or not (render/ColourLayers.hpp).
  std::vector<std::vector<vtkSmartPointer<vtkUnstructuredGrid>>> grids(runs.size());
  std::vector<std::vector<double>> times(runs.size());
  const auto picks = pickFrames(runs[0], o);
  std::array<double, 6> bounds = {1e300, -1e300, 1e300, -1e300, 1e300, -1e300};
  std::vector<ColourLayer> layers;
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
      if (layers.empty()) layers = colourLayers(o.color, g);
      grids[r].push_back(g);
      times[r].push_back(runs[r].frames[f].t);
    }
  }
  for (const auto& run : runs)
    for (size_t f = 0; f < run.frames.size(); ++f)
      widenRanges(layers, load(run, static_cast<int>(f)));
  finishRanges(layers);

  VirtualDisplay display;  // only now: errors above need no display
  fs::create_directories(o.outDir);
  std::vector<vtkSmartPointer<vtkLookupTable>> luts;
  for (const auto& layer : layers) {
    auto lut = vtkSmartPointer<vtkLookupTable>::New();
    lut->SetHueRange(0.667, 0.0);
    if (layer.component < 0)
      lut->SetVectorModeToMagnitude();
    else
      lut->SetVectorModeToComponent(), lut->SetVectorComponent(layer.component);
    lut->SetTableRange(layer.range[0], layer.range[1]);
    lut->SetNanColor(0.6, 0.6, 0.6, 1.0);
    lut->SetUseAboveRangeColor(layer.above);
    lut->SetAboveRangeColor(0.55, 0.0, 0.55, 1.0);  // beyond the scale's red, and unlike it
    lut->Build();
    luts.push_back(lut);
  }

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
      const Scene s = buildScene(grids[r][i], layers, luts, tube, text, fontSize);
      for (const auto& actor : s.actors) ren->AddActor(actor);
      ren->AddActor2D(s.label);
      if (r + 1 == runs.size()) addColourBars(ren, layers, luts, runs.size(), fontSize);
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
