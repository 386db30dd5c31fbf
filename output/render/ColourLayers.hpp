#pragma once
// What colours a snapshot. By default ("stress") each kind of cell is coloured by the quantity an
// engineer reads off it: membranes by their largest principal stress, lines by their axial force
// (two colour bars, since the two are different quantities); point masses are grey. Any other
// request names one point or cell field that colours everything (vectors by magnitude). Each
// layer's colour range is taken over every frame of the series (and of both runs of a
// comparison), so one colour means one value in every image. Stress and force scales end at the
// 99th percentile of their values over the series: a fabric's largest stresses sit in a few
// elements (a fold, a grommet) and would leave the rest of the canopy in the lowest colour; the
// few values above the scale get a colour of their own, shown as a swatch on the bar.
#include <array>
#include <string>
#include <vector>

class vtkUnstructuredGrid;

namespace chute::render {

inline constexpr const char* kDefaultColour = "stress";

struct ColourLayer {
  int kindLo = 1, kindHi = 6;  // cells whose "kind" (CellKind) is in [kindLo, kindHi]
  std::string field;           // empty: drawn grey
  int component = -1;          // -1: the magnitude
  std::string title;           // the colour bar's title
  double percentile = 100.0;   // the scale's top: this percentile of the values (100: the largest)
  std::array<double, 2> range = {0.0, 1.0};
  bool seen = false;          // some frame has cells of this layer with a finite value
  bool above = false;         // values beyond the top of the scale (after finishRanges)
  std::vector<float> values;  // the values seen, kept while percentile < 100
  double largest = 0.0;       // the largest value seen
};

// The layers for `colour` ("stress" or a field name). Throws std::runtime_error for a field the
// grid does not carry (naming the fields it does).
std::vector<ColourLayer> colourLayers(const std::string& colour, vtkUnstructuredGrid* grid);

// Widens each layer's range to the finite values of its field on its cells in `grid` (a frame).
void widenRanges(std::vector<ColourLayer>& layers, vtkUnstructuredGrid* grid);

// After all frames are seen: the range of every layer (stress and force start at zero, and end
// at their percentile), and whether values lie above it.
void finishRanges(std::vector<ColourLayer>& layers);

}  // namespace chute::render
