#pragma once
// Internal force, inertia and gravity of every membrane element (docs/formulation.md section 5),
// with the tension-field model where its set asks for it; keeps each element's last wrinkling
// state.
#include <array>
#include <cstdint>
#include <vector>

#include "assembly/Term.hpp"
#include "kernels/MembraneTriangleBatch.hpp"
#include "kernels/MembraneTriangleForce.hpp"
#include "kernels/StiffnessBound.hpp"
#include "kernels/TriangleFaceLoads.hpp"
#include "model/Model.hpp"
#include "terms/CanopyFlowTerm.hpp"
#include "terms/FaceLoadFusion.hpp"
#include "terms/NodeMassEnergy.hpp"

namespace chute {

class MembraneTerm final : public Term {
 public:
  explicit MembraneTerm(const Model& m);
  const char* name() const override { return "membranes"; }
  bool loadDependent() const override { return m_->hasGravity(); }  // gravity only
  void addCouplings(std::vector<std::vector<int>>& cliques) const override;
  void assemble(const EvalPoint& p, SystemAssembler& out) override;
  void addEnergy(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double t,
                 EnergyBreakdown& e) const override;
  // Elements [0, n/2) and [n/2, n): the halves of the energy balance's evaluation.
  void addEnergyHalf(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double t,
                     EnergyBreakdown& e, int half) const override;
  // Wrinkling state and principal stresses / strains of each element at the last assembly.
  struct ElementState {
    kernels::WrinkleState state = kernels::WrinkleState::Taut;
    Eigen::Vector2d principalStress = Eigen::Vector2d::Zero();
    Eigen::Vector2d principalStrain = Eigen::Vector2d::Zero();
    // True stress resultant, force per current width (kernels::MembraneResult).
    Eigen::Vector2d principalResultant = Eigen::Vector2d::Zero();
  };
  // A function of the current strain, recomputed at every assembly (not history); kept so that
  // output after a coupling checkpoint is restored shows the restored state. The principal
  // values are output only: an assembly keeps its positions, and they are computed from those
  // when asked for (four eigen-solves per quad were a tenth of a C-9 Newton iteration).
  const std::vector<ElementState>& elementStates() const;
  bool hasHistory() const override { return true; }
  void save(History& h) const override;
  void load(HistoryReader& h) override;
  void prepareFor(const IntegrationTraits& traits) override;
  void addStiffnessBound(const Eigen::VectorXd& x, double t, const std::vector<char>& free,
                         std::vector<double>& S) const override;
  void addStiffnessBoundHalf(const Eigen::VectorXd& x, double t, const std::vector<char>& free,
                             std::vector<double>& S, int half) const override;
  double assemblyCost() const override;
  bool assemblesApart() const override { return true; }
  // The explicit step's triangles in two halves of their batches (the quads with the second);
  // every other evaluation whole in the first half.
  bool assemblesInHalves() const override { return true; }
  void assembleHalf(const EvalPoint& p, SystemAssembler& out, int half) override;
  void beforeHalves(const EvalPoint& p, const SystemAssembler& out) override;
  bool afterHalves(const EvalPoint& p) override;
  void afterHalvesPart(const EvalPoint& p, SystemAssembler& out, int half) override;
  // P2: takes the pressure and face drag of the triangles whose set has at most one of each (and
  // one at least), to add to their forces on the explicit step's evaluations (fusedFaceLoads());
  // the pressure and face-drag terms are given the faces taken, to leave out then. None without
  // such triangles, or with mass damping (the explicit step's triangles are then not taken apart
  // from the element path).
  TakenFaces takeFaceLoads();
  // FL13: takes the airflow's loads of a canopy whose faces are all triangles, to add to their
  // forces on the explicit step's evaluations (CanopyFlowTerm::takenParameters, finishTaken*).
  // One canopy, and none where face loads were taken (P2), or with mass damping; false: left to
  // the airflow's term.
  bool takeCanopyFlow(CanopyFlowTerm& flow);
  // Elements around a node, for stress probes.
  std::vector<int> elementsAt(int node) const;

 private:
  template <int N>
  void assembleElement(int e, const kernels::MembraneReference<N>& ref, const EvalPoint& p,
                       SystemAssembler& out);
  // The internal force alone, residual only (the explicit step), and the element's weight when
  // the model has gravity.
  template <int N>
  void assembleInternalForce(int e, const kernels::MembraneReference<N>& ref, const EvalPoint& p,
                             SystemAssembler& out);
  // The explicit step's triangles, in refs3_'s order: what their force and weight need, side by
  // side (kernels/MembraneTriangleForce.hpp); the lumped triangles' energies read them too.
  struct ExplicitTriangle {
    std::array<int, 3> nodes;
    kernels::MembraneTriangleRecord force;
    std::array<double, 3> share;  // massSharesOf's, with or without gravity
  };
  std::vector<ExplicitTriangle> explicitTriangles_;  // made with the term
  // With a lumped mass: each node of a triangle with mass, and its triangles' shares' sum (M4).
  NodeMasses triangleNodeMass_;
  // The same records four at a time for the explicit step (kernels/MembraneTriangleBatch.hpp):
  // batch b holds triangles 4 b .. 4 b + 3, the last batch's missing lanes its last triangle
  // again. And the quads, which the explicit step takes after the triangles.
  std::vector<kernels::MembraneTriangleLanes> triangleLanes_;
  std::vector<int> quads_;
  // P2: per explicit triangle, the pressure and face drag taken (index into the model's
  // pressures and faceDrags, -1: none) and the pressure's factor for the element; empty: none
  // taken. Per batch the lanes' winds and steady parts, set once; their pressures and drags per
  // evaluation. The loads at the evaluation's time and load factor, per pressure and face drag.
  struct TakenLoad {
    int pressure = -1, drag = -1;
    double pressureFactor = 1.0;
  };
  std::vector<TakenLoad> taken_;
  std::vector<kernels::TriangleFaceLoadLanes> takenLanes_;
  std::vector<double> pressureNow_[2], dragNow_[2];  // per half (assembleHalf; whole: 0)
  long takenDrags_ = 0;                              // faces with a drag taken
  std::vector<long> takenPerPressure_;               // faces per pressure taken
  // What a taken load carries at the evaluation (0 where it has none), and all of a triangle's.
  double takenPressure(const TakenLoad& tl, int half) const {
    return tl.pressure >= 0 ? pressureNow_[half][tl.pressure] * tl.pressureFactor : 0.0;
  }
  double takenDrag(const TakenLoad& tl, int half) const {
    return tl.drag >= 0 ? dragNow_[half][tl.drag] : 0.0;
  }
  kernels::TriangleFaceLoadParameters takenParameters(size_t triangle, int half) const;
  void makeExplicitTriangles();
  // The explicit step's evaluation (EX2: residual only, a = 0, no mass damping).
  bool explicitPath(const EvalPoint& p, const SystemAssembler& out) const;
  // Its triangles of batches [b0, b1) into out, with the scratch of `half` (0: the whole pass).
  void assembleExplicitTriangles(const EvalPoint& p, SystemAssembler& out, size_t b0, size_t b1,
                                 int half);
  // FL13: the canopy whose airflow's loads were taken; per explicit triangle its nodes' slots in
  // that term ({-1, ...}: not the canopy's); per batch, the canopy's lanes and their slots.
  CanopyFlowTerm* flow_ = nullptr;
  std::vector<std::array<int, 3>> flowSlots_;
  std::vector<kernels::TriangleFlowBatch> flowLanes_;
  kernels::TriangleFlowAccumulators flowSums_[2];  // per half: the canopy's sums, lane by lane
  void assembleTrianglesWithFlow(const EvalPoint& p, SystemAssembler& out, size_t b0, size_t b1,
                                 int half);
  // The airflow's faces' sums once they are done (the whole pass's, or both halves').
  CanopyFlowTerm::FaceSums flowSums(bool halves) const;
  // The halves' evaluation takes the airflow's loads, with these parameters (beforeHalves).
  bool flowHalves_ = false;
  kernels::TriangleFlowParameters flowParameters_;
  // Per element, each node's share of its mass, rho t0 int N_i dA: the weight, made once when the
  // model has gravity (empty without).
  std::vector<std::array<double, 4>> massShare_;
  // Element k's shares: the row sums of its mass matrix (zero for a massless element).
  std::array<double, 4> massSharesOf(size_t k) const;
  // r -= load factor x the weight of an element with these mass shares on its nodes. Inlined:
  // outlined, r went through memory on every element of every explicit step (2.8 % of the step
  // on the generated C-9 against 1.2 % inline).
  template <int N>
  [[gnu::always_inline]] void addWeight(const double* share, double loadFactor,
                                        Eigen::Matrix<double, 3 * N, 1>& r) const {
    for (int i = 0; i < N; ++i) r.template segment<3>(3 * i) -= loadFactor * share[i] * m_->gravity;
  }
  // A triangle's forces r (its face load f, when it has one, already in them) with its weight
  // to the assembler, and f kept over all dofs where the energy balance asks (captured). Inlined:
  // every explicit triangle at every step.
  [[gnu::always_inline]] void scatterTriangle(const ExplicitTriangle& t,
                                              Eigen::Matrix<double, 9, 1>& r, const double* f,
                                              Eigen::VectorXd* captured, bool weighed,
                                              double loadFactor, SystemAssembler& out) const {
    if (captured && f)
      for (int i = 0; i < 3; ++i)
        for (int c = 0; c < 3; ++c) (*captured)[3 * t.nodes[i] + c] += f[c];
    if (weighed) addWeight<3>(t.share.data(), loadFactor, r);
    out.add<3>(t.nodes, r, nullptr);
  }
  // The same for lane l of a batch: its forces fs, its face load f (withLoad: it has one).
  [[gnu::always_inline]] void scatterLane(const kernels::TriangleLaneVectors& fs,
                                          const double (&f)[3][kernels::kTriangleLanes], int l,
                                          const ExplicitTriangle& t, bool withLoad,
                                          Eigen::VectorXd* captured, bool weighed,
                                          double loadFactor, SystemAssembler& out) const {
    Eigen::Matrix<double, 9, 1> r;
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < 3; ++c) r[3 * i + c] = fs.v[i][c][l];
    double load[3];
    const double* kept = nullptr;  // f is read only where there is a load to keep
    if (captured && withLoad) {
      for (int c = 0; c < 3; ++c) load[c] = f[c][l];
      kept = load;
    }
    scatterTriangle(t, r, kept, captured, weighed, loadFactor, out);
  }
  const Model* m_;
  std::vector<int> slot_;  // per element: index into refs3_ or refs4_
  std::vector<kernels::MembraneReference<3>> refs3_;
  std::vector<kernels::MembraneReference<4>> refs4_;
  mutable std::vector<ElementState> states_;
  // The reference part of each element's stable-step bound (EX6m), made for explicit steps.
  mutable std::vector<kernels::MembraneBoundReference> bound_;
  void makeBound() const;
  void addStiffnessBoundOver(const Eigen::VectorXd& x, size_t begin, size_t end,
                             std::vector<double>& S) const;
  // addEnergy over elements [begin, end) (the whole, or a half of addEnergyHalf).
  void addEnergyOver(const Eigen::VectorXd& x, const Eigen::VectorXd& v, size_t begin, size_t end,
                     EnergyBreakdown& e) const;
  // Positions of the last assembly, and whether states_' principal values are still to be
  // computed from them.
  Eigen::VectorXd lastX_;
  mutable bool principalsStale_ = false;
};

}  // namespace chute
