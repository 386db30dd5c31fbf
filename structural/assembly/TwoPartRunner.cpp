#include "assembly/TwoPartRunner.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>

namespace chute {

namespace {

// How long a waiting thread polls before it sleeps: longer than the gap between two explicit
// steps' assemblies (under 0.1 ms on the C-9), so that explicit runs never wait for a wake-up;
// an implicit iteration (a factorisation between assemblies) costs the worker 0.3 ms of polling.
// Measured on the C-9: 1 ms cost implicit runs 8 % more CPU and explicit runs no wall time.
constexpr auto kSpin = std::chrono::microseconds(300);

inline void pause() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();  // spin-wait hint: leaves the core's resources to its sibling
#endif
}

// The clock is read only once the first polls found nothing: most waits of the explicit step
// end within them, and a clock read costs about as much as the hand-over itself.
template <class Ready>
bool spinUntil(Ready ready) {
  constexpr int kFirstPolls = 64;
  for (int k = 0; k < kFirstPolls; ++k) {
    if (ready()) return true;
    pause();
  }
  const auto until = std::chrono::steady_clock::now() + kSpin;
  for (int k = 0;; ++k) {
    if (ready()) return true;
    pause();
    if ((k & 63) == 63 && std::chrono::steady_clock::now() > until) return false;
  }
}

// Mode choice (TwoPartRunner::choose): how much faster one thread's window must be for it to be
// kept: two threads unless one is clearly faster (on a loaded machine it was 25-40 %,
// docs/performance.md).
constexpr double kSerialMargin = 1.15;
// How much faster two threads must be for one thread to be timed ever more rarely (choose()):
// an idle machine's explicit C-9 assemblies run about 1.6 times faster on two.
constexpr double kClearMargin = 1.25;
constexpr int kProbeEveryClear = 256;

bool twoThreadsAllowed() {
  const char* env = std::getenv("CHUTE_THREADS");
  if (env && std::strcmp(env, "1") == 0) return false;
  return std::thread::hardware_concurrency() >= 2;
}

}  // namespace

TwoPartRunner::TwoPartRunner() {
  if (twoThreadsAllowed()) worker_ = std::thread([this] { work(); });
}

TwoPartRunner::~TwoPartRunner() {
  if (!worker_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    quit_.store(true);
  }
  wake_.notify_one();
  worker_.join();
}

// The sleeping side sets its flag and then reads the ticket, the other side writes the ticket
// and then reads the flag (all sequentially consistent): at least one of them sees the other's
// write, so a sleeper is either woken or never sleeps. The flag is set under the mutex that the
// waker takes before it notifies, so the notification cannot fall between the sleeper's test and
// its wait.
void TwoPartRunner::work() {
  unsigned seen = 0;
  auto posted = [&] { return posted_.load() != seen || quit_.load(); };
  for (;;) {
    if (!spinUntil(posted)) {
      std::unique_lock<std::mutex> lock(mutex_);
      workerSleeps_.store(true);
      wake_.wait(lock, posted);
      workerSleeps_.store(false);
    }
    if (quit_.load()) return;
    seen = posted_.load(std::memory_order_acquire);
    try {
      (*job_)();
    } catch (...) {
      failure_ = std::current_exception();
    }
    finished_.store(seen);
    if (callerSleeps_.load()) {
      std::lock_guard<std::mutex> lock(mutex_);
      done_.notify_one();
    }
  }
}

bool TwoPartRunner::choose() {
  if (windowCalls_ < kWindow) return mode_;
  std::nth_element(windowTimes_.begin(), windowTimes_.begin() + kWindow / 2, windowTimes_.end());
  median_[mode_ ? 1 : 0] = windowTimes_[kWindow / 2];
  windowCalls_ = 0;
  const bool other = !mode_;
  if (median_[other ? 1 : 0] < 0.0 || ++windowsSinceProbe_ >= probeEvery_) {
    windowsSinceProbe_ = 0;
    probed_ = true;
    mode_ = other;  // (re)measure the other mode
    return mode_;
  }
  const bool two = median_[1] <= kSerialMargin * median_[0];
  // One thread newly chosen: two threads are timed again after 2 windows, then 4, 8, ... up to
  // kProbeEvery while one thread keeps winning. A passing disturbance costs a few windows (the
  // BLAS library's worker spins on the second core for about 0.1 s after start-up: two threads
  // timed then lost to one, which then ran 32 windows, a third of a generated C-9 run); a loaded
  // machine settles at kProbeEvery.
  // Two threads clearly faster than one (by kClearMargin) at each timing of one thread: one
  // thread is timed again after 64, 128, then 256 windows (each such window cost the C-9 slider
  // case 16 assemblies on one thread: 3 % of its assemblies at every 32 windows).
  if (two && kClearMargin * median_[1] <= median_[0])
    probeEvery_ = probed_ && !mode_
                      ? std::min(2 * std::max(probeEvery_, kProbeEvery), kProbeEveryClear)
                      : std::max(probeEvery_, kProbeEvery);
  else if (two)
    probeEvery_ = kProbeEvery;
  else if (mode_ && probed_)
    probeEvery_ = std::min(2 * probeEvery_, kProbeEvery);
  else if (mode_ || probed_)
    probeEvery_ = 2;
  probed_ = false;
  mode_ = two;
  return mode_;
}

void TwoPartRunner::record(bool concurrentCall, double seconds) {
  ++runs_[concurrentCall ? 1 : 0];
  windowTimes_[windowCalls_++] = seconds;
}

void TwoPartRunner::run(const std::function<void()>& first, const std::function<void()>& second) {
  if (!worker_.joinable()) {
    first();
    second();
    return;
  }
  const bool concurrentCall = choose();
  const auto start = std::chrono::steady_clock::now();
  if (concurrentCall) {
    runConcurrently(first, second);
  } else {
    first();
    second();
  }
  record(concurrentCall,
         std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

void TwoPartRunner::runOther(const std::function<void()>& first,
                             const std::function<void()>& second) {
  if (worker_.joinable() && mode_) {
    runConcurrently(first, second);
  } else {
    first();
    second();
  }
}

void TwoPartRunner::runConcurrently(const std::function<void()>& first,
                                    const std::function<void()>& second) {
  failure_ = nullptr;
  job_ = &second;
  const unsigned ticket = posted_.load(std::memory_order_relaxed) + 1;
  posted_.store(ticket);
  if (workerSleeps_.load()) {
    std::lock_guard<std::mutex> lock(mutex_);
    wake_.notify_one();
  }
  std::exception_ptr mine;
  try {
    first();
  } catch (...) {
    mine = std::current_exception();
  }
  // Wait for the worker even when first() threw: second() still uses the caller's objects.
  auto finished = [&] { return finished_.load() == ticket; };
  if (!spinUntil(finished)) {
    std::unique_lock<std::mutex> lock(mutex_);
    callerSleeps_.store(true);
    done_.wait(lock, finished);
    callerSleeps_.store(false);
  }
  job_ = nullptr;
  if (mine) std::rethrow_exception(mine);
  if (failure_) std::rethrow_exception(failure_);
}

}  // namespace chute
