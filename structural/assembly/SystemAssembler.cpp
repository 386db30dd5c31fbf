#include "assembly/SystemAssembler.hpp"

namespace chute {

void SystemAssembler::buildPattern(std::vector<std::vector<int>> nodeCliques) {
  cliques_ = std::move(nodeCliques);
  patternBuilt_ = false;
  matrix_ = SparseMatrix();
  residual_.setZero(dofs_->numEquations());
}

void SystemAssembler::ensurePattern() {
  if (patternBuilt_) return;
  const int n = dofs_->numEquations();
  std::vector<Eigen::Triplet<double, int>> trip;
  for (int e = 0; e < n; ++e) trip.emplace_back(e, e, 0.0);  // diagonal always present
  for (const auto& clique : cliques_)
    for (int a : clique)
      for (int b : clique)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) {
            const int ei = dofs_->eq(a, i), ej = dofs_->eq(b, j);
            if (ei >= 0 && ej >= 0) trip.emplace_back(ei, ej, 0.0);
          }
  matrix_.resize(n, n);
  matrix_.setFromTriplets(trip.begin(), trip.end());
  matrix_.makeCompressed();
  cliques_ = {};
  patternBuilt_ = true;
}

void SystemAssembler::sharePatternOf(const SystemAssembler& other) {
  matrix_ = other.matrix_;
  cliques_ = {};
  patternBuilt_ = other.patternBuilt_;
}

void SystemAssembler::begin(bool wantMatrix) {
  beginWithoutClearing(wantMatrix);
  clearResidual();
}

void SystemAssembler::beginWithoutClearing(bool wantMatrix) {
  if (wantMatrix) ensurePattern();
  wantMatrix_ = wantMatrix;
  if (wantMatrix) std::fill(matrix_.valuePtr(), matrix_.valuePtr() + matrix_.nonZeros(), 0.0);
}

void SystemAssembler::accumulateWork(SystemAssembler& other) {
  work_ += other.work_;
  other.work_ = WorkCounters{};
}

void SystemAssembler::beginOn(const std::vector<int>& eqs) {
  wantMatrix_ = false;
  if (residual_.size() != dofs_->numEquations()) residual_.setZero(dofs_->numEquations());
  for (int e : eqs) residual_[e] = 0.0;
}

void SystemAssembler::accumulate(SystemAssembler& other) {
  residual_ += other.residual_;
  if (wantMatrix_ && other.wantMatrix_) {
    double* v = matrix_.valuePtr();
    const double* w = other.matrix_.valuePtr();
    for (long k = 0; k < matrix_.nonZeros(); ++k) v[k] += w[k];
  }
  accumulateWork(other);
}

}  // namespace chute
