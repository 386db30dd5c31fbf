#pragma once
// A frame on disk for `chute intersections` (IntersectionFrames.hpp): read and checked as
// `chute render` reads its frames (FrameFile.hpp: a regular file of bounded size read without
// blocking, its XML checked before VTK's reader sees it, every cell's points in range), so that
// a frame VTK's reader would trust and crash on (a negative point count, big-endian or 64-bit
// headers, a component count of 2^32) is refused instead.
#include <string>

#include "IntersectionCheck.hpp"

namespace chute::render {

// Throws std::runtime_error naming the file if it cannot be read, fails the checks or holds a
// cell of another kind (polygons, volumes).
mesh::IntersectionMesh readIntersectionMesh(const std::string& vtuFile);

}  // namespace chute::render
