#include "app/RunOutput.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace chute {

bool OutputClock::due(double t, long steps, double dt) {
  if (!on) return false;
  if (interval <= 0) return steps % every == 0;
  if (t < static_cast<double>(index) * interval - 1e-9 * dt) return false;
  while (static_cast<double>(index) * interval <= t + 1e-9 * dt) ++index;
  return true;
}

namespace {
long csvRows(const std::string& path) {
  std::ifstream in(path);
  long n = -1;  // the header is not a row
  for (std::string line; std::getline(in, line);) ++n;
  return std::max(n, 0L);
}

// An advisory lock on dir/.chute-run.lock, held while the run writes: two runs into one
// directory would interleave their rows. Released by the kernel however the process ends.
int lockDirectory(const std::string& dir) {
  const std::string path = dir + "/.chute-run.lock";
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error(path + ": cannot create the output lock");
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd);
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
                     const OutputMark* resume, RunResult& r)
    : spec_(&spec),
      sys_(&sys),
      r_(&r),
      probes_(spec.model, spec.output.probes),
      inertia_(spec.solver.type != AnalysisType::Static),
      probeClock_{true, spec.output.everySteps, spec.output.interval},
      vtuClock_{false, spec.output.vtu.everySteps, spec.output.vtu.interval} {
  r.columns = probes_.columns();
  const bool write = !outDir.empty();
  const bool wantVtu = spec.output.vtu.write && write;
  ScopedTimer timer(sys.timings().output);
  if (write) {
    std::filesystem::create_directories(outDir);
    lockFd_ = lockDirectory(outDir);
    if (resume) checkResumable(outDir, spec.name, *resume, wantVtu);
  }
  if (resume) {
    probeClock_.index = resume->probeClockIndex;
    vtuClock_.index = resume->vtuClockIndex;
    vtuLast_ = resume->vtuLast;
    r.energyInitial = resume->energyInitial;
    r.energyMaxDrift = resume->energyMaxDrift;
    r.kineticMax = resume->kineticMax;
  }
  if (write) {
    const std::string path = outDir + "/probes.csv";
    if (resume)
      csv_ = std::make_unique<CsvWriter>(path, r.columns, static_cast<size_t>(resume->probeRows),
                                         r.times, r.rows);
    else
      csv_ = std::make_unique<CsvWriter>(path, r.columns);
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
}

RunOutput::~RunOutput() {
  vtu_.reset();  // its last frames are written while the directory is still ours
  if (lockFd_ >= 0) ::close(lockFd_);
}

void RunOutput::record(const StructuralState& s) {
  ScopedTimer timer(sys_->timings().output);
  // The energy of the equilibrium point (the cut sets of s's time gone): with Chung-Hulbert the
  // end-of-step positions hold a stretch of stiff members that no force balances.
  const EquilibriumPoint eq = equilibriumOf(s);
  const auto e = sys_->energy(eq.x, eq.v, s.t);
  r_->times.push_back(s.t);
  ProbeBalance b;
  if (monitor_) b = {monitor_->work(), monitor_->balance()};
  r_->rows.push_back(probes_.evaluate(*sys_, s, eq, e, b));
  if (csv_) csv_->row(s.t, r_->rows.back());
  if (r_->times.size() == 1) r_->energyInitial = e.total();
  r_->energyMaxDrift = std::max(r_->energyMaxDrift, std::abs(e.total() - r_->energyInitial));
  r_->kineticMax = std::max(r_->kineticMax, e.kinetic);
}

void RunOutput::frame(const StructuralState& s) {
  if (!vtu_ || s.t == vtuLast_) return;
  ScopedTimer timer(sys_->timings().output);
  vtu_->write(buildFrame(*sys_, s, equilibriumOf(s), fields_, inertia_));
  vtuLast_ = s.t;
}

void RunOutput::afterStep(const StructuralState& s, long steps, bool last) {
  const double dt = spec_->solver.dt;
  if (probeClock_.due(s.t, steps, dt) || last) record(s);
  if (vtuClock_.due(s.t, steps, dt) || last) frame(s);
}

bool RunOutput::recordsAt(double t, long steps) const {
  OutputClock c = probeClock_;  // due() moves the clock on: asked of a copy
  return c.due(t, steps, spec_->solver.dt);
}

void RunOutput::lastGoodState(const StructuralState& s) {
  if (r_->times.empty() || r_->times.back() != s.t) record(s);
  frame(s);
}

OutputMark RunOutput::mark() const {
  OutputMark m;
  m.probeRows = static_cast<long>(r_->times.size());
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

}  // namespace chute
