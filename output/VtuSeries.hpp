#pragma once
// The VTU time series of a run (docs/output.md): one `<case>_NNNNNN.vtu` per output time (binary,
// appended; frames above 64 KiB of arrays LZ4-compressed through VTK's XML writer, smaller ones
// raw, written by VtuRawFrame) and a `<case>.pvd` collection with the physical times. The
// collection is valid at every moment: each new entry and the closing tags go to the file in one
// write at the end of the previous entry, so a run killed half-way still opens in ParaView with
// every frame written so far.
#include <condition_variable>
#include <deque>
#include <exception>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
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

enum class Writing { InCaller, Background };

class VtuSeries {
 public:
  // Starts a series `<dir>/<name>.pvd`; an existing collection of that name is replaced.
  VtuSeries(std::string dir, std::string name, Writing writing = Writing::InCaller);
  // Continues the series of a restarted run: its first keepFrames frames (those written up to
  // the checkpoint) are kept, the others dropped (collection entries and files). Throws if the
  // collection has fewer (not the output of this run).
  VtuSeries(std::string dir, std::string name, int keepFrames, Writing writing = Writing::InCaller);
  ~VtuSeries();  // writes what is queued
  VtuSeries(const VtuSeries&) = delete;
  VtuSeries& operator=(const VtuSeries&) = delete;

  // Queues a frame (written in the caller or in the background). A failed write (a full disk,
  // the directory removed) is an OutputError, thrown here or by a later write() or flush():
  // the frame's file is removed and the collection lists the frames written whole before it.
  void write(SceneFrame frame);
  void flush();        // every frame given so far is in its file and in the .pvd
  int frames() const;  // frames given so far
  // Frames the .pvd lists (each file whole), and the time of the last one (NaN: none).
  int listedFrames() const;
  double lastListedTime() const;
  // Drops the frames after the first `frames` (their files and entries): the output of a run
  // that stopped as unstable ends at its last good state.
  void cutBackTo(int frames);
  // Seconds the background thread spent writing (0 when writing in the caller).
  double backgroundSeconds() const;
  std::string pvdPath() const { return dir_ + "/" + name_ + ".pvd"; }

 private:
  void start(const std::vector<PvdEntry>& kept);
  bool isFrameFile(const std::string& file) const;  // <name>_NNNNNN.vtu
  // Writes a frame's file and adds its entry to those not yet in the .pvd.
  void addPending(const SceneFrame& f, int index);
  void appendPending();  // the entries of files written, into the .pvd
  bool queueLooksEmpty() const;
  void startThread();
  void writerLoop();
  void rethrowWriterError();
  std::string dir_, name_;
  Writing writing_;
  int fd_ = -1;
  long footerAt_ = 0;           // offset of the closing tags in the .pvd
  std::string pendingEntries_;  // of files written, not yet in the .pvd (writer's own)
  std::vector<std::string> pendingFiles_;
  double pendingLastTime_ = 0.0;
  int pendingCount_ = 0;
  int frames_ = 0;  // given to write()
  int listed_ = 0;  // in the .pvd (under mutex_)
  double lastListedTime_ = std::numeric_limits<double>::quiet_NaN();

  // Background writing: frames queued in order; the writer takes them one at a time.
  mutable std::mutex mutex_;
  std::condition_variable queued_, drained_;
  std::deque<std::pair<SceneFrame, int>> queue_;
  size_t queuedBytes_ = 0;
  bool busy_ = false, stopping_ = false, flushWanted_ = false;
  std::exception_ptr writerError_;  // to be thrown to the caller (once)
  bool failed_ = false;             // a write failed: later frames are dropped
  double backgroundSeconds_ = 0.0;
  std::thread thread_;
};

}  // namespace chute
