#pragma once
// How a sliding group finds the element each slider is on (solver.search).

namespace chute {

enum class SliderSearch {
  NearestLength,       // F12: every element of the group, least |l - L| (the paper's search)
  MaterialCoordinate,  // track the slider along the chain: it leaves its element only by
                       // passing one of the element's end nodes, to the neighbour there
};

}  // namespace chute
