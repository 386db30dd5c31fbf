#pragma once
// The discrete system of one scene: its dof map, the terms the scene needs (and only those),
// the sparsity pattern built once, and timing of assembly and search.
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "assembly/SystemAssembler.hpp"
#include "assembly/Term.hpp"
#include "assembly/TwoPartRunner.hpp"
#include "model/Model.hpp"
#include "solver/StructuralState.hpp"
#include "solver/Timings.hpp"
#include "terms/TermList.hpp"

namespace chute {

class StructuralSystem {
 public:
  // The terms of the model (terms/TermList.hpp); extraTerms: terms the model does not describe
  // (loads supplied by a coupled flow solver), which join the sparsity pattern like the others.
  StructuralSystem(const Model& model, TermOptions options,
                   std::vector<std::unique_ptr<Term>> extraTerms = {});
  // Not copied or moved: inTwoHalves_ holds this.
  StructuralSystem(const StructuralSystem&) = delete;
  StructuralSystem& operator=(const StructuralSystem&) = delete;

  const Model& model() const { return *model_; }
  const DofMap& dofs() const { return dofs_; }
  // Constrained dofs of s on their prescribed motion at s.t (fixed ones where they started):
  // positions, velocities and accelerations. Free dofs are left alone.
  void prescribeMotion(StructuralState& s) const;
  // The dofs without an equation (fixed or prescribed), in order.
  const std::vector<int>& constrainedDofs() const { return constrainedDofs_; }
  int numEquations() const { return dofs_.numEquations(); }

  // The state a run starts from: the model's positions X + u0, prescribed velocities on the
  // constrained dofs, zero acceleration (the integrator computes it), t = 0.
  StructuralState initialState() const;
  // Whether node i has a free dof (its rows are part of the free system).
  const std::vector<char>& freeNodes() const { return freeNode_; }
  // The nodes with a free dof that no term touches (no element, load or point mass): the
  // equations are singular there.
  const std::vector<int>& untouchedFreeNodes() const { return untouchedFreeNodes_; }

  // Tells every term which kind of integrator steps the system (Term::prepareFor), once.
  void prepareFor(const IntegrationTraits& traits);
  // Per node, the row sum S_i of the stiffness at x, t that bounds the explicit step's highest
  // frequency, omega^2 <= max S_i / m_i (EX5; the membranes' part an estimate, EX6m): the bounds
  // of the terms whose bound is a function of (x, t) alone added up in term order
  // (positionStiffnessBound), then those of the terms that read their state
  // (addStateStiffnessBound), so that the first part can be made elsewhere (alongside an assembly)
  // and give the same bits.
  std::vector<double> stiffnessBound(const Eigen::VectorXd& x, double t) const;
  std::vector<double> positionStiffnessBound(const Eigen::VectorXd& x, double t) const;
  // Where the assembly has two parts (hasTwoParts): positionStiffnessBound is made as each part's
  // sums (the part's terms in order, the halved term's half in each), the second part's then
  // added node by node to the first's. One part's, into S (sized and zeroed here), so that each
  // may be made on its own thread (after its part of an assembly: assemble's afterPart).
  bool hasTwoParts() const { return !secondPart_.empty(); }
  void positionStiffnessBoundPart(const Eigen::VectorXd& x, double t, int part,
                                  std::vector<double>& S) const;
  // The second part's bound added to the first's, node by node: positionStiffnessBound's sum.
  static void addBoundPart(std::vector<double>& first, const std::vector<double>& second);
  void addStateStiffnessBound(const Eigen::VectorXd& x, double t, std::vector<double>& S) const;
  // The largest of the terms' bounds on the squared frequencies of modes over many nodes
  // (Term::frequencySquaredBound), given the lumped nodal masses.
  double frequencySquaredBound(const Eigen::VectorXd& x, double t,
                               const std::vector<double>& nodalMass) const;

  // Discrete state updates (sliding search) for trial positions; returns the number of changes.
  int updateState(const Eigen::VectorXd& x);
  void assemble(const EvalPoint& p, bool wantMatrix);
  // The same, and alongside() after the part that finishes first, on its thread (after the whole
  // assembly without a split): work that reads what the assembly reads and writes nothing it
  // touches (the explicit step's lumped mass of the sliding elements, EX2), so that the same bits
  // come out on whichever thread it runs.
  // afterPart(part), where given and the assembly has two parts: after each part, on its thread.
  void assemble(const EvalPoint& p, bool wantMatrix, const std::function<void()>& alongside,
                const std::function<void(int)>* afterPart = nullptr);
  // The explicit step's assembly (residual only) whose residual is used in halves of the
  // equations, one on each thread: each part's residual is cleared on its own thread, and the
  // two parts' sum is left to useResidualInHalves, which makes it half by half just before each
  // half is used (no pass over all equations of its own). residual() is not to be read between.
  void assembleForHalves(const EvalPoint& p, const std::function<void()>& alongside,
                         const std::function<void(int)>* afterPart = nullptr);
  // use(begin, end) over equations [0, n/2) here and [n/2, n) on the second thread (one after the
  // other without one), each half of the residual complete when it is called. use must touch only
  // what belongs to its equations.
  void useResidualInHalves(const std::function<void(int, int)>& use);
  // The residual as use() may read it, over its own equations only.
  const Eigen::VectorXd& residualInHalves() const { return assembler_.residual(); }
  // first(begin, end), second(begin, end) over halves of [0, n) on the two threads (one after
  // the other without a second): the explicit step's passes over all dofs.
  void inHalves(int n, const std::function<void(int, int)>& use);
  // While on, every residual-only assembly of an explicit step (EvalPoint::explicitStep > 0) also
  // sums the residual of the terms that do external work over all dofs, kept with the step's end
  // time: the loads the step applied, which the energy balance's work takes at its window's end
  // (EB1) instead of evaluating them again.
  void captureStepLoads(bool on) { captureLoads_ = on; }
  // The residual of the loads the explicit step ending at t applied (over all dofs), or nullptr
  // when the last assembly was not such a step's or ended elsewhere.
  const Eigen::VectorXd* stepLoadsAt(double t) const {
    return capturedLoadsT_ == t ? &partLoads_[0] : nullptr;
  }
  // Whether assemble() splits the terms into two parts (docs/performance.md, "Two threads").
  bool assemblesInTwoParts() const { return !secondPart_.empty(); }
  // Assemblies whose two parts ran on two threads, and one after the other (0, 0 without a
  // split or without a second hardware thread).
  long concurrentAssemblies() const { return runner_ ? runner_->concurrentRuns() : 0; }
  long serialAssemblies() const { return runner_ ? runner_->serialRuns() : 0; }
  // first() here and second() on the assembly's second thread when it has one (and the
  // assemblies run on two threads now), else one after the other: for evaluations that do not
  // touch each other's data (the energy balance's load residual and energy), whose results are
  // the same bits either way.
  void runTwo(const std::function<void()>& first, const std::function<void()>& second);
  const Eigen::VectorXd& residual() const {
    if (sumPending_) residualNotSummed();
    return assembler_.residual();
  }
  const SparseMatrix& matrix() const { return assembler_.matrix(); }
  bool symmetric() const;
  // The terms' event sources taken together (assembly/EventSource.hpp): the least fraction,
  // any change, the largest floor.
  double passageFraction(const Eigen::VectorXd& x, const Eigen::VectorXd& dx);
  double stepEventFraction(const Eigen::VectorXd& start, const Eigen::VectorXd& motion);
  bool onConverged(Eigen::VectorXd& x);
  bool crossNow(Eigen::VectorXd& x);
  bool drivesKinks() const;
  int crossDriven(const Eigen::VectorXd& from, Eigen::VectorXd& to);
  double displacementFloor() const;
  // An explicit step moved the positions from x to xEnd (EX3): the sources that watch the motion
  // note the kinks passed and may move xEnd onto one reached (afterExplicitMotion), then every
  // term's updateState and every source's onConverged at xEnd. The same bits as those three one
  // after the other: where the watchers fall into groups that share no free node, the groups in
  // two parts (settleParts_), each part's watchers doing all of it in order, the parts at once
  // on two threads. Returns whether a source that does not watch the motion moved xEnd
  // (onConverged); else only the watchers' nodes (watchedDofs) moved.
  bool settleExplicitMotion(const Eigen::VectorXd& x, Eigen::VectorXd& xEnd);
  // Whether settleExplicitMotion has two parts (watchers in groups that share no free node).
  bool settlesInTwoParts() const { return !settleParts_[1].empty(); }
  // The dofs of the nodes of the watchers' couplings.
  const std::vector<int>& watchedDofs() const { return watchedDofs_; }

  // Nodal forces over all dofs at a converged state (for output): the support reactions
  // (the residual at constrained dofs, zero elsewhere) and the applied loads (gravity, pressure,
  // drag: the part of the residual scaled by the load factor).
  struct NodalForces {
    Eigen::VectorXd reaction, applied;
  };
  NodalForces nodalForces(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                          const Eigen::VectorXd& a, double t, bool inertia);

  // Over all dofs: the residual of the terms that do external work (Term::doesExternalWork), or
  // of every term when allTerms, at p (the energy balance).
  Eigen::VectorXd residualOverAllDofs(const EvalPoint& p, bool allTerms);

  EnergyBreakdown energy(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double t) const;
  // The same energies, the assembly's two parts' terms on its two threads (when it has them),
  // added part by part: for the energy balance, whose windows' loads now cost nothing (the same
  // value to round-off, not the same bits as energy()).
  EnergyBreakdown energyOnTwoThreads(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double t);
  EnergyBreakdown energy(const StructuralState& s) const { return energy(s.x, s.v, s.t); }

  // History (Term::commit / revert / save / load) of every term.
  void commit(const CommitPoint& c);
  void revert();
  // The one snapshot of a run's state: s with every term's history.
  SystemSnapshot saveState(const StructuralState& s) const;
  // Restores the terms' histories and returns the state; checks the snapshot against this
  // system first (sizes, term names, finite values) and throws HistoryError naming what is
  // wrong, before anything is changed.
  StructuralState loadState(const SystemSnapshot& snap);

  // Scatter equation-space vectors to / from full dof vectors.
  void addToDofs(const Eigen::VectorXd& eqVec, Eigen::VectorXd& dofVec, double scale = 1.0) const;
  Eigen::VectorXd gatherEquations(const Eigen::VectorXd& dofVec) const;

  const std::vector<std::unique_ptr<Term>>& terms() const { return list_.terms(); }
  // The terms by kind, for output that reports what a kind of term knows.
  const TermList& termList() const { return list_; }
  TermList& termList() { return list_; }

  // Work done so far, per kind of term (kernel evaluations, searches, energies, output frames).
  WorkCounters work() const {
    WorkCounters w = assembler_.work();
    w.energy = energyEvaluations_;
    return w;
  }
  WorkCounters& workCounters() { return assembler_.work(); }  // output code counts its frames

  Timings& timings() { return timings_; }
  const Timings& timings() const { return timings_; }

 private:
  const Model* model_;
  DofMap dofs_;
  std::vector<int> constrainedDofs_;  // the dofs without an equation, in order (prescribeMotion)
  std::vector<char> freeNode_;
  std::vector<int> untouchedFreeNodes_;
  TermList list_;
  const std::vector<std::unique_ptr<Term>>& terms_;  // list_'s
  std::vector<EventSource*> events_;
  bool watchesExplicitMotion_ = false;
  std::vector<int> watchedDofs_;  // the dofs of the watchers' nodes (their couplings')
  Eigen::VectorXd motion_;        // settleExplicitMotion's, at watchedDofs_
  // settleExplicitMotion's parts: watchers (events_ indices) whose groups share no free node.
  // Fused: every term with a search is a watcher, so the parts also make the searches and the
  // moves onto nodes at the step's end; else those follow for all terms in order.
  std::vector<int> settleParts_[2];
  std::vector<Term*> eventTerms_;  // events_[i]'s term
  bool drivesKinks_ = false;       // some source does (EventSource::drivesKinks, fixed)
  bool settleFused_ = false;
  void splitSettling(const std::vector<char>& freeNodes);
  // commit()'s terms that commit apart (Term::commitsApart), in two parts; empty: none or one.
  std::vector<Term*> commitParts_[2];
  // captureStepLoads: the loads' residual of each part (the first's then their sum) and the time
  // of that sum (NaN: none).
  bool captureLoads_ = false;
  Eigen::VectorXd partLoads_[2];
  double capturedLoadsT_ = std::numeric_limits<double>::quiet_NaN();
  // The terms' searches per update (Term::searchesPerUpdate, fixed with each term); 0: no term
  // has configuration-dependent state, and updates are skipped.
  long searchesPerUpdate_ = 0;
  // search() timed and counted as one update's searches (updateState, settleExplicitMotion).
  int timedSearch(const std::function<int()>& search);
  std::vector<Term*> dynamicCouplings_;  // terms whose couplings move (contact)
  bool patternStale_ = false;            // their couplings changed since the pattern was built
  SystemAssembler assembler_;
  // Assembly in two parts (docs/performance.md, "Two threads"): the terms split by an estimate
  // of their cost, the second part assembled into its own assembler on a second thread and then
  // added to the first. The split depends on the scene only, never on the thread count, so a
  // run gives the same bits with one thread or two.
  void splitAssembly();
  [[noreturn]] static void residualNotSummed();
  std::vector<Term*> firstPart_, secondPart_;
  Term* halved_ = nullptr;   // in both parts, each assembling half (Term::assemblesInHalves)
  bool sumPending_ = false;  // assembleForHalves left the parts' residuals to be summed
  void assembleParts(const EvalPoint& p, bool wantMatrix, const std::function<void()>& alongside,
                     bool forHalves, const std::function<void(int)>* afterPart);
  SystemAssembler secondAssembler_;
  std::unique_ptr<TwoPartRunner> runner_;  // only with a second part
  // The halves a term's pass is split into (CommitPoint::inHalves, EvalPoint::inHalves).
  const InHalves inTwoHalves_ = [this](const std::function<void(int)>& f) {
    runTwo([&] { f(0); }, [&] { f(1); });
  };
  Timings timings_;
  mutable long energyEvaluations_ = 0;
};

}  // namespace chute
