#pragma once
// Sparse direct solves through SuiteSparse: CHOLMOD for symmetric positive definite matrices,
// UMFPACK otherwise. The symbolic analysis is done once per pattern and reused; a failed
// Cholesky (indefinite or singular matrix) falls back to UMFPACK for the rest of the run.
#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>
#include <memory>
#include <string>

#include "assembly/SystemAssembler.hpp"
#include "solver/Timings.hpp"

namespace chute {

class LinearSolver {
 public:
  enum class Kind { Cholmod, Umfpack };

  // preferCholesky: the matrix is symmetric by construction (all terms say so).
  LinearSolver(bool preferCholesky, Timings& timings);
  ~LinearSolver();

  // Factorises A (analysing its pattern the first time). Returns false if singular.
  bool factorize(const SparseMatrix& A);
  // Solves A x = b with the last factorisation; false on failure or non-finite result.
  bool solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);

  Kind kind() const { return kind_; }
  // LU from now on (a restart of a run whose Cholesky fell back to LU).
  void useLU() {
    if (kind_ != Kind::Umfpack) kind_ = Kind::Umfpack, analysed_ = false;
  }
  std::string kindName() const { return kind_ == Kind::Cholmod ? "cholmod" : "umfpack"; }
  long analyses() const { return analyses_; }

 private:
  Kind kind_;
  bool analysed_ = false;
  long analyses_ = 0;
  Timings* timings_;
  std::unique_ptr<Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower>> cholmod_;
  std::unique_ptr<Eigen::UmfPackLU<SparseMatrix>> umfpack_;
};

}  // namespace chute
