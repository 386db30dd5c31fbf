// The BLAS library's idle threads released at start (releaseBlasThreads): the process keeps no
// thread of OpenBLAS's, and CHOLMOD's and UMFPACK's solves afterwards are what they were (their
// residuals against the matrix, and the same bits as before the release).
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <thread>
#include <vector>

#include "solver/LinearSolver.hpp"

namespace {

int threadsOfThisProcess() {
  int n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator("/proc/self/task")) ++n;
  return n;
}

// A banded matrix of n equations with dense enough fronts for CHOLMOD's supernodes (BLAS):
// symmetric positive definite, or with a skew part for UMFPACK.
chute::SparseMatrix bandMatrix(int n, int band, bool skew) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 4.0 * band + 1.0);
    for (int k = 1; k <= band && i + k < n; ++k) {
      const double a = -1.0 / k, s = skew ? 0.3 / k : 0.0;
      t.emplace_back(i, i + k, a + s);
      t.emplace_back(i + k, i, a - s);
    }
  }
  chute::SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

Eigen::VectorXd solveWith(bool cholesky, const chute::SparseMatrix& A, const Eigen::VectorXd& b) {
  chute::Timings timings;
  chute::LinearSolver solver(cholesky, timings);
  Eigen::VectorXd x;
  EXPECT_TRUE(solver.factorize(A));
  EXPECT_TRUE(solver.solve(b, x));
  return x;
}

}  // namespace

TEST(LinearSolver, TheBlasThreadsReleasedAtStartLeaveTheSolvesAsTheyWere) {
  if (std::getenv("OPENBLAS_NUM_THREADS") || std::getenv("OMP_NUM_THREADS"))
    GTEST_SKIP() << "BLAS threads asked for by the environment: releaseBlasThreads keeps them";
  const chute::SparseMatrix spd = bandMatrix(3000, 60, false), lu = bandMatrix(3000, 60, true);
  Eigen::VectorXd b(3000);
  for (int i = 0; i < b.size(); ++i) b[i] = 1.0 + 0.001 * (i % 17);
  const Eigen::VectorXd x0 = solveWith(true, spd, b), y0 = solveWith(false, lu, b);
  const int before = threadsOfThisProcess();
  chute::releaseBlasThreads();
  const int after = threadsOfThisProcess();
  const Eigen::VectorXd x1 = solveWith(true, spd, b), y1 = solveWith(false, lu, b);
  const int afterSolves = threadsOfThisProcess();
  const double rx = (spd * x1 - b).norm() / b.norm(), ry = (lu * y1 - b).norm() / b.norm();
  std::printf(
      "threads of the process: %d before, %d after the release, %d after the solves; "
      "relative residuals after: CHOLMOD %.2e, UMFPACK %.2e\n",
      before, after, afterSolves, rx, ry);
  // OpenBLAS (its pthread build, install-deps.sh) on more than one core starts idle threads when
  // it is loaded: they are gone. Another BLAS: nothing to release.
  if (dlsym(RTLD_DEFAULT, "blas_thread_shutdown_") && std::thread::hardware_concurrency() >= 2)
    EXPECT_LT(after, before);
  else
    EXPECT_EQ(after, before);
  EXPECT_EQ(afterSolves, after);  // one BLAS thread: none started again
  EXPECT_LE(rx, 1e-12);
  EXPECT_LE(ry, 1e-12);
  for (int i = 0; i < b.size(); ++i) {
    ASSERT_EQ(std::bit_cast<std::uint64_t>(x1[i]), std::bit_cast<std::uint64_t>(x0[i])) << i;
    ASSERT_EQ(std::bit_cast<std::uint64_t>(y1[i]), std::bit_cast<std::uint64_t>(y0[i])) << i;
  }
}
