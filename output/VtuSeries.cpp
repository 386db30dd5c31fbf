#include "VtuSeries.hpp"

#include <fcntl.h>
#include <fmt/core.h>
#include <unistd.h>
#include <vtkNew.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "VtuRawFrame.hpp"
#include "VtuVtkFrame.hpp"
#include "io/InputFile.hpp"

namespace chute {

namespace {
constexpr const char* kHeader =
    "<?xml version=\"1.0\"?>\n"
    "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
    "  <Collection>\n";
constexpr size_t kCompressAbove = 64 * 1024;         // bytes of array data in a frame
constexpr size_t kMaxQueuedBytes = 256u << 20;       // frames waiting for the background writer
constexpr size_t kWakeBatch = 16;                    // frames that wake the writer
constexpr std::chrono::milliseconds kWriterPoll{5};  // else it looks every 5 ms
constexpr const char* kFooter = "  </Collection>\n</VTKFile>\n";

std::string entryLine(double t, const std::string& file) {
  return fmt::format("    <DataSet timestep=\"{:.17g}\" group=\"\" part=\"0\" file=\"{}\"/>\n", t,
                     file);
}

void writeAllAt(int fd, const std::string& text, long offset, const std::string& path) {
  const char* p = text.data();
  size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::pwrite(fd, p, left, offset);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
    }
    p += n, left -= static_cast<size_t>(n), offset += n;
  }
}

size_t frameBytes(const SceneFrame& f) {
  size_t n = f.points.size() * sizeof(double) + f.connectivity.size() * sizeof(int);
  for (const auto& a : f.pointData) n += a.values.size() * sizeof(double);
  for (const auto& a : f.cellData) n += a.values.size() * sizeof(double);
  return n;
}

}  // namespace

VtuSeries::VtuSeries(std::string dir, std::string name, Writing writing)
    : dir_(std::move(dir)), name_(std::move(name)), writing_(writing) {
  std::filesystem::create_directories(dir_);
  // Frames of an earlier run of this case in this directory go first: they would be stale, and
  // writing over them costs more than writing new files (ext4 flushes a file truncated on open).
  const std::string prefix = name_ + "_";
  for (const auto& e : std::filesystem::directory_iterator(dir_)) {
    const std::string f = e.path().filename().string();
    if (f.size() == prefix.size() + 10 && f.starts_with(prefix) && f.ends_with(".vtu"))
      std::filesystem::remove(e.path());
  }
  start({});
  startThread();
}

VtuSeries::VtuSeries(std::string dir, std::string name, int keepFrames, Writing writing)
    : dir_(std::move(dir)), name_(std::move(name)), writing_(writing) {
  std::filesystem::create_directories(dir_);
  std::vector<PvdEntry> kept;
  if (std::filesystem::exists(pvdPath())) {
    for (const auto& e : readPvd(pvdPath())) {
      if (static_cast<int>(kept.size()) < keepFrames)
        kept.push_back(e);
      else
        std::filesystem::remove(std::filesystem::path(dir_) / e.file);
    }
  }
  if (static_cast<int>(kept.size()) < keepFrames)
    throw std::runtime_error(pvdPath() + ": " + std::to_string(kept.size()) +
                             " frames where the checkpoint was taken after " +
                             std::to_string(keepFrames) + " (not this run's output)");
  frames_ = static_cast<int>(kept.size());
  start(kept);
  startThread();
}

void VtuSeries::start(const std::vector<PvdEntry>& kept) {
  const std::string path = pvdPath();
  std::string text = kHeader;
  for (const auto& e : kept) text += entryLine(e.t, e.file);
  footerAt_ = static_cast<long>(text.size());
  text += kFooter;
  // A new file: written whole under a temporary name, then renamed over the old collection.
  const std::string tmp = path + ".tmp";
  fd_ = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) throw std::runtime_error("cannot create " + tmp + ": " + std::strerror(errno));
  writeAllAt(fd_, text, 0, tmp);
  std::filesystem::rename(tmp, path);
}

VtuSeries::~VtuSeries() {
  if (thread_.joinable()) {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    queued_.notify_one();
    thread_.join();  // the writer empties the queue first
  }
  if (fd_ >= 0) ::close(fd_);
}

void VtuSeries::startThread() {
  if (writing_ == Writing::Background) thread_ = std::thread([this] { writerLoop(); });
}

int VtuSeries::frames() const {
  std::lock_guard lock(mutex_);
  return frames_;
}

double VtuSeries::backgroundSeconds() const {
  std::lock_guard lock(mutex_);
  return backgroundSeconds_;
}

void VtuSeries::rethrowWriterError() {
  if (writerError_) {
    auto e = writerError_;
    writerError_ = nullptr;
    std::rethrow_exception(e);
  }
}

void VtuSeries::writerLoop() {
  std::unique_lock lock(mutex_);
  for (;;) {
    // Woken by a batch of frames (or a flush, or the end), else every few ms: a wake-up per frame
    // would cost the stepping thread a futex call and often a context switch per step.
    queued_.wait_for(lock, kWriterPoll, [&] {
      return stopping_ || (!queue_.empty() && (flushWanted_ || queue_.size() >= kWakeBatch));
    });
    if (queue_.empty()) {
      if (stopping_) return;
      continue;
    }
    auto [frame, index] = std::move(queue_.front());
    queue_.pop_front();
    busy_ = true;
    lock.unlock();
    const auto t0 = std::chrono::steady_clock::now();
    std::exception_ptr error;
    try {
      if (!writerError_) {  // after an error, frames are dropped
        pendingEntries_ += writeFile(frame, index);
        // The collection is updated in one write once the queue is empty (or every 32 frames):
        // valid at every moment, and one pwrite instead of one per frame when frames queue up.
        if (++pendingCount_ >= 32 || queueLooksEmpty()) appendPending();
      }
    } catch (...) {
      error = std::current_exception();
    }
    const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    lock.lock();
    queuedBytes_ -= frameBytes(frame);
    backgroundSeconds_ += dt;
    if (error && !writerError_) writerError_ = error;
    busy_ = false;
    drained_.notify_all();
  }
}

void VtuSeries::flush() {
  std::unique_lock lock(mutex_);
  flushWanted_ = true;
  queued_.notify_one();
  drained_.wait(lock, [&] { return queue_.empty() && !busy_; });
  flushWanted_ = false;
  rethrowWriterError();
}

bool VtuSeries::queueLooksEmpty() const {
  std::lock_guard lock(mutex_);
  return queue_.empty();
}

void VtuSeries::appendPending() {
  // One write: the new entries followed by the closing tags, at the old closing tags.
  if (pendingEntries_.empty()) return;
  writeAllAt(fd_, pendingEntries_ + kFooter, footerAt_, pvdPath());
  footerAt_ += static_cast<long>(pendingEntries_.size());
  pendingEntries_.clear();
  pendingCount_ = 0;
}

namespace {
std::string frameText(const SceneFrame& f) {
  // Small frames go raw and are written directly (VtuRawFrame): compressing them costs more
  // than the bytes it saves (LZ4 clears a 16 KiB state per array), and VTK's writer costs
  // ~1.2 M instructions a frame where a step of such a scene costs ~20 us.
  if (frameBytes(f) < kCompressAbove) return vtuRawText(f);
  return vtuVtkText(f, VtkCompression::LZ4);
}
}  // namespace

void VtuSeries::write(SceneFrame f) {
  if (writing_ == Writing::InCaller) {
    pendingEntries_ = writeFile(f, frames_);
    appendPending();
    ++frames_;
    return;
  }
  std::unique_lock lock(mutex_);
  rethrowWriterError();
  // A bounded queue: a writer that cannot keep up holds the run back instead of filling memory.
  drained_.wait(lock, [&] { return queuedBytes_ < kMaxQueuedBytes || writerError_ != nullptr; });
  rethrowWriterError();
  queuedBytes_ += frameBytes(f);
  queue_.emplace_back(std::move(f), frames_);
  ++frames_;
  const bool wake = queue_.size() == kWakeBatch;
  lock.unlock();
  if (wake) queued_.notify_one();
}

std::string VtuSeries::writeFile(const SceneFrame& f, int index) {
  const std::string file = fmt::format("{}_{:06d}.vtu", name_, index);
  const std::string path = dir_ + "/" + file;
  const std::string text = frameText(f);
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);  // new file
  if (fd < 0) throw std::runtime_error("cannot create " + path + ": " + std::strerror(errno));
  try {
    writeAllAt(fd, text, 0, path);
  } catch (...) {
    ::close(fd);
    throw;
  }
  ::close(fd);
  return entryLine(f.t, file);
}

std::vector<PvdEntry> readPvd(const std::string& path) {
  // Read whole first (a regular file of bounded size, without blocking on a FIFO), then parsed.
  std::istringstream in(io::readInputFile(path, 64ull << 20));
  vtkNew<vtkXMLDataParser> parser;
  parser->SetStream(&in);
  if (!parser->Parse()) throw std::runtime_error(path + ": not a readable .pvd collection");
  vtkXMLDataElement* root = parser->GetRootElement();
  vtkXMLDataElement* coll = root ? root->FindNestedElementWithName("Collection") : nullptr;
  if (!coll) throw std::runtime_error(path + ": no <Collection> element");
  std::vector<PvdEntry> out;
  for (int i = 0; i < coll->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* e = coll->GetNestedElement(i);
    if (std::strcmp(e->GetName(), "DataSet") != 0) continue;
    PvdEntry p;
    if (!e->GetScalarAttribute("timestep", p.t) || !e->GetAttribute("file"))
      throw std::runtime_error(path + ": a DataSet without timestep or file");
    p.file = e->GetAttribute("file");
    if (!std::isfinite(p.t) || p.file.empty())
      throw std::runtime_error(path +
                               ": a DataSet with a time that is not a finite number or "
                               "no file");
    out.push_back(p);
  }
  return out;
}

}  // namespace chute
