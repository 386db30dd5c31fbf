#include "app/Progress.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace chute {

namespace {
constexpr auto kTerminalEvery = std::chrono::milliseconds(200);
constexpr auto kLogAtLeastEvery = std::chrono::seconds(60);
constexpr double kLogFraction = 0.05;
}  // namespace

Progress::Progress(bool on, double t0, double tEnd, bool implicitSteps)
    : mode_(!on ? Mode::Off : (isatty(STDERR_FILENO) ? Mode::Terminal : Mode::Log)),
      t0_(t0),
      tEnd_(tEnd),
      implicit_(implicitSteps),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {
  if (tEnd_ > t0_) nextFraction_ = (std::floor((t0_ / tEnd_) / kLogFraction) + 1.0) * kLogFraction;
}

std::string Progress::duration(double s) {
  if (!std::isfinite(s) || s < 0) return "?";
  if (s < 10) return fmt::format("{:.1f} s", s);
  const long n = std::lround(s);
  if (n < 60) return fmt::format("{} s", n);
  if (n < 3600) return fmt::format("{} min {:02d} s", n / 60, n % 60);
  return fmt::format("{} h {:02d} min", n / 3600, (n % 3600) / 60);
}

std::string Progress::figures(const Step& s, double elapsed) const {
  const double done = s.t - t0_;
  std::string left = "?";
  if (s.t >= tEnd_)
    left = duration(0.0);  // the end: nothing left, however short the run
  else if (done > 0 && elapsed > 0.5)
    left = duration(elapsed * (tEnd_ - s.t) / done);  // below half a second the rate is noise
  std::string work;
  if (implicit_) {
    work = fmt::format("newton {:2d} (avg {:.2f})  rejected {}", s.newton, s.newtonAverage,
                       s.rejected);
  } else {
    const double rate = elapsed > 0 ? static_cast<double>(s.step - stepsAtStart_) / elapsed : 0.0;
    work = fmt::format("{:.0f} steps/s", rate);
  }
  return fmt::format("step {:7d}  t = {:<10.6g} / {:<8.4g} dt = {:<9.3g} {}  {} left", s.step, s.t,
                     tEnd_, s.dt, work, left);
}

void Progress::update(const Step& s, bool force) {
  if (mode_ == Mode::Off) return;
  const auto now = std::chrono::steady_clock::now();
  if (stepsAtStart_ < 0) stepsAtStart_ = std::max(0L, s.step - 1);
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (mode_ == Mode::Terminal) {
    if (!force && now - last_ < kTerminalEvery) return;
    last_ = now;
    std::fprintf(stderr, "\r  %s   ", figures(s, elapsed).c_str());
    return;
  }
  // A log: at every 5 % of the simulated time, and at least once a minute.
  const double fraction = tEnd_ > 0 ? s.t / tEnd_ : 1.0;
  if (!force && fraction < nextFraction_ && now - last_ < kLogAtLeastEvery) return;
  while (nextFraction_ <= fraction) nextFraction_ += kLogFraction;
  last_ = now;
  std::fprintf(stdout, "  %3.0f %%  %s (%s elapsed)\n", 100.0 * std::min(fraction, 1.0),
               figures(s, elapsed).c_str(), duration(elapsed).c_str());
  std::fflush(stdout);
}

void Progress::finish() {
  if (mode_ == Mode::Terminal) std::fputc('\n', stderr);
}

}  // namespace chute
