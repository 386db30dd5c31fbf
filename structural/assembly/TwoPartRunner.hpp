#pragma once
// Runs two parts of one job at once: the first on the calling thread, the second on a worker
// thread that lives as long as the runner (docs/performance.md, "Two threads"). The worker
// spins for a short while after each job before it sleeps, because the explicit path hands it
// a job every few hundred microseconds; a longer spin would burn the core while the implicit
// path factorises. Not OpenMP: libgomp fixes its spin at program start from the environment
// (GOMP_SPINCOUNT), and its default spin doubled the CPU time of implicit runs.
#include <array>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace chute {

class TwoPartRunner {
 public:
  TwoPartRunner();
  ~TwoPartRunner();
  TwoPartRunner(const TwoPartRunner&) = delete;
  TwoPartRunner& operator=(const TwoPartRunner&) = delete;

  // first() here and second() on the worker; returns when both are done and rethrows what
  // either threw (the first's exception first). Without a worker: one after the other.
  void run(const std::function<void()>& first, const std::function<void()>& second);
  // The same for occasional jobs other than the assembly (the energy balance's two evaluations):
  // in the mode the assemblies currently run in, neither timed nor counted with them.
  void runOther(const std::function<void()>& first, const std::function<void()>& second);

  // Whether parts can run on two threads: a machine with at least two hardware threads and
  // CHUTE_THREADS not set to 1.
  bool concurrent() const { return worker_.joinable(); }
  // Calls run on two threads and one after the other so far (see choose()).
  long concurrentRuns() const { return runs_[1]; }
  long serialRuns() const { return runs_[0]; }

 private:
  void work();
  void runConcurrently(const std::function<void()>& first, const std::function<void()>& second);
  // Two threads only pay while the machine has a core free for the second: on a loaded
  // machine the caller waits for a worker that waits for a core. The runner times windows of
  // calls in each mode and keeps the faster, trying the other again every few windows. The
  // parts' results do not depend on the mode.
  bool choose();
  void record(bool concurrentCall, double seconds);

  std::thread worker_;
  // The hand-over of a job and of its end: tickets that the waiting thread polls, and the mutex
  // and condition variables only for a thread that stopped polling and sleeps (its flag set
  // under the mutex). On the fast path neither thread takes the mutex: the C-9's explicit step
  // hands the worker eight jobs of a few microseconds each (docs/performance.md, "Two threads").
  // Each ticket on a cache line of its own, so that polling one does not pull the other away.
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void()>* job_ = nullptr;
  std::exception_ptr failure_;
  alignas(64) std::atomic<unsigned> posted_{0};
  alignas(64) std::atomic<unsigned> finished_{0};
  alignas(64) std::atomic<bool> workerSleeps_{false};
  std::atomic<bool> callerSleeps_{false};
  std::atomic<bool> quit_{false};
  // Mode choice: the mode of the current window, its calls' times, the last median of each.
  // The median, not the mean: a call that waited for the worker's wake-up or lost its core for a
  // moment made a window of two threads look slower than one (a third of an idle machine's
  // generated C-9 run went to one thread).
  static constexpr int kWindow = 16;      // calls per timed window
  static constexpr int kProbeEvery = 32;  // windows between timings of the mode not in use, at most
  bool mode_ = true;
  int windowCalls_ = 0, windowsSinceProbe_ = 0;
  int probeEvery_ = kProbeEvery;  // now (choose(): fewer after a switch to one thread)
  bool probed_ = false;           // the window just timed was such a timing
  std::array<double, kWindow> windowTimes_{};
  double median_[2] = {-1.0, -1.0};  // serial, concurrent; < 0: not measured yet
  long runs_[2] = {0, 0};
};

}  // namespace chute
