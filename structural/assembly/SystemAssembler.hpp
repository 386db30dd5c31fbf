#pragma once
// The one local -> global assembly path: every term scatters its element residual and element
// matrix through add(), with one dof ordering (node by node, xyz), into a sparsity pattern that
// is built once and covers every coupling any term can ever create.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "assembly/WorkCounters.hpp"
#include "model/Model.hpp"

namespace chute {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

class SystemAssembler {
 public:
  explicit SystemAssembler(const DofMap& dofs) : dofs_(&dofs) {}

  // Node cliques: every pair of nodes inside one clique may couple. The pattern is built when
  // a matrix is first asked for (begin(true)): residual-only runs (the explicit path) never
  // build it.
  void buildPattern(std::vector<std::vector<int>> nodeCliques);
  // The pattern of another assembler, built (the second part of a split assembly).
  void sharePatternOf(const SystemAssembler& other);
  bool hasPattern() const { return patternBuilt_; }

  void begin(bool wantMatrix);
  // begin() in two: the mode first, the residual's clearing later (by the thread that then
  // assembles into it: the clearing of each part's residual on its own thread).
  void beginWithoutClearing(bool wantMatrix);
  void clearResidual() { residual_.setZero(); }
  // The second part's residual added to this one's over equations [begin, end) (accumulate's
  // residual sum in pieces, which may run at once on different threads), and its work counters,
  // which it clears (accumulateWork: once, after the pieces).
  void accumulateResidual(const SystemAssembler& other, int begin, int end) {
    residual_.segment(begin, end - begin) += other.residual_.segment(begin, end - begin);
  }
  void accumulateWork(SystemAssembler& other);
  // A residual-only begin() for terms that write only to the equations eqs (those of their
  // couplings' nodes, addCouplings): only those entries are cleared, the others are zero from the
  // first begin and stay so. For an assembler used only by such terms (the explicit step's
  // moving mass, a few line nodes, at every step): no clearing of the whole residual.
  void beginOn(const std::vector<int>& eqs);
  // Adds what another assembler with the same pattern gathered since its begin() (the second
  // part of a split assembly) and its work counters, which it clears.
  void accumulate(SystemAssembler& other);

  template <int N>
  void add(const std::array<int, N>& nodes, const Eigen::Matrix<double, 3 * N, 1>& r,
           const Eigen::Matrix<double, 3 * N, 3 * N>* J) {
    // The residual node by node, entry by entry in the element's order (the same sums as entry
    // by entry): a node whose three dofs are free, nearly every node, has three consecutive
    // equations, found with one look-up and no test per entry; the explicit path scatters every
    // element this way at every step.
    double* residual = residual_.data();  // loaded once, not at every entry
    for (int i = 0; i < N; ++i) {
      if (const int e = dofs_->freeNodeEq(nodes[i]); e >= 0) {
        residual[e] += r[3 * i];
        residual[e + 1] += r[3 * i + 1];
        residual[e + 2] += r[3 * i + 2];
        continue;
      }
      for (int k = 0; k < 3; ++k)
        if (const int e = dofs_->eq(nodes[i], k); e >= 0) residual[e] += r[3 * i + k];
    }
    if (full_)
      for (int i = 0; i < N; ++i) full_->segment<3>(3 * nodes[i]) += r.template segment<3>(3 * i);
    if (!J || !wantMatrix_) return;
    std::array<int, 3 * N> eq;
    for (int i = 0; i < N; ++i)
      for (int k = 0; k < 3; ++k) eq[3 * i + k] = dofs_->eq(nodes[i], k);
    // Node block by node block: a node's free dofs have consecutive equation numbers and the
    // pattern holds every dof pair of a clique, so within a column the rows of node a are
    // consecutive entries. One search per (node a, column) instead of one per entry.
    const int* inner = matrix_.innerIndexPtr();
    const int* outer = matrix_.outerIndexPtr();
    double* values = matrix_.valuePtr();
    for (int j = 0; j < 3 * N; ++j) {
      const int col = eq[j];
      if (col < 0) continue;
      const int* begin = inner + outer[col];
      const int* end = inner + outer[col + 1];
      for (int a = 0; a < N; ++a) {
        int k0 = 0;
        while (k0 < 3 && eq[3 * a + k0] < 0) ++k0;
        if (k0 == 3) continue;
        const int* pos = std::lower_bound(begin, end, eq[3 * a + k0]);
        if (pos == end || *pos != eq[3 * a + k0]) {
          outsidePattern(eq[3 * a + k0], col);
          continue;
        }
        double* v = values + (pos - inner);
        for (int k = k0; k < 3; ++k)
          if (eq[3 * a + k] >= 0) *v++ += (*J)(3 * a + k, j);
      }
    }
  }

  // The residual r added to each of the element's nodes (residual only): what add() does with
  // r repeated node by node, the same sums, without forming the repeated vector (a face's
  // pressure and drag on the explicit path, every face at every step).
  template <int N>
  void addToEachNode(const std::array<int, N>& nodes, const Eigen::Vector3d& r) {
    double* residual = residual_.data();
    for (int i = 0; i < N; ++i) {
      if (const int e = dofs_->freeNodeEq(nodes[i]); e >= 0) {
        residual[e] += r[0];
        residual[e + 1] += r[1];
        residual[e + 2] += r[2];
        continue;
      }
      for (int k = 0; k < 3; ++k)
        if (const int e = dofs_->eq(nodes[i], k); e >= 0) residual[e] += r[k];
    }
    if (full_)
      for (int i = 0; i < N; ++i) full_->segment<3>(3 * nodes[i]) += r;
  }

  // The residual r(i) at node nodes[i] for each i in [begin, end) (residual only): add<1> node
  // after node, the same sums, with the test for capturing all dofs made once for the run instead
  // of at every node (a term's per-node loads: the airflow's inside pressure at every canopy node
  // of every step). r is called exactly once per node, in order.
  template <class R>
  void addPerNode(const int* nodes, size_t begin, size_t end, R&& r) {
    if (full_)
      addPerNodeTo<true>(nodes, begin, end, r);
    else
      addPerNodeTo<false>(nodes, begin, end, r);
  }

  // A coupling the pattern lacks (a term that did not declare its cliques): a programming
  // error, reported rather than written to the wrong entry.
  [[noreturn]] static void outsidePattern(int row, int col) {
    throw std::logic_error("SystemAssembler: entry (" + std::to_string(row) + ", " +
                           std::to_string(col) + ") is outside the sparsity pattern");
  }

  // While set, every residual is also summed over all dofs, constrained ones included (for
  // reactions and applied loads in the output); nullptr switches it off.
  void captureAllDofs(Eigen::VectorXd* full) { full_ = full; }
  // While set (an explicit step whose loads the energy balance keeps, StructuralSystem::
  // captureStepLoads), a term that adds loads inside its own residual (the membranes' fused face
  // loads, FaceLoadFusion.hpp) also sums those loads here over all dofs.
  void captureFusedLoads(Eigen::VectorXd* loads) { fusedLoads_ = loads; }
  Eigen::VectorXd* fusedLoads() const { return fusedLoads_; }

  const Eigen::VectorXd& residual() const { return residual_; }
  const SparseMatrix& matrix() const { return matrix_; }  // empty before the first begin(true)
  bool wantMatrix() const { return wantMatrix_; }
  long nonZeros() const { return matrix_.nonZeros(); }
  // Terms count their kernel evaluations here.
  WorkCounters& work() { return work_; }
  const WorkCounters& work() const { return work_; }

 private:
  void ensurePattern();
  template <bool Full, class R>
  void addPerNodeTo(const int* nodes, size_t begin, size_t end, R& r) {
    // Loaded once: the compiler reloads members through this at every node otherwise.
    double* residual = residual_.data();
    double* full = Full ? full_->data() : nullptr;
    const int* freeNodeEq = dofs_->freeNodeEqs();
    for (size_t i = begin; i < end; ++i) {
      const int n = nodes[i];
      const Eigen::Vector3d f = r(i);
      if constexpr (Full)
        for (int k = 0; k < 3; ++k) full[3 * n + k] += f[k];
      if (const int e = freeNodeEq[n]; e >= 0) {
        residual[e] += f[0];
        residual[e + 1] += f[1];
        residual[e + 2] += f[2];
        continue;
      }
      for (int k = 0; k < 3; ++k)
        if (const int e = dofs_->eq(n, k); e >= 0) residual[e] += f[k];
    }
  }

  const DofMap* dofs_;
  std::vector<std::vector<int>> cliques_;  // until the pattern is built
  bool patternBuilt_ = false;
  SparseMatrix matrix_;
  Eigen::VectorXd residual_;
  bool wantMatrix_ = true;
  Eigen::VectorXd* full_ = nullptr;
  Eigen::VectorXd* fusedLoads_ = nullptr;
  WorkCounters work_;
};

}  // namespace chute
