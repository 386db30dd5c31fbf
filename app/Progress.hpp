#pragma once
// How far a run has got, while it runs (docs/cli.md, "Progress"):
//  - on a terminal (stderr is one): one status line on stderr, rewritten at most 5 times a
//    second: step, t of t_end, the step, Newton iterations (implicit) or steps per second
//    (explicit), and an estimate of the time left;
//  - otherwise (a log): a line on stdout at every 5 % of the simulated time and at least every
//    60 s, with the same figures.
// The estimate of the time left assumes the rest of the run goes at the rate of the run so far
// (simulated time per wall second since it started or restarted).
#include <chrono>
#include <cstdio>
#include <string>

namespace chute {

class Progress {
 public:
  // on: false prints nothing (--quiet). t0: the time the run starts from (a restart's), tEnd its
  // end. implicitSteps: Newton iterations are worth showing (false: explicit steps per second).
  Progress(bool on, double t0, double tEnd, bool implicitSteps);
  struct Step {
    long step = 0;
    double t = 0.0, dt = 0.0;
    int newton = 0;
    double newtonAverage = 0.0;
    long rejected = 0;
  };
  void update(const Step& s, bool force = false);
  void finish();  // ends the terminal's status line

  // "1 h 02 min", "3 min 05 s", "12 s", "0.4 s": a duration for people.
  static std::string duration(double seconds);

 private:
  std::string figures(const Step& s, double elapsed) const;
  enum class Mode { Off, Terminal, Log } mode_;
  double t0_, tEnd_;
  bool implicit_;
  std::chrono::steady_clock::time_point start_, last_;
  long stepsAtStart_ = -1;
  double nextFraction_ = 0.05;  // Log: the next 5 % mark
};

}  // namespace chute
