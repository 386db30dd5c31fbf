#include "solver/LinearSolver.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>

namespace chute {

namespace {
// SuiteSparse does its dense fronts in BLAS. With OpenBLAS (Debian's libopenblas0-pthread, the
// libblas.so.3 alternative install-deps.sh selects) a second thread barely pays here and costs a
// lot when the machine is busy (OpenBLAS threads spin): measured on the bench canopy, one
// factorisation at 91k equations 0.68 s with 2 threads and 0.73 s with 1 on a quiet machine, but
// 5.2 s with 2 threads at load 6 on 2 cores; at 178k, 1 thread 2.07 s against 2.45 s with 2
// (bench/README.md). So one thread, unless the user set OPENBLAS_NUM_THREADS or
// OMP_NUM_THREADS. Looked up at run time: with another BLAS it is a no-op.
bool blasThreadsAsked() {
  return std::getenv("OPENBLAS_NUM_THREADS") || std::getenv("OMP_NUM_THREADS");
}

// Set by releaseBlasThreads: one thread already, and none running (setting it again would start
// OpenBLAS's pool anew: its set function re-creates a pool that was shut down).
std::atomic<bool> blasReleased{false};

// OpenBLAS's thread count setter, looked up once (nullptr with another BLAS).
using SetThreads = void (*)(int);
SetThreads openblasSetThreads() {
  static const auto set =
      reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  return set;
}

void chooseBlasThreads(int /*equations*/) {
  if (blasThreadsAsked() || blasReleased.load()) return;
  if (const auto set = openblasSetThreads()) set(1);
}
}  // namespace

void releaseBlasThreads() {
  if (blasThreadsAsked()) return;
  // OpenBLAS's own entry points, looked up at run time. With one thread set first, its
  // single-threaded calls start none again (nor does chooseBlasThreads after this);
  // blas_thread_shutdown_ (what OpenBLAS itself calls around a fork) joins the idle ones.
  // Measured on the C-9 slider case, two threads: 0.934 of the wall time with the spinning pool
  // (OPENBLAS_NUM_THREADS=1 in the environment: 0.957).
  using Shutdown = int (*)();
  const auto set = openblasSetThreads();
  const auto shutdown = reinterpret_cast<Shutdown>(dlsym(RTLD_DEFAULT, "blas_thread_shutdown_"));
  if (!set || !shutdown) return;
  set(1);
  shutdown();
  blasReleased.store(true);
}

LinearSolver::LinearSolver(bool preferCholesky, Timings& timings)
    : kind_(preferCholesky ? Kind::Cholmod : Kind::Umfpack),
      preferred_(kind_),
      timings_(&timings) {}

LinearSolver::~LinearSolver() = default;

bool LinearSolver::factorize(const SparseMatrix& A) {
  ScopedTimer timer(timings_->factorisation);
  ++timings_->factorisations;
  // A pattern that moved (contact pairs, Term::updateCouplings) is analysed afresh.
  if (analysed_ && !samePattern(A)) analysed_ = false;
  if (!analysed_) rememberPattern(A);
  if (kind_ == Kind::SymmetricPart) {
    if (factorizeSymmetricPart(A)) return true;
    // A zero pivot without pivoting: LU for good.
    kind_ = Kind::Umfpack;
    analysed_ = false;
    ldlt_.reset();
  }
  if (kind_ == Kind::Cholmod) {
    if (!cholmod_) {
      cholmod_ = std::make_unique<Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower>>();
      // A matrix that is not positive definite is an expected outcome here (we fall back to LU),
      // not something for CHOLMOD to print.
      cholmod_->cholmod().print = 0;
    }
    if (!analysed_) {
      chooseBlasThreads(static_cast<int>(A.rows()));
      cholmod_->analyzePattern(A);
      analysed_ = true;
      ++analyses_;
    }
    cholmod_->factorize(A);
    if (cholmod_->info() == Eigen::Success) return true;
    // Not positive definite (a slack cable, a massless node): fall back to LU for good.
    kind_ = Kind::Umfpack;
    analysed_ = false;
    cholmod_.reset();
  }
  if (!umfpack_) {
    umfpack_ = std::make_unique<Eigen::UmfPackLU<SparseMatrix>>();
    // No iterative refinement: Newton's next iteration corrects what a refinement step would,
    // and UMFPACK's default two steps made a solve cost 15-20 % of a factorisation (bench
    // scaling) instead of a few per cent.
    umfpack_->umfpackControl()(UMFPACK_IRSTEP) = 0;
  }
  if (!analysed_) {
    chooseBlasThreads(static_cast<int>(A.rows()));
    // UMFPACK's symbolic analysis looks at the values too. Analyse the pattern with unit values,
    // so the ordering depends on the pattern alone: a restarted run then factorises exactly as
    // the run it continues (bit for bit), whatever matrix it meets first.
    SparseMatrix pattern = A;
    std::fill(pattern.valuePtr(), pattern.valuePtr() + pattern.nonZeros(), 1.0);
    umfpack_->analyzePattern(pattern);
    analysed_ = true;
    ++analyses_;
  }
  umfpack_->factorize(A);
  return umfpack_->info() == Eigen::Success;
}

bool LinearSolver::samePattern(const SparseMatrix& A) const {
  const long n = A.cols(), nnz = A.nonZeros();
  return n + 1 == static_cast<long>(outer_.size()) && nnz == static_cast<long>(inner_.size()) &&
         std::equal(outer_.begin(), outer_.end(), A.outerIndexPtr()) &&
         std::equal(inner_.begin(), inner_.end(), A.innerIndexPtr());
}

void LinearSolver::rememberPattern(const SparseMatrix& A) {
  outer_.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.cols() + 1);
  inner_.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
}

bool LinearSolver::factorizeSymmetricPart(const SparseMatrix& A) {
  if (!analysed_) {
    // The pattern is structurally symmetric (cliques couple both ways): find each entry's
    // transposed partner once.
    const int n = static_cast<int>(A.cols());
    transposed_.assign(A.nonZeros(), -1);
    const int* outer = A.outerIndexPtr();
    const int* inner = A.innerIndexPtr();
    for (int j = 0; j < n; ++j)
      for (int k = outer[j]; k < outer[j + 1]; ++k) {
        const int i = inner[k];
        const int* pos = std::lower_bound(inner + outer[i], inner + outer[i + 1], j);
        if (pos == inner + outer[i + 1] || *pos != j) return false;  // not symmetric in pattern
        transposed_[k] = static_cast<int>(pos - inner);
      }
    symmetricPart_ = A;
    ldlt_ = std::make_unique<Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower>>();
    ldlt_->analyzePattern(symmetricPart_);
    analysed_ = true;
    ++analyses_;
  }
  const double* a = A.valuePtr();
  double* s = symmetricPart_.valuePtr();
  for (size_t k = 0; k < transposed_.size(); ++k) s[k] = 0.5 * (a[k] + a[transposed_[k]]);
  ldlt_->factorize(symmetricPart_);
  return ldlt_->info() == Eigen::Success;
}

bool LinearSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  ScopedTimer timer(timings_->solve);
  ++timings_->solves;
  if (kind_ == Kind::SymmetricPart) {
    x = ldlt_->solve(b);
    if (ldlt_->info() != Eigen::Success) return false;
  } else if (kind_ == Kind::Cholmod) {
    x = cholmod_->solve(b);
    if (cholmod_->info() != Eigen::Success) return false;
  } else {
    x = umfpack_->solve(b);
    if (umfpack_->info() != Eigen::Success) return false;
  }
  return x.allFinite();
}

}  // namespace chute
