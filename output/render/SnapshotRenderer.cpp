#include "render/SnapshotRenderer.hpp"

#include <fmt/core.h>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkCellDataToPointData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkGeometryFilter.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
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
#include <vtkVariant.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "SceneFrame.hpp"
#include "VtuSeries.hpp"
#include "render/ColourLayers.hpp"
#include "render/FrameFile.hpp"
#include "render/ImageOutput.hpp"
#include "render/RunUnits.hpp"
#include "render/VirtualDisplay.hpp"

namespace chute::render {

namespace fs = std::filesystem;

namespace {

struct Run {
  std::string dir, name;
  std::vector<PvdEntry> frames;
  UnitSystem units;
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
  r.units = runUnits(dir);
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
  return readFrame((fs::path(r.dir) / r.frames[frame].file).string());
}

// "t = 1.20 s": as many decimals as tell the series' frames apart.
std::string timeStamp(double t, const Run& r) {
  double spacing = 0.0;
  for (size_t i = 1; i < r.frames.size(); ++i) {
    const double d = std::abs(r.frames[i].t - r.frames[i - 1].t);
    if (d > 0.0 && (spacing == 0.0 || d < spacing)) spacing = d;
  }
  const int decimals =
      spacing > 0.0 ? std::clamp(static_cast<int>(std::ceil(-std::log10(spacing) - 1e-9)), 0, 9)
                    : 3;
  return fmt::format("t = {:.{}f} {}", t, decimals, r.units.time);
}

// A colour bar's numbers: 3 significant digits, no trailing zeros, no "+" in exponents.
std::string number(double v) {
  if (v == 0.0) return "0";
  std::string s = fmt::format("{:.3g}", v);
  if (const auto e = s.find("e+"); e != std::string::npos) s.erase(e + 1, 1);
  if (const auto e = s.find("e-0"); e != std::string::npos) s.erase(e + 2, 1);
  if (const auto e = s.find("e0"); e != std::string::npos) s.erase(e + 1, 1);
  return s;
}

// Four or five round numbers across [lo, hi] (1, 2 or 5 times a power of ten apart).
std::vector<double> roundTicks(double lo, double hi) {
  const double span = hi - lo;
  if (!(span > 0.0) || !std::isfinite(span)) return {lo, hi};
  const double raw = span / 4.0, p = std::pow(10.0, std::floor(std::log10(raw)));
  double step = p;
  for (const double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * p >= raw) {
      step = m * p;
      break;
    }
  std::vector<double> ticks;
  for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * span; v += step)
    ticks.push_back(std::abs(v) < 1e-12 * span ? 0.0 : v);
  return ticks;
}

// One actor per layer and per drawing style: membranes as lit surfaces, lines as tubes, point
// masses as spheres. Each layer takes its cells by their "kind" and its own lookup table.
struct Scene {
  std::vector<vtkSmartPointer<vtkActor>> actors;
  vtkSmartPointer<vtkTextActor> label;
};

void colourBy(vtkPolyDataMapper* m, vtkUnstructuredGrid* grid, const ColourLayer& layer,
              vtkLookupTable* lut, bool averagedAtNodes = false) {
  if (layer.field.empty()) {
    m->ScalarVisibilityOff();
    return;
  }
  if (averagedAtNodes || grid->GetPointData()->GetArray(layer.field.c_str()))
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
    // A membrane layer's element field (constant per element: a checkerboard that hides the
    // field's trend) is shown averaged at each node over the membrane elements around it,
    // weighted equally (ColourLayer::atNodes). Only the layer's cells are in `cells`, so no
    // line's value enters.
    const bool average = layer.atNodes && grid->GetCellData()->GetArray(layer.field.c_str());
    vtkNew<vtkCellDataToPointData> atNodes;
    vtkNew<vtkGeometryFilter> geometry;
    if (average) {
      atNodes->SetInputConnection(cells->GetOutputPort());
      atNodes->ProcessAllArraysOff();
      atNodes->AddCellDataArray(layer.field.c_str());
      atNodes->PassCellDataOff();
      geometry->SetInputConnection(atNodes->GetOutputPort());
    } else {
      geometry->SetInputConnection(cells->GetOutputPort());
    }

    vtkNew<vtkPolyDataMapper> surfaceMapper;
    surfaceMapper->SetInputConnection(geometry->GetOutputPort());
    colourBy(surfaceMapper, grid, layer, luts[i], average);
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
    colourBy(tubeMapper, grid, layer, luts[i], average);
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

// The colour bars of the layers that have values, stacked in a column at the right of the last
// panel, where the camera leaves room (placeCamera): each with its title and unit above it, a
// categorical one as swatches named by category, and a scale whose top is below the largest
// value saying up to what value its purple swatch goes, on a line of its own under the title.
void addColourBars(vtkRenderer* ren, const std::vector<ColourLayer>& layers,
                   const std::vector<vtkSmartPointer<vtkLookupTable>>& luts, int fontSize,
                   int widthPixels, int heightPixels) {
  std::vector<size_t> shown;
  for (size_t i = 0; i < layers.size(); ++i) {
    const auto& l = layers[i];
    if (!l.field.empty() && (l.categorical ? !l.categories.empty() || l.notApplicableSeen : l.seen))
      shown.push_back(i);
  }
  if (shown.empty()) return;
  constexpr double left = 0.66, top = 0.95, bottom = 0.06;
  const double slot = (top - bottom) / static_cast<double>(shown.size());
  auto text = [&](const std::string& s, double x, double y, int size, bool bold) {
    vtkNew<vtkTextActor> t;
    t->SetInput(s.c_str());
    t->GetTextProperty()->SetFontSize(size);
    t->GetTextProperty()->SetBold(bold);
    t->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
    t->GetTextProperty()->SetVerticalJustificationToTop();
    t->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    t->SetPosition(x, y);
    ren->AddActor2D(t);
  };
  const int noteSize = std::max(10, fontSize * 3 / 4);
  for (size_t j = 0; j < shown.size(); ++j) {
    const auto& layer = layers[shown[j]];
    const double y0 = top - slot * static_cast<double>(j);  // the slot's top
    text(layer.title, left, y0, fontSize, true);
    double titleLines = 1.6;
    if (layer.above) {
      text("purple: above the scale, up to " + number(layer.largest), left,
           y0 - 1.25 * fontSize / double(heightPixels), noteSize, false);
      titleLines = 2.7;
    }
    const double titleHeight = titleLines * fontSize / double(heightPixels);
    vtkNew<vtkScalarBarActor> bar;
    bar->SetLookupTable(luts[shown[j]]);
    bar->SetTitle("");
    bar->SetOrientationToVertical();
    bar->SetTextPositionToSucceedScalarBar();
    bar->UnconstrainedFontSizeOn();
    bar->GetLabelTextProperty()->SetFontSize(noteSize);
    bar->GetLabelTextProperty()->SetColor(0.1, 0.1, 0.1);
    bar->GetLabelTextProperty()->SetBold(false);
    bar->GetLabelTextProperty()->SetItalic(false);
    bar->GetLabelTextProperty()->SetShadow(false);
    bar->GetAnnotationTextProperty()->ShallowCopy(bar->GetLabelTextProperty());
    double shift = 0.0;  // of the bar to the right: a categorical legend's names stand left of it
    if (layer.categorical) {
      size_t longest = 3;  // "n/a"
      for (const auto& c : layer.categories) longest = std::max(longest, c.name.size());
      shift = (0.6 * noteSize * static_cast<double>(longest) + 12.0) / double(widthPixels);
      bar->DrawAnnotationsOn();
      bar->SetNumberOfLabels(0);
      bar->DrawNanAnnotationOff();
      bar->SetDrawAboveRangeSwatch(false);
    } else {
      bar->DrawAnnotationsOff();
      const auto ticks = roundTicks(layer.range[0], layer.range[1]);
      vtkNew<vtkDoubleArray> labels;
      for (const double t : ticks) labels->InsertNextValue(t);
      bar->SetUseCustomLabels(true);
      bar->SetCustomLabels(labels);
      bar->SetLabelFormat("%g");
      if (layer.above) bar->DrawAboveRangeSwatchOn();
    }
    // A categorical legend: a swatch of about 6 % of the height per category.
    const double swatches =
        static_cast<double>(layer.categories.size() + (layer.notApplicableSeen ? 1 : 0));
    const double height = layer.categorical ? std::min(slot - titleHeight - 0.03, 0.065 * swatches)
                                            : slot - titleHeight - 0.03;
    bar->SetPosition(left + shift, y0 - titleHeight - height);
    bar->SetWidth(0.3);
    bar->SetHeight(height);
    bar->SetBarRatio(layer.categorical ? 0.12 : 0.15);
    ren->AddActor2D(bar);
  }
}

// The lookup table of a layer: a blue-to-red scale over its range (purple above it, grey for
// NaN), or for a categorical layer one colour per category that occurs and grey for "n/a".
vtkSmartPointer<vtkLookupTable> lookupTable(const ColourLayer& layer) {
  auto lut = vtkSmartPointer<vtkLookupTable>::New();
  lut->SetNanColor(0.6, 0.6, 0.6, 1.0);
  if (layer.categorical) {
    // A qualitative palette (distinct hues of similar weight), repeated beyond ten categories.
    static constexpr double kPalette[10][3] = {
        {0.12, 0.47, 0.71}, {1.00, 0.50, 0.05}, {0.17, 0.63, 0.17}, {0.84, 0.15, 0.16},
        {0.58, 0.40, 0.74}, {0.55, 0.34, 0.29}, {0.89, 0.47, 0.76}, {0.74, 0.74, 0.13},
        {0.09, 0.75, 0.81}, {0.50, 0.50, 0.50}};
    lut->IndexedLookupOn();
    const bool na = layer.notApplicableSeen;
    lut->SetNumberOfTableValues(static_cast<vtkIdType>(layer.categories.size() + (na ? 1 : 0)));
    vtkIdType k = 0;
    for (size_t c = 0; c < layer.categories.size(); ++c, ++k) {
      const auto& rgb = kPalette[c % 10];
      lut->SetTableValue(k, rgb[0], rgb[1], rgb[2], 1.0);
      lut->SetAnnotation(vtkVariant(layer.categories[c].code), layer.categories[c].name);
    }
    if (na) {  // cells the field does not apply to (lines in wrinkling_state)
      lut->SetTableValue(k, 0.78, 0.78, 0.78, 1.0);
      if (std::isnan(layer.notApplicable))
        lut->SetAnnotation(vtkVariant(std::nan("")), "n/a");
      else
        lut->SetAnnotation(vtkVariant(layer.notApplicable), "n/a");
      lut->SetNanColor(0.78, 0.78, 0.78, 1.0);
    }
    return lut;
  }
  lut->SetHueRange(0.667, 0.0);
  if (layer.component < 0)
    lut->SetVectorModeToMagnitude();
  else
    lut->SetVectorModeToComponent(), lut->SetVectorComponent(layer.component);
  lut->SetTableRange(layer.range[0], layer.range[1]);
  lut->SetUseAboveRangeColor(layer.above);
  lut->SetAboveRangeColor(0.55, 0.0, 0.55, 1.0);  // beyond the scale's red, and unlike it
  lut->Build();
  return lut;
}

}  // namespace

std::vector<std::string> renderSnapshots(const SnapshotOptions& o) {
  if (o.view != "side" && o.view != "below" && o.view != "iso")
    throw std::runtime_error("--view must be side, below or iso (got '" + o.view + "')");
  if (const auto bad = imageSizeProblem(o.width, o.height)) throw std::runtime_error(*bad);
  std::vector<Run> runs = {openRun(o.runDir)};
  if (!o.compareDir.empty()) runs.push_back(openRun(o.compareDir));
  if (runs.size() > 1 && runs[0].units.note != runs[1].units.note)
    throw std::runtime_error("--compare: the runs are in different units ('" + runs[0].units.note +
                             "' and '" + runs[1].units.note +
                             "'): one colour would mean two values");

  // The frames shown (for a compared run, the frames nearest to the first run's times); the
  // camera is common to all images, over their bounds. The colour ranges are over every frame of
  // every run, shown or not (render/ColourLayers.hpp). One pass over the frames, one frame in
  // memory at a time; each shown frame is read again when it is drawn (`--all` over a long series
  // of a large model held every frame).
  const auto picks = pickFrames(runs[0], o);
  std::vector<std::vector<int>> shown(runs.size());
  std::vector<std::vector<double>> times(runs.size());
  for (size_t r = 0; r < runs.size(); ++r)
    for (int p : picks) {
      int f = p;
      if (r > 0) {
        SnapshotOptions one = o;
        one.allFrames = false;
        one.times = {runs[0].frames[p].t};
        f = pickFrames(runs[r], one)[0];
      }
      shown[r].push_back(f);
      times[r].push_back(runs[r].frames[f].t);
    }
  std::array<double, 6> bounds = {1e300, -1e300, 1e300, -1e300, 1e300, -1e300};
  std::vector<ColourLayer> layers;
  for (size_t r = 0; r < runs.size(); ++r)
    for (size_t f = 0; f < runs[r].frames.size(); ++f) {
      const auto g = load(runs[r], static_cast<int>(f));
      if (layers.empty()) layers = colourLayers(o.color, g, runs[0].units, o.cellValues);
      widenRanges(layers, g);
      if (std::find(shown[r].begin(), shown[r].end(), static_cast<int>(f)) == shown[r].end())
        continue;
      double b[6];
      g->GetBounds(b);
      for (int k = 0; k < 3; ++k)
        bounds[2 * k] = std::min(bounds[2 * k], b[2 * k]),
                   bounds[2 * k + 1] = std::max(bounds[2 * k + 1], b[2 * k + 1]);
    }
  finishRanges(layers);

  // Every image's file, checked before anything is drawn.
  std::vector<std::string> files;
  for (size_t i = 0; i < picks.size(); ++i) {
    // <case>[_compare]_<view>[_<field>]_t<time>.png: a field other than the default colouring
    // is in the name, so that pictures of one frame in two colourings do not overwrite each other.
    const std::string field = o.color == kDefaultColour ? "" : "_" + o.color;
    files.push_back((fs::path(o.outDir) / fmt::format("{}{}_{}{}_t{:.6f}.png", runs[0].name,
                                                      runs.size() > 1 ? "_compare" : "", o.view,
                                                      field, times[0][i]))
                        .string());
    if (const std::string bad = imageFileProblem(files.back());
        !bad.empty() && fs::exists(fs::symlink_status(o.outDir)))
      throw std::runtime_error(bad);
  }

  VirtualDisplay display;  // only now: errors above need no display
  fs::create_directories(o.outDir);
  std::vector<vtkSmartPointer<vtkLookupTable>> luts;
  for (const auto& layer : layers) luts.push_back(lookupTable(layer));

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
    window->SetMultiSamples(multiSamplesFor(o.width, o.height));
    window->SetSize(o.width, o.height);
    vtkSmartPointer<vtkCamera> camera = vtkSmartPointer<vtkCamera>::New();
    placeCamera(camera, bounds, o.view, panelAspect);
    for (size_t r = 0; r < runs.size(); ++r) {
      vtkNew<vtkRenderer> ren;
      ren->SetViewport(double(r) / runs.size(), 0.0, double(r + 1) / runs.size(), 1.0);
      ren->SetBackground(1.0, 1.0, 1.0);
      ren->SetActiveCamera(camera);
      const std::string text = fmt::format(
          "{}   {}",
          runs[r].name +
              (runs.size() > 1 ? " (" + fs::path(runs[r].dir).filename().string() + ")" : ""),
          timeStamp(times[r][i], runs[r]));
      const auto grid = load(runs[r], shown[r][i]);
      const Scene s = buildScene(grid, layers, luts, tube, text, fontSize);
      for (const auto& actor : s.actors) ren->AddActor(actor);
      ren->AddActor2D(s.label);
      if (r + 1 == runs.size())
        addColourBars(ren, layers, luts, fontSize, o.width / static_cast<int>(runs.size()),
                      o.height);
      ren->ResetCameraClippingRange();
      window->AddRenderer(ren);
    }
    window->Render();
    writeWindowPng(window, files[i]);
    written.push_back(files[i]);
  }
  return written;
}

}  // namespace chute::render
