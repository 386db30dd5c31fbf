#pragma once
// Wall-time accounting of a run, split as summary.json reports it.
#include <chrono>

namespace chute {

struct Timings {
  double assembly = 0.0;
  double search = 0.0;
  double factorisation = 0.0;
  double solve = 0.0;
  double output = 0.0;  // in the stepping thread, including the wait for the last frames
  // An explicit step's own work besides the assembly and the sliders' settling: its passes over
  // all dofs (EX1's prediction and update, EX7's positions made again), the terms' commits and
  // the stable-step estimate (EX5); and, in every dynamic run, the energy balance (EB1).
  double passes = 0.0;
  double commits = 0.0;
  double stableStep = 0.0;
  double balance = 0.0;
  // VTU frames written on the background thread: overlaps the others, not part of the total.
  double outputBackground = 0.0;
  long assemblies = 0, searches = 0, factorisations = 0, solves = 0;
};

// Adds the lifetime of the guard to one Timings field.
class ScopedTimer {
 public:
  explicit ScopedTimer(double& acc) : acc_(acc), t0_(std::chrono::steady_clock::now()) {}
  ~ScopedTimer() {
    acc_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  }
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;

 private:
  double& acc_;
  std::chrono::steady_clock::time_point t0_;
};

}  // namespace chute
