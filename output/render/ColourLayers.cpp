#include "render/ColourLayers.hpp"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "SceneFrame.hpp"

namespace chute::render {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

vtkDataArray* findField(vtkUnstructuredGrid* g, const std::string& name, bool& onPoints) {
  if (auto* a = g->GetPointData()->GetArray(name.c_str())) return onPoints = true, a;
  if (auto* a = g->GetCellData()->GetArray(name.c_str())) return onPoints = false, a;
  std::string known;
  for (int i = 0; i < g->GetPointData()->GetNumberOfArrays(); ++i)
    known += std::string(known.empty() ? "" : ", ") + g->GetPointData()->GetArrayName(i);
  for (int i = 0; i < g->GetCellData()->GetNumberOfArrays(); ++i)
    known += std::string(known.empty() ? "" : ", ") + g->GetCellData()->GetArrayName(i);
  throw std::runtime_error("no field '" + name + "' in the run (fields: " + known + ")");
}

ColourLayer layer(int kindLo, int kindHi, std::string field, int component, std::string title,
                  double percentile) {
  ColourLayer l;
  l.kindLo = kindLo, l.kindHi = kindHi, l.component = component, l.percentile = percentile;
  l.field = std::move(field), l.title = std::move(title);
  return l;
}

double valueOf(vtkDataArray* a, vtkIdType i, int component) {
  if (component >= 0) return a->GetComponent(i, component);
  double s = 0.0;
  for (int c = 0; c < a->GetNumberOfComponents(); ++c)
    s += a->GetComponent(i, c) * a->GetComponent(i, c);
  return std::sqrt(s);
}
}  // namespace

std::vector<ColourLayer> colourLayers(const std::string& colour, vtkUnstructuredGrid* grid) {
  const int membrane = static_cast<int>(CellKind::Membrane);
  const int mass = static_cast<int>(CellKind::PointMass);
  bool onPoints = false;
  if (colour == kDefaultColour) {
    // principal_stress holds the principal values of the second Piola-Kirchhoff stress S,
    // largest first. At fabric strains (a few percent) the Cauchy stress differs from S by about
    // the strain, well inside a colour band, and S is what the VTU carries.
    findField(grid, "principal_stress", onPoints);
    findField(grid, "axial_force", onPoints);
    return {layer(membrane, membrane, "principal_stress", 0, "membrane stress S1", 99.0),
            layer(static_cast<int>(CellKind::Cable), static_cast<int>(CellKind::SlidingActivePart),
                  "axial_force", 0, "line force", 99.0),
            layer(mass, mass, "", -1, "", 100.0)};
  }
  const bool vector = findField(grid, colour, onPoints)->GetNumberOfComponents() > 1;
  return {layer(1, mass, colour, -1, vector ? "|" + colour + "|" : colour, 100.0)};
}

void widenRanges(std::vector<ColourLayer>& layers, vtkUnstructuredGrid* grid) {
  auto* kind = grid->GetCellData()->GetArray("kind");
  for (auto& layer : layers) {
    if (layer.field.empty()) continue;
    bool onPoints = false;
    vtkDataArray* a = findField(grid, layer.field, onPoints);
    double lo = kInf, hi = -kInf;
    const bool keep = layer.percentile < 100.0;
    auto take = [&](vtkIdType i) {
      const double v = valueOf(a, i, layer.component);
      if (!std::isfinite(v)) return;
      lo = std::min(lo, v), hi = std::max(hi, v);
      if (keep) layer.values.push_back(static_cast<float>(v));
    };
    if (onPoints || !kind) {
      for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i) take(i);
    } else {
      for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
        const double k = kind->GetComponent(c, 0);
        if (k >= layer.kindLo && k <= layer.kindHi) take(c);
      }
    }
    if (lo > hi) continue;  // no finite value of this layer in this frame
    layer.range = layer.seen ? std::array<double, 2>{std::min(layer.range[0], lo),
                                                     std::max(layer.range[1], hi)}
                             : std::array<double, 2>{lo, hi};
    layer.seen = true;
  }
}

void finishRanges(std::vector<ColourLayer>& layers) {
  for (auto& layer : layers) {
    if (!layer.seen) continue;
    layer.largest = layer.range[1];
    if (layer.percentile < 100.0 && !layer.values.empty()) {
      auto& v = layer.values;
      const size_t k = std::min(
          v.size() - 1, static_cast<size_t>(std::floor(layer.percentile / 100.0 * v.size())));
      std::nth_element(v.begin(), v.begin() + static_cast<long>(k), v.end());
      const double top = v[k];
      // Mostly unloaded (the percentile at the bottom of the range): the largest value instead.
      if (top > layer.range[0]) layer.range[1] = std::min(layer.range[1], top);
      layer.above = layer.largest > layer.range[1];
      v.clear();
      v.shrink_to_fit();
    }
    // Tension-only fabric and lines: the scale starts at zero, so blue means unloaded.
    if (layer.field == "principal_stress" || layer.field == "axial_force")
      layer.range[0] = std::min(0.0, layer.range[0]);
    if (layer.range[1] - layer.range[0] < 1e-300) layer.range[1] = layer.range[0] + 1.0;
  }
}

}  // namespace chute::render
