#pragma once
// A small frame's .vtu text written directly: the same UnstructuredGrid file VTK's XML writer makes
// in appended raw mode (UInt32 block headers, little endian), without building a vtkDataSet.
// Why: on a scene of a few nodes a step costs ~20 us and VTK's writer ~1.2 M instructions a
// frame (issue 5: output at every step of the pulley must cost little against the run). Frames
// above VtuSeries' compression threshold still go through VTK's writer with LZ4.
// Range attributes are left out (optional in the format; readers compute them).
#include <string>

#include "SceneFrame.hpp"

namespace chute {

// The whole file. Throws std::length_error if an array exceeds the 4 GiB a UInt32 header allows.
std::string vtuRawText(const SceneFrame& frame);

}  // namespace chute
