#pragma once
// What colours a snapshot. By default ("stress") each kind of cell is coloured by the quantity an
// engineer reads off it: membranes by their largest principal stress, lines by their axial force
// (two colour bars, since the two are different quantities); point masses are grey. Any other
// request names one point or cell field that colours everything: a vector by its magnitude, a
// field with named components (principal_stress: S1, S2) by its first, a categorical field
// (wrinkling_state, kind, part, ...) by categorical colours with a legend of its categories, the
// cells it does not apply to (lines in wrinkling_state) in a neutral grey labelled "n/a". Titles
// carry the quantity's unit from the case's `units` (render/Quantities.hpp).
//
// Each continuous layer's range is taken over every frame of the series (and of both runs of a
// comparison), so one colour means one value in every image. Stress and force scales end at the
// 99th percentile of their values over the series -- of all of them, or of a uniform sample of
// kSampleSize when there are more (bounded memory): a fabric's largest stresses sit in a few
// elements (a fold, a grommet) and would leave the rest of the canopy in the lowest colour; the
// few values above the scale get a colour of their own, and the bar says up to what value.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "render/Quantities.hpp"

class vtkUnstructuredGrid;

namespace chute::render {

inline constexpr const char* kDefaultColour = "stress";
inline constexpr std::size_t kSampleSize = std::size_t{1} << 20;  // values kept for a percentile
inline constexpr std::size_t kMaxCategories = 64;  // more distinct codes: drawn as a scale

struct ColourLayer {
  int kindLo = 1, kindHi = 6;  // cells whose "kind" (CellKind) is in [kindLo, kindHi]
  std::string field;           // empty: drawn grey
  int component = -1;          // -1: the magnitude
  std::string title;           // the colour bar's title, with the unit
  double percentile = 100.0;   // the scale's top: this percentile of the values (100: the largest)
  std::array<double, 2> range = {0.0, 1.0};
  bool seen = false;          // some frame has cells of this layer with a finite value
  bool above = false;         // values beyond the top of the scale (after finishRanges)
  std::vector<float> values;  // a uniform sample of the values seen, kept while percentile < 100
  std::uint64_t counted = 0;  // values seen (the sample holds min(counted, kSampleSize))
  std::uint64_t random = 0x9e3779b97f4a7c15ull;  // state of the sample's generator (fixed seed)
  double largest = 0.0;                          // the largest value seen
  // Categorical fields: the categories that occur (codes and names, in code order), and whether
  // cells the field does not apply to occur.
  bool categorical = false;
  double notApplicable = -1.0;  // the code of those cells (or NaN)
  std::vector<Category> categories;
  bool notApplicableSeen = false;
  // A membrane layer's cell field shown averaged at the nodes over the membrane elements around
  // each (display only: an element field is a checkerboard that hides its trend); its range and
  // percentile are those of the averages, the values drawn.
  bool atNodes = false;
};

// The layers for `colour` ("stress" or a field name), titled in the units `units`. Throws
// std::runtime_error for a field the grid does not carry (naming the fields it does).
// cellValues: membrane fields element by element (no layer atNodes).
std::vector<ColourLayer> colourLayers(const std::string& colour, vtkUnstructuredGrid* grid,
                                      const UnitSystem& units = {}, bool cellValues = false);

// Widens each layer's range to the finite values of its field on its cells in `grid` (a frame);
// a categorical layer collects the codes that occur.
void widenRanges(std::vector<ColourLayer>& layers, vtkUnstructuredGrid* grid);

// Adds one value to a layer's sample (Algorithm R: every value seen so far is in the sample with
// the same probability; a fixed seed, so one series always gives one scale).
void sampleValue(ColourLayer& layer, double value);

// After all frames are seen: the range of every layer (stress and force start at zero, and end
// at their percentile), and whether values lie above it; a categorical layer with more than
// kMaxCategories codes becomes a scale.
void finishRanges(std::vector<ColourLayer>& layers);

}  // namespace chute::render
