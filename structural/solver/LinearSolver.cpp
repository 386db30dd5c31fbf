#include "solver/LinearSolver.hpp"

#include <algorithm>

namespace chute {

LinearSolver::LinearSolver(bool preferCholesky, Timings& timings)
    : kind_(preferCholesky ? Kind::Cholmod : Kind::Umfpack), timings_(&timings) {}

LinearSolver::~LinearSolver() = default;

bool LinearSolver::factorize(const SparseMatrix& A) {
  ScopedTimer timer(timings_->factorisation);
  ++timings_->factorisations;
  if (kind_ == Kind::Cholmod) {
    if (!cholmod_) {
      cholmod_ = std::make_unique<Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower>>();
      // A matrix that is not positive definite is an expected outcome here (we fall back to LU),
      // not something for CHOLMOD to print.
      cholmod_->cholmod().print = 0;
    }
    if (!analysed_) {
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
  if (!umfpack_) umfpack_ = std::make_unique<Eigen::UmfPackLU<SparseMatrix>>();
  if (!analysed_) {
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

bool LinearSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  ScopedTimer timer(timings_->solve);
  ++timings_->solves;
  if (kind_ == Kind::Cholmod) {
    x = cholmod_->solve(b);
    if (cholmod_->info() != Eigen::Success) return false;
  } else {
    x = umfpack_->solve(b);
    if (umfpack_->info() != Eigen::Success) return false;
  }
  return x.allFinite();
}

}  // namespace chute
