// The two-part assembly (docs/performance.md, "Two threads"): the worker runs its part every
// time and hands back what it threw, and a system assembled on two threads gives the same bits
// as one assembled on one (the split depends on the scene only).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "assembly/TwoPartRunner.hpp"
#include "case/CaseSpec.hpp"
#include "case/SolverSetup.hpp"
#include "solver/GeneralizedAlpha.hpp"

using namespace chute;

namespace {

bool sameBits(const double* a, const double* b, long n) {
  return std::memcmp(a, b, sizeof(double) * static_cast<size_t>(n)) == 0;
}

// A system built while CHUTE_THREADS is set to `threads` (the runner reads it once).
std::unique_ptr<StructuralSystem> systemWith(const CaseSpec& spec, const char* threads) {
  setenv("CHUTE_THREADS", threads, 1);
  auto sys = std::make_unique<StructuralSystem>(spec.model, spec.solver.search);
  unsetenv("CHUTE_THREADS");
  return sys;
}

}  // namespace

TEST(TwoPartRunner, RunsBothPartsEveryTime) {
  TwoPartRunner runner;
  std::atomic<long> first{0}, second{0};
  for (int k = 0; k < 20000; ++k) runner.run([&] { ++first; }, [&] { ++second; });
  EXPECT_EQ(first.load(), 20000);
  EXPECT_EQ(second.load(), 20000);
  // Both modes are timed (the one not chosen every few windows), and every call is counted.
  EXPECT_EQ(runner.concurrentRuns() + runner.serialRuns(), runner.concurrent() ? 20000 : 0);
  if (runner.concurrent()) {
    EXPECT_GT(runner.concurrentRuns(), 0);
    EXPECT_GT(runner.serialRuns(), 0);
  }
}

TEST(TwoPartRunner, HandsBackWhatEitherPartThrew) {
  TwoPartRunner runner;
  EXPECT_THROW(runner.run([] {}, [] { throw std::runtime_error("second"); }), std::runtime_error);
  // The first part's exception waits for the second part to finish (it may use the caller's
  // objects): the second part's effect is there when run() throws.
  std::atomic<bool> secondDone{false};
  try {
    runner.run([] { throw std::logic_error("first"); }, [&] { secondDone = true; });
    FAIL() << "no exception";
  } catch (const std::logic_error& e) {
    EXPECT_STREQ(e.what(), "first");
  }
  EXPECT_TRUE(secondDone.load());
  // And it goes on working.
  std::atomic<int> both{0};
  runner.run([&] { ++both; }, [&] { ++both; });
  EXPECT_EQ(both.load(), 2);
}

TEST(TwoPartAssembly, OneThreadAndTwoGiveTheSameBits) {
  // c9_slider: every kind of term the split moves (membranes, pressure, face drag, cables, line
  // drag) and the ones it keeps on the first thread (sliding groups, point masses).
  const CaseSpec spec = readCase(CHUTE_SOURCE_DIR "/cases/c9_slider.toml", {});
  auto one = systemWith(spec, "1");
  auto two = systemWith(spec, "2");
  ASSERT_TRUE(one->assemblesInTwoParts());
  StructuralState s = one->initialState();
  // Some motion, so that drag and inertia are not zero.
  for (long d = 0; d < s.v.size(); ++d) s.v[d] = 0.3 * std::sin(0.7 * static_cast<double>(d));
  for (long d = 0; d < s.a.size(); ++d) s.a[d] = 2.0 * std::cos(0.3 * static_cast<double>(d));
  for (bool wantMatrix : {false, true}) {
    const EvalPoint p = EvalPoint::implicitStep(s.x, s.v, s.a, 0.05, {1.0, 0.5, 2.0}, 1e-3);
    one->updateState(s.x);
    two->updateState(s.x);
    one->assemble(p, wantMatrix);
    two->assemble(p, wantMatrix);
    ASSERT_EQ(one->residual().size(), two->residual().size());
    EXPECT_GT(one->residual().norm(), 0.0);
    EXPECT_TRUE(sameBits(one->residual().data(), two->residual().data(), one->residual().size()))
        << "residual, wantMatrix " << wantMatrix;
    if (wantMatrix) {
      ASSERT_EQ(one->matrix().nonZeros(), two->matrix().nonZeros());
      EXPECT_TRUE(
          sameBits(one->matrix().valuePtr(), two->matrix().valuePtr(), one->matrix().nonZeros()));
    }
  }
  // The work counters count both parts.
  EXPECT_EQ(one->work().membrane, two->work().membrane);
  EXPECT_EQ(two->work().membrane, 2 * static_cast<long>(spec.model.membranes.size()));
  EXPECT_EQ(two->work().faceDrag, one->work().faceDrag);
  EXPECT_GT(two->work().faceDrag, 0);
}
