#pragma once
// `chute render`: PNG snapshots of a run's VTU series, off-screen. Membranes are lit surfaces,
// lines are tubes, point masses are spheres; by default membranes are coloured by their stress
// and lines by their force (render/ColourLayers.hpp), with colour bars and a time stamp. The camera
// and colour range are fixed over all snapshots (and both runs of a comparison), so a sequence of
// images can be compared by eye.
#include <string>
#include <vector>

namespace chute::render {

struct SnapshotOptions {
  std::string runDir;
  std::string compareDir;        // optional second run, drawn side by side at the same times
  std::vector<double> times;     // empty: the last frame
  bool allFrames = false;        // every frame of the series
  std::string view = "iso";      // side (along +y), below (looking up +z), iso
  std::string color = "stress";  // "stress" (membrane stress, line force) or one field
  // A continuous cell field on membranes is drawn averaged at the nodes over the membrane
  // elements around each (display only: the VTU keeps the element values); true: element by
  // element.
  bool cellValues = false;
  int width = 1280, height = 720;
  std::string outDir;
};

// Renders the snapshots; returns the PNG files written. Throws std::runtime_error (missing run,
// unknown field, no display).
std::vector<std::string> renderSnapshots(const SnapshotOptions& options);

}  // namespace chute::render
