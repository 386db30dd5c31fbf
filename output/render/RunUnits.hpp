#pragma once
// The unit system of a run: the `units` note its summary.json copies from the case
// (docs/output.md), read without blocking (a FIFO or /dev/zero named summary.json would block or
// never end). A run stopped early may have no summary: no units then.
#include <string>

#include "render/Quantities.hpp"

namespace chute::render {

UnitSystem runUnits(const std::string& runDir);

}  // namespace chute::render
