#pragma once
// Fabric contact as a term of the equations (docs/contact.md): fabric against fabric (within a
// canopy, between the canopies of a cluster, the slider against the canopy) and lines against
// fabric, between the primitives of the sets a case's [contact] names. The broad phase
// (BroadPhase, CT10) keeps the candidate pairs and the term a near list of them; each evaluation
// computes the distance of the near pairs its motion could have brought within the contact
// thickness and adds, for those closer, the penalty and damping of CT4-CT6 with the stiffness of
// CT9, and for the pairs in contact at the step's start their lagged friction (CT7). The
// integrators know nothing of it: residual only for the explicit path, the consistent Jacobian cx
// dr/dx + cv dr/dv for the implicit ones, whose sparsity pattern follows the candidate list
// (Term::updateCouplings). The penalty's energy is strain energy in the energy balance; damping and
// friction only take energy out.
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <vector>

#include "assembly/Term.hpp"
#include "kernels/ContactFriction.hpp"
#include "kernels/ContactPotential.hpp"
#include "model/Model.hpp"
#include "terms/contact/BroadPhase.hpp"
#include "terms/contact/ContactMesh.hpp"

namespace chute {

class SlidingGroupState;

class ContactTerm final : public Term {
 public:
  // groups: the sliding groups' states, one per group of the model in order (the elements their
  // sliders are on bend the lines).
  ContactTerm(const Model& m, std::vector<const SlidingGroupState*> groups);
  ~ContactTerm() override;
  const char* name() const override { return "contact"; }
  bool loadDependent() const override { return false; }
  // Damping makes the position derivative unsymmetric; penalty and friction alone are symmetric.
  bool symmetricJacobian() const override { return m_->contact.dampingRatio == 0.0; }
  void addCouplings(std::vector<std::vector<int>>& cliques) const override;
  bool dynamicCouplings() const override { return true; }
  bool updateCouplings(const Eigen::VectorXd& x) override;
  void assemble(const EvalPoint& p, SystemAssembler& out) override;
  void addEnergy(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double t,
                 EnergyBreakdown& e) const override;

  bool hasHistory() const override { return true; }
  void commit(const CommitPoint& c) override;
  void revert() override;
  void save(History& h) const override;
  void load(HistoryReader& h) override;

  // The explicit path's stable step (EX5, CT12): adds to the nodal stiffness bound S (one entry
  // per node of the model) the row sums 2 k |w_i| of every pair in contact at x. A pair that
  // comes into contact before the next estimate (4 steps) adds one pair's k, about 1/400 of its
  // nodes' bound at the default scale: the safety factor covers it.
  void addStiffnessBound(const Eigen::VectorXd& x, double t, const std::vector<char>& free,
                         std::vector<double>& S) const override;
  bool stiffnessBoundOfPositions() const override { return false; }  // reads the contact pairs

  // What the run met (summary.json "contact").
  struct Record {
    long builds = 0;         // broad-phase builds (candidate lists)
    long treeBuilds = 0;     // trees built afresh (the others refitted)
    long candidates = 0;     // candidate pairs of the current list
    long largestActive = 0;  // most pairs in contact at one evaluation
    double closest = 1.0;    // least d / dHat met in a step's evaluation
    // CT13: the largest approach of a pair in contact over one step, as a fraction of dHat
    // (-ddot dt / dHat), and the largest kinetic energy of an approach over the energy that
    // stops it (m ddot^2 / (k dHat^2)); above 1 a pair may be pushed through.
    double largestApproachPerStep = 0.0;
    double largestApproachEnergy = 0.0;
  };
  const Record& record() const { return record_; }
  const contact::ContactMesh& mesh() const { return *mesh_; }
  const contact::BroadPhase& broadPhase() const { return *broadPhase_; }
  // The stiffness k of CT9 at every node of the model (0 at nodes that take no part).
  const std::vector<double>& nodeStiffness() const { return nodeStiffness_; }

 private:
  struct Pair {
    kernels::ContactPairKind kind;
    std::array<int, 4> nodes;
    int list = 0, first = 0, second = 0;  // which candidate list (0 pt, 1 ee, 2 le) and entry
    int sub = 0;  // a line element bent at its slider: its segment 1 or 2 (0: unbent)
    // One number per pair, increasing in the order the lists are walked (CT15's table).
    std::int64_t key() const {
      return (static_cast<std::int64_t>(list) << 60) | (static_cast<std::int64_t>(first) << 31) |
             (static_cast<std::int64_t>(second) << 2) | static_cast<std::int64_t>(sub);
    }
  };
  struct Lag {
    kernels::ContactPairKind kind;
    std::array<int, 4> nodes;
    int list = 0, first = 0, second = 0;
    kernels::FrictionLag lag;
  };
  // The slider node on each line element now (-1: none).
  void slidersNow(std::vector<int>& sliders) const;
  // Whether the last build covers x (every node within skin / 2 of it, the same sliders); fills
  // `moved` with each node's motion since the build.
  bool covered(const Eigen::VectorXd& x, const std::vector<int>& sliders,
               std::vector<double>& moved) const;
  void refresh(const Eigen::VectorXd& x);
  double nearSkin() const;
  void nearList(const Eigen::VectorXd& x);
  Eigen::VectorXd unpacked(const Eigen::VectorXd& packed) const;
  template <class F>
  void forEachNear(const std::vector<double>& moved, double reach, F&& f) const;
  struct Near;
  template <class F>
  void forEachNearOf(const std::vector<Near>& list, const std::vector<double>& moved, double reach,
                     F&& f) const;
  void candidatesAtBuild();
  template <class F>
  void forEachPairWithin(const Eigen::VectorXd& x, double reach, F&& f) const;
  // f(pair) for every candidate pair of `bp` (line elements bent at a slider as their two
  // segments), in the lists' order.
  template <class F>
  void forEachPair(const contact::BroadPhase& bp, F&& f) const;
  double pairStiffness(const std::array<int, 4>& n) const;
  double pairMass(kernels::ContactPairKind kind, const std::array<int, 4>& n) const;
  static double mollifierThreshold(kernels::ContactPairKind kind,
                                   const std::array<kernels::Vec3, 4>& xs);
  bool lagCovered(const std::vector<Lag>& lag) const;

  const Model* m_;
  std::vector<const SlidingGroupState*> groups_;
  std::unique_ptr<contact::ContactMesh> mesh_;
  std::unique_ptr<contact::BroadPhase> broadPhase_;
  struct Near {
    Pair pair;
    double distance;   // where the list was made
    double thickness;  // the pair's own (CT15)
    double mollifier;  // CT5's threshold on the edges where the list was made (edge-edge pairs)
  };
  // CT15: the pairs closer than dHat at the start, with their own thickness (sorted by key);
  // committed, and as the last step's evaluation would leave it.
  using Thickness = std::pair<std::int64_t, double>;
  std::vector<Thickness> startGaps_, trialStartGaps_;
  double thicknessOf(const Pair& p) const;
  void raiseStartGap(const Pair& p, double distance);
  void startGapsAt(const Eigen::VectorXd& x0);
  void nearThicknesses();
  std::vector<Near> near_;  // the candidates within dHat + the near skin at nearAt_ (CT10)
  // The candidates within dHat + skin at the last build, with their distance there (CT10).
  std::vector<Near> candidates_;
  long candidatesBuild_ = -1;  // the build they are of (BroadPhase::builds())
  std::vector<double> moved_;  // per node: motion since the near list, at the last refresh
  // Where the mesh's nodes were when the near list was made (packed, ContactMesh::nodes()
  // order), committed; and how far each was then from the candidate lists' build.
  Eigen::VectorXd nearAt_, committedNearAt_;
  std::vector<double> nearFromBuild_;
  std::vector<int> slidersScratch_;
  // Near lists made (CT10), and how many there were when the lists were last committed.
  long nearLists_ = 0, committedNearLists_ = -1;
  std::vector<double> nodeStiffness_, nodeMass_;
  contact::BuildState committedBuild_;
  std::vector<Lag> lag_, trialLag_;
  std::vector<double> lagShare_;  // per node: sum of |w_i| over the lagged pairs (explicit cap)  //
                                  // committed (the step's start) and of the last step evaluation
  bool couplingsChanged_ = true;
  long buildsSeen_ = 0;
  Record record_;
};

}  // namespace chute
