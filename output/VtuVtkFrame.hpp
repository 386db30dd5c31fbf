#pragma once
// A frame's .vtu text through VTK's XML writer (appended, raw binary, optionally LZ4-compressed):
// the writer VtuSeries uses for large frames, and the reference the direct writer of small
// frames (VtuRawFrame) is tested against.
#include <string>

#include "SceneFrame.hpp"

namespace chute {

enum class VtkCompression { None, LZ4 };

std::string vtuVtkText(const SceneFrame& frame, VtkCompression compression);

}  // namespace chute
