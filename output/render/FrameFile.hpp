#pragma once
// One frame of a run's series, read for drawing: a regular file of at most kMaxFrameBytes, read
// whole without blocking (a FIFO named by the .pvd would block `chute render` for ever), its XML
// checked to have the structure of a frame chute writes (VTK's reader trusts it: an unknown data
// type or stray text crashed it), parsed by VTK from memory and then checked before anything
// draws it -- every cell a vertex, line,
// triangle or quadrangle of its number of points, every point index in range, finite points,
// every field of one value per point or cell, a "kind" for every cell (an index out of range or
// an unknown cell type crashed the renderer, and left its Xvfb running).
#include <vtkSmartPointer.h>

#include <cstdint>
#include <string>

class vtkUnstructuredGrid;

namespace chute::render {

inline constexpr std::uintmax_t kMaxFrameBytes = 256ull << 20;        // docs/limits.md
inline constexpr std::uintmax_t kMaxSeriesBytes = 64ull << 20;        // the .pvd
inline constexpr double kMaxFramePoints = 2e7, kMaxFrameCells = 4e7;  // about 1 GB of arrays

// Throws std::runtime_error "path: reason" for a file that cannot be read or a frame that fails
// the checks.
vtkSmartPointer<vtkUnstructuredGrid> readFrame(const std::string& path);

// The checks alone (on a grid read by other means).
void checkFrame(vtkUnstructuredGrid* grid, const std::string& path);

}  // namespace chute::render
