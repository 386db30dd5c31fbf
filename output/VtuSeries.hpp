#pragma once
// The VTU time series of a run (interfaces.md): one `<case>_NNNNNN.vtu` per output time through
// VTK's XML writer (binary, appended, zlib-compressed) and a `<case>.pvd` collection with the
// physical times. The collection is valid at every moment: each new entry and the closing tags
// go to the file in one write at the end of the previous entry, so a run killed half-way still
// opens in ParaView with every frame written so far.
#include <memory>
#include <string>
#include <vector>

#include "SceneFrame.hpp"

namespace chute {

// One frame of a .pvd collection: its time and file (relative to the .pvd).
struct PvdEntry {
  double t = 0.0;
  std::string file;
};
// Reads a .pvd collection, frames in order.
std::vector<PvdEntry> readPvd(const std::string& path);

class VtuSeries {
 public:
  // Starts a series `<dir>/<name>.pvd`; an existing collection of that name is replaced.
  VtuSeries(std::string dir, std::string name);
  // Continues the series of a restarted run: frames after resumeAfter are dropped (collection
  // entries and files), so no output time appears twice.
  VtuSeries(std::string dir, std::string name, double resumeAfter);
  ~VtuSeries();
  VtuSeries(const VtuSeries&) = delete;
  VtuSeries& operator=(const VtuSeries&) = delete;

  void write(const SceneFrame& frame);
  int frames() const { return frames_; }
  std::string pvdPath() const { return dir_ + "/" + name_ + ".pvd"; }

 private:
  void start(const std::vector<PvdEntry>& kept);
  void appendEntry(double t, const std::string& file);
  std::string dir_, name_;
  int fd_ = -1;
  long footerAt_ = 0;  // offset of the closing tags in the .pvd
  int frames_ = 0;
  struct Vtk;
  std::unique_ptr<Vtk> vtk_;  // writer objects kept across frames
};

}  // namespace chute
