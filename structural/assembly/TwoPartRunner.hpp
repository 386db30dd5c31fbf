#pragma once
// Runs two parts of one job at once: the first on the calling thread, the second on a worker
// thread that lives as long as the runner (docs/performance.md, "Two threads"). The worker
// spins for a short while after each job before it sleeps, because the explicit path hands it
// a job every few hundred microseconds; a longer spin would burn the core while the implicit
// path factorises. Not OpenMP: libgomp fixes its spin at program start from the environment
// (GOMP_SPINCOUNT), and its default spin doubled the CPU time of implicit runs.
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

  // Whether parts run on two threads: a machine with at least two hardware threads and
  // CHUTE_THREADS not set to 1.
  bool concurrent() const { return worker_.joinable(); }

 private:
  void work();

  std::thread worker_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void()>* job_ = nullptr;
  std::exception_ptr failure_;
  std::atomic<unsigned> posted_{0}, finished_{0};
  std::atomic<bool> quit_{false};
};

}  // namespace chute
