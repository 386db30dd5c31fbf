#include "render/ColourLayers.hpp"

#include <vtkAbstractArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
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

// splitmix64: the sample's generator (fixed seed: the same series gives the same scale).
std::uint64_t nextRandom(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

bool isNotApplicable(const ColourLayer& l, double v) {
  return std::isnan(l.notApplicable) ? std::isnan(v) : v == l.notApplicable;
}

// The name of a code of a categorical field: from the table of fields, or for parts the frame's
// part_names, or numbered.
std::string codeName(const std::string& field, double code, vtkUnstructuredGrid* g) {
  for (const auto& c : vtuField(field).categories)
    if (c.code == code) return c.name;
  if (field == "part") {
    auto* names = vtkStringArray::SafeDownCast(g->GetFieldData()->GetAbstractArray("part_names"));
    if (names && code >= 0 && code < names->GetNumberOfValues())
      return names->GetValue(static_cast<vtkIdType>(code));
  }
  char text[32];
  std::snprintf(text, sizeof text, "%s %g", field == "slider_group" ? "group" : "code", code);
  return text;
}
}  // namespace

std::vector<ColourLayer> colourLayers(const std::string& colour, vtkUnstructuredGrid* grid,
                                      const UnitSystem& units, bool cellValues) {
  const int membrane = static_cast<int>(CellKind::Membrane);
  const int mass = static_cast<int>(CellKind::PointMass);
  bool onPoints = false;
  if (colour == kDefaultColour) {
    // principal_stress holds the principal values of the second Piola-Kirchhoff stress S,
    // largest first. At fabric strains (a few percent) the Cauchy stress differs from S by about
    // the strain, well inside a colour band, and S is what the VTU carries.
    findField(grid, "principal_stress", onPoints);
    findField(grid, "axial_force", onPoints);
    const FieldInfo stress = vtuField("principal_stress"), force = vtuField("axial_force");
    ColourLayer fabric =
        layer(membrane, membrane, "principal_stress", 0,
              withUnit(stress.title + " " + stress.components[0], stress.quantity, units), 99.0);
    fabric.atNodes = !cellValues && !onPoints;
    if (fabric.atNodes) fabric.title += ", nodal mean";
    return {fabric,
            layer(static_cast<int>(CellKind::Cable), static_cast<int>(CellKind::SlidingActivePart),
                  "axial_force", 0, withUnit(force.title, force.quantity, units), 99.0),
            layer(mass, mass, "", -1, "", 100.0)};
  }
  const int components = findField(grid, colour, onPoints)->GetNumberOfComponents();
  const FieldInfo info = vtuField(colour);
  if (info.quantity == Quantity::Category && components == 1) {
    ColourLayer l = layer(1, mass, colour, 0, info.title, 100.0);
    l.categorical = true;
    l.notApplicable = info.notApplicable;
    return {l};
  }
  // A field with named components by its first (the largest principal value), a vector by its
  // magnitude.
  if (components > 1 && !info.components.empty())
    return {layer(1, mass, colour, 0,
                  withUnit(info.title + " " + info.components[0], info.quantity, units), 100.0)};
  const std::string title = components > 1 ? "|" + info.title + "|" : info.title;
  return {layer(1, mass, colour, -1, withUnit(title, info.quantity, units), 100.0)};
}

void sampleValue(ColourLayer& l, double v) {
  ++l.counted;
  if (l.values.size() < kSampleSize) {
    l.values.push_back(static_cast<float>(v));
    return;
  }
  const std::uint64_t k = nextRandom(l.random) % l.counted;
  if (k < kSampleSize) l.values[k] = static_cast<float>(v);
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
      if (layer.categorical) {
        if (isNotApplicable(layer, v)) {
          layer.notApplicableSeen = true;
          return;
        }
        if (!std::isfinite(v)) return;
        const bool listed = std::any_of(layer.categories.begin(), layer.categories.end(),
                                        [v](const Category& c) { return c.code == v; });
        if (!listed && layer.categories.size() <= kMaxCategories)
          layer.categories.push_back({v, codeName(layer.field, v, grid)});
      }
      if (!std::isfinite(v)) return;
      lo = std::min(lo, v), hi = std::max(hi, v);
      if (keep) sampleValue(layer, v);
    };
    if (layer.atNodes && !onPoints && kind) {
      // The values drawn: each node's mean over the layer's cells around it (as
      // vtkCellDataToPointData makes them for the picture).
      std::vector<double> sum(static_cast<size_t>(grid->GetNumberOfPoints()), 0.0);
      std::vector<int> count(sum.size(), 0);
      vtkNew<vtkIdList> ids;
      for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
        const double k = kind->GetComponent(c, 0);
        if (!(k >= layer.kindLo && k <= layer.kindHi)) continue;
        const double v = valueOf(a, c, layer.component);
        grid->GetCellPoints(c, ids);
        for (vtkIdType j = 0; j < ids->GetNumberOfIds(); ++j)
          sum[ids->GetId(j)] += v, ++count[ids->GetId(j)];
      }
      for (size_t i = 0; i < sum.size(); ++i) {
        if (count[i] == 0) continue;
        const double v = sum[i] / count[i];
        if (!std::isfinite(v)) continue;
        lo = std::min(lo, v), hi = std::max(hi, v);
        if (keep) sampleValue(layer, v);
      }
    } else if (onPoints || !kind) {
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
    if (layer.categorical) {
      if (layer.categories.size() <= kMaxCategories) {
        // The categories that occur, in code order: the legend names what is drawn.
        std::sort(layer.categories.begin(), layer.categories.end(),
                  [](const Category& a, const Category& b) { return a.code < b.code; });
        continue;
      }
      layer.categorical = false;  // too many to name: a scale over the codes
      layer.categories.clear();
    }
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
