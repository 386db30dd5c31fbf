#pragma once
// Sparse direct solves through SuiteSparse: CHOLMOD for symmetric positive definite matrices,
// UMFPACK otherwise; on request (NS2) Eigen's simplicial LDL^T of the symmetric part. The symbolic
// analysis is done once per pattern and reused (again when the pattern changes); a failed Cholesky
// (indefinite or singular matrix) falls back to UMFPACK for the rest of the run.
#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <Eigen/UmfPackSupport>
#include <memory>
#include <string>
#include <vector>

#include "assembly/SystemAssembler.hpp"
#include "solver/Timings.hpp"

namespace chute {

// The BLAS library's idle threads stopped, unless the user asked for threads (OPENBLAS_NUM_THREADS
// or OMP_NUM_THREADS set): OpenBLAS starts them when it is loaded and they spin for about 0.1 s
// on the cores the explicit step's two threads use, while chute's solvers use one BLAS thread
// (LinearSolver.cpp). A no-op with another BLAS. Called by the command first thing.
void releaseBlasThreads();

class LinearSolver {
 public:
  enum class Kind { Cholmod, Umfpack, SymmetricPart };

  // preferCholesky: the matrix is symmetric by construction (all terms say so).
  LinearSolver(bool preferCholesky, Timings& timings);
  ~LinearSolver();

  // Factorises A (analysing its pattern the first time). Returns false if singular.
  bool factorize(const SparseMatrix& A);
  // Solves A x = b with the last factorisation; false on failure or non-finite result.
  bool solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);

  Kind kind() const { return kind_; }
  // The kind asked for at the start (kind() differs after a fall-back to LU).
  Kind preferred() const { return preferred_; }
  // LU from now on (a restart of a run whose Cholesky fell back to LU).
  void useLU() {
    if (kind_ != Kind::Umfpack) kind_ = Kind::Umfpack, analysed_ = false;
  }
  std::string kindName() const {
    return kind_ == Kind::Cholmod   ? "cholmod"
           : kind_ == Kind::Umfpack ? "umfpack"
                                    : "ldlt_symmetric_part";
  }
  // LDL^T of the symmetric part (A + A^T) / 2 from now on (solver.linear_solver =
  // "symmetric_part"): an approximate tangent whose error, the skew part, Newton absorbs.
  void useSymmetricPart() {
    if (kind_ != Kind::SymmetricPart) kind_ = preferred_ = Kind::SymmetricPart, analysed_ = false;
  }
  long analyses() const { return analyses_; }

 private:
  Kind kind_, preferred_;
  bool analysed_ = false;
  long analyses_ = 0;
  Timings* timings_;
  std::unique_ptr<Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower>> cholmod_;
  std::unique_ptr<Eigen::UmfPackLU<SparseMatrix>> umfpack_;
  std::unique_ptr<Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower>> ldlt_;
  SparseMatrix symmetricPart_;
  std::vector<int> transposed_;  // index of entry (j, i) for entry (i, j) in A's storage
  bool factorizeSymmetricPart(const SparseMatrix& A);
  // The pattern of the last analysis (a matrix with another is analysed again).
  std::vector<int> outer_, inner_;
  bool samePattern(const SparseMatrix& A) const;
  void rememberPattern(const SparseMatrix& A);
};

}  // namespace chute
