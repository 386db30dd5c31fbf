#include "app/RunOutput.hpp"

#include <fcntl.h>
#include <fmt/core.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <filesystem>

#include "OutputError.hpp"
#include "io/InputFile.hpp"

namespace chute {

bool OutputClock::due(double t, long steps, double dt) {
  if (!on) return false;
  if (interval <= 0) return steps % every == 0;
  if (t < static_cast<double>(index) * interval - 1e-9 * dt) return false;
  while (static_cast<double>(index) * interval <= t + 1e-9 * dt) ++index;
  return true;
}

namespace {
// Rows of a probes.csv, counted without holding them (a regular file only).
long csvRows(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return 0;
  if (io::inputFileProblem(path, ~std::uintmax_t{0})) {
    ::close(fd);
    return 0;
  }
  long n = 0;
  char buf[1 << 16];
  for (;;) {
    const ssize_t k = ::read(fd, buf, sizeof buf);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) break;
    for (ssize_t i = 0; i < k; ++i) n += buf[i] == '\n';
  }
  ::close(fd);
  return std::max(n - 1, 0L);  // the header is not a row
}

// An advisory lock on dir/.chute-run.lock, held while the run writes: two runs into one
// directory would interleave their rows. Released by the kernel however the process ends.
// `created`: whether this call made the file (a refused restart removes it again).
int lockDirectory(const std::string& dir, bool& created) {
  const std::string path = dir + "/.chute-run.lock";
  int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  created = fd >= 0;
  if (fd < 0 && errno == EEXIST) fd = ::open(path.c_str(), O_RDWR | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0)
    throw std::runtime_error(path + ": cannot create the output lock (" +
                             (errno == ELOOP ? std::string("a symbolic link is there")
                                             : std::string(std::strerror(errno))) +
                             ")");
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd);
    if (created) ::unlink(path.c_str());
    throw std::runtime_error(dir + ": another chute run is writing into this directory");
  }
  return fd;
}

// The output in dir must hold at least what the checkpoint says it had: checked before
// anything is cut.
void checkResumable(const std::string& dir, const std::string& name, const OutputMark& m,
                    bool vtu) {
  const std::string csv = dir + "/probes.csv";
  if (csvRows(csv) < m.probeRows)
    throw std::runtime_error(csv +
                             ": fewer rows than when the checkpoint was taken (not the "
                             "output of this run)");
  if (vtu && m.vtuFrames > 0) {
    const std::string pvd = dir + "/" + name + ".pvd";
    if (!std::filesystem::exists(pvd) || static_cast<long>(readPvd(pvd).size()) < m.vtuFrames)
      throw std::runtime_error(pvd +
                               ": fewer frames than when the checkpoint was taken (not the "
                               "output of this run)");
  }
}
}  // namespace

RunOutput::RunOutput(const CaseSpec& spec, StructuralSystem& sys, const std::string& outDir,
                     const OutputMark* resume, RunResult& r, bool keepRows)
    : spec_(&spec),
      sys_(&sys),
      r_(&r),
      dir_(outDir),
      keepRows_(keepRows || outDir.empty()),
      probes_(spec.model, spec.output.probes),
      reference_(ReferenceTracker::forCase(spec, probes_)),
      inertia_(spec.solver.type != AnalysisType::Static),
      probeClock_{true, spec.output.everySteps, spec.output.interval},
      vtuClock_{false, spec.output.vtu.everySteps, spec.output.vtu.interval} {
  r.columns = probes_.columns();
  flight_ = FlightSeriesCollector::forCase(spec.output.probes, r.columns);
  const bool write = !outDir.empty();
  const bool wantVtu = spec.output.vtu.write && write;
  ScopedTimer timer(sys.timings().output);
  bool createdLock = false;
  if (write) {
    if (resume) {
      // A restart continues the output there: nothing is created before it is found to be the
      // checkpointed run's (a refused restart leaves the directory as it was).
      if (!std::filesystem::is_directory(outDir))
        throw std::runtime_error(outDir + ": no output of the checkpointed run there");
      lockFd_ = lockDirectory(outDir, createdLock);
      try {
        checkResumable(outDir, spec.name, *resume, wantVtu);
      } catch (...) {
        if (createdLock) ::unlink((outDir + "/.chute-run.lock").c_str());
        ::close(lockFd_);
        lockFd_ = -1;
        throw;
      }
    } else {
      std::filesystem::create_directories(outDir);
      lockFd_ = lockDirectory(outDir, createdLock);
    }
  }
  if (resume) {
    probeClock_.index = resume->probeClockIndex;
    vtuClock_.index = resume->vtuClockIndex;
    vtuLast_ = resume->vtuLast;
    r.energyInitial = resume->energyInitial;
    r.energyMaxDrift = resume->energyMaxDrift;
    r.kineticMax = resume->kineticMax;
  }
  try {
    if (write) {
      const std::string path = outDir + "/probes.csv";
      if (resume) {
        // The rows up to the checkpoint, read back once: the reference comparison (and the
        // rows a caller keeps) go on from them.
        csv_ = std::make_unique<CsvWriter>(path, r.columns, resume->probeRows,
                                           [&](double t, const std::vector<double>& row) {
                                             ++rows_;
                                             lastRowTime_ = t;
                                             if (reference_) reference_->add(t, row);
                                             if (flight_) flight_->add(t, row);
                                             if (keepRows_)
                                               r.times.push_back(t), r.rows.push_back(row);
                                           });
      } else {
        csv_ = std::make_unique<CsvWriter>(path, r.columns);
      }
    }
    // The VTU series only when the case asks for it: no VTK work otherwise.
    if (wantVtu) {
      if (resume)
        vtu_ = std::make_unique<VtuSeries>(outDir, spec.name, static_cast<int>(resume->vtuFrames),
                                           Writing::Background);
      else
        vtu_ = std::make_unique<VtuSeries>(outDir, spec.name, Writing::Background);
      if (!spec.output.vtu.fields.empty()) fields_.select(spec.output.vtu.fields);
      vtuClock_.on = true;
    }
    if (resume) markLastGood();
  } catch (...) {
    if (lockFd_ >= 0) {
      if (resume && createdLock) ::unlink((outDir + "/.chute-run.lock").c_str());
      ::close(lockFd_);
      lockFd_ = -1;
    }
    throw;
  }
}

RunOutput::~RunOutput() {
  try {
    vtu_.reset();  // its last frames are written while the directory is still ours
  } catch (...) {  // a write that failed now has nobody to report to: the .pvd stays valid
  }
  if (lockFd_ >= 0) ::close(lockFd_);
}

void RunOutput::addRow(double t, std::vector<double> values) {
  if (csv_) csv_->row(t, values);
  ++rows_;
  lastRowTime_ = t;
  if (reference_) reference_->add(t, values);
  if (flight_) flight_->add(t, values);
  if (keepRows_) {
    r_->times.push_back(t);
    r_->rows.push_back(std::move(values));
  }
}

void RunOutput::record(const StructuralState& s) {
  ScopedTimer timer(sys_->timings().output);
  // The energy of the equilibrium point (the cut sets of s's time gone): with Chung-Hulbert the
  // end-of-step positions hold a stretch of stiff members that no force balances.
  const EquilibriumPoint eq = equilibriumOf(s);
  const auto e = sys_->energy(eq.x, eq.v, s.t);
  ProbeBalance b;
  if (monitor_) b = {monitor_->work(), monitor_->balance()};
  const bool first = rows_ == 0;
  addRow(s.t, probes_.evaluate(*sys_, s, eq, e, b));
  if (first) r_->energyInitial = e.total();
  r_->energyMaxDrift = std::max(r_->energyMaxDrift, std::abs(e.total() - r_->energyInitial));
  r_->kineticMax = std::max(r_->kineticMax, e.kinetic);
  rowWrittenThisStep_ = true;
}

void RunOutput::frame(const StructuralState& s) {
  if (!vtu_ || s.t == vtuLast_) return;
  ScopedTimer timer(sys_->timings().output);
  vtu_->write(buildFrame(*sys_, s, equilibriumOf(s), fields_, inertia_));
  vtuLast_ = s.t;
}

void RunOutput::afterStep(const StructuralState& s, long steps, bool last) {
  const double dt = spec_->solver.dt;
  rowWrittenThisStep_ = false;
  if (probeClock_.due(s.t, steps, dt) || last) record(s);
  if (vtuClock_.due(s.t, steps, dt) || last) frame(s);
  // A row written while the energy balance holds (no monitor: statics, every row) is a state the
  // output may be cut back to.
  if (rowWrittenThisStep_ && (!monitor_ || monitor_->withinBounds())) markLastGood();
}

bool RunOutput::recordsAt(double t, long steps) const {
  OutputClock c = probeClock_;  // due() moves the clock on: asked of a copy
  return c.due(t, steps, spec_->solver.dt);
}

void RunOutput::lastGoodState(const StructuralState& s) {
  if (rows_ == 0 || lastRowTime_ != s.t) record(s);
  frame(s);
}

RunOutput::Position RunOutput::position() const {
  Position p;
  if (csv_) p.csv = csv_->mark();
  p.rows = rows_;
  p.lastRowTime = lastRowTime_;
  p.frames = vtuFrames();
  p.vtuLast = vtuLast_;
  p.energyInitial = r_->energyInitial;
  p.energyMaxDrift = r_->energyMaxDrift;
  p.kineticMax = r_->kineticMax;
  p.reference = reference_;
  return p;
}

double RunOutput::cutBackToLastGoodRow() {
  if (!lastGood_) return std::numeric_limits<double>::quiet_NaN();
  ScopedTimer timer(sys_->timings().output);
  const Position& p = *lastGood_;
  if (csv_) csv_->cutBackTo(p.csv);
  if (vtu_) vtu_->cutBackTo(p.frames);
  rows_ = p.rows;
  lastRowTime_ = p.lastRowTime;
  vtuLast_ = p.vtuLast;
  r_->energyInitial = p.energyInitial;
  r_->energyMaxDrift = p.energyMaxDrift;
  r_->kineticMax = p.kineticMax;
  reference_ = p.reference;
  if (flight_) flight_->cutBackTo(static_cast<size_t>(p.rows));
  if (keepRows_ && static_cast<long>(r_->times.size()) > p.rows) {
    r_->times.resize(static_cast<size_t>(p.rows));
    r_->rows.resize(static_cast<size_t>(p.rows));
  }
  return lastRowTime_;
}

OutputMark RunOutput::mark() const {
  OutputMark m;
  m.probeRows = rows_;
  m.vtuFrames = vtuFrames();
  m.probeClockIndex = probeClock_.index;
  m.vtuClockIndex = vtuClock_.index;
  m.vtuLast = vtuLast_;
  m.energyInitial = r_->energyInitial;
  m.energyMaxDrift = r_->energyMaxDrift;
  m.kineticMax = r_->kineticMax;
  return m;
}

void RunOutput::flush() {
  if (!vtu_) return;
  ScopedTimer timer(sys_->timings().output);
  vtu_->flush();
}

std::string RunOutput::wholeSoFar() const {
  std::string out;
  if (csv_) {
    const auto m = csv_->mark();
    out = m.rows > 0 ? fmt::format("probes.csv is whole up to t = {:.9g} ({} row{})", m.lastTime,
                                   m.rows, m.rows > 1 ? "s" : "")
                     : std::string("probes.csv holds no row");
  }
  if (vtu_) {
    const int n = vtu_->listedFrames();
    out += (out.empty() ? "" : "; ") +
           (n > 0 ? fmt::format("{}.pvd lists {} whole frame{}, up to t = {:.9g}", spec_->name, n,
                                n > 1 ? "s" : "", vtu_->lastListedTime())
                  : fmt::format("{}.pvd lists no frame", spec_->name));
  }
  return out;
}

}  // namespace chute
