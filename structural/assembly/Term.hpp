#pragma once
// A time step is a sum of terms. Each term adds its residual r(x, v, a, t) and its Jacobian
//   J = cx dr/dx + cv dr/dv + ca dr/da
// where (cx, cv, ca) are the integrator's derivatives of the evaluation-point quantities with
// respect to the unknown positions. The integrator knows nothing of what a term models.
#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include "assembly/EventSource.hpp"
#include "assembly/SystemAssembler.hpp"
#include "model/History.hpp"

namespace chute {

// Runs its argument with 0 and with 1, at once where the system has two threads (each call's
// writes its own): a term's per-node pass in two halves, its partial sums added in a fixed order,
// gives the same bits on one thread and on two (StructuralSystem::inTwoHalves).
using InHalves = std::function<void(const std::function<void(int)>&)>;

// Half 0 or 1 of n items, as the system splits them: [0, n/2) and [n/2, n).
inline std::pair<size_t, size_t> halfOf(size_t n, int half) {
  return half == 0 ? std::pair<size_t, size_t>{0, n / 2} : std::pair<size_t, size_t>{n / 2, n};
}
// each(0) and each(1): at once through inHalves where the system gave it, else one after the
// other (the same bits either way, when each writes its own).
inline void forBothHalves(const InHalves* inHalves, const std::function<void(int)>& each) {
  if (inHalves) {
    (*inHalves)(each);
  } else {
    each(0);
    each(1);
  }
}

// Where the terms are evaluated: positions, velocities and accelerations, the time, the
// integrator's derivatives (cx, cv, ca) and what each kind of evaluation asks of the terms. Made
// only by the named constructors below, one per use, so that no caller fills its fields by
// position; the fields are read by the terms.
struct EvalPoint {
  // The integrator's derivatives of (x, v, a) with respect to the unknown positions.
  struct Derivatives {
    double cx = 1.0, cv = 0.0, ca = 0.0;
  };

  const Eigen::VectorXd& x;  // positions of all dofs at the evaluation point
  const Eigen::VectorXd& v;  // velocities
  const Eigen::VectorXd& a;  // accelerations entering the inertia forces
  double t = 0.0;
  double cx = 1.0, cv = 0.0, ca = 0.0;
  bool inertia = true;      // false in static mode
  double loadFactor = 1.0;  // scales external loads (static load stepping)
  double dt = 0.0;          // step length (0: static), for rate-dependent history (friction)
  // Energy-momentum steps (docs/formulation.md EM1-EM2): the positions x_n the step started
  // from; x is then the midpoint (x_n + x_{n+1}) / 2 and cx = 1/2. Terms with a strain energy
  // use the discrete gradient between x_n and x_{n+1} = 2 x - x_n, their Jacobian with respect to
  // x_{n+1} being 2 cx d r / d x_{n+1}: others are evaluated at the midpoint. nullptr otherwise.
  const Eigen::VectorXd* xStart = nullptr;
  double emDissipation = 0.0;  // EM8: energy-decaying parameter chi (0: energy conserving)
  // Only the inertia M(x) a of the terms whose mass moves with the positions
  // (Term::massMovesWithPositions), nothing else: the explicit path's lumped mass M(x) 1 (EX2).
  bool inertiaOnly = false;
  // > 0: an explicit step of this length evaluates the forces (velocity-dependent forces too
  // stiff for it cap themselves, RG8); 0 in implicit steps and statics.
  double explicitStep = 0.0;
  // a is zero at every dof (the explicit step evaluates its forces at a = 0, EX2): the terms skip
  // the inertia M a without gathering a at every element. Set only by the caller that made a.
  bool zeroAcceleration = false;
  // Stiffness-proportional damping (EX7) evaluates the internal forces at x = x_step + beta v:
  // the step's own positions, for loads that are not part of the stiffness it damps (the
  // captured air of a canopy, docs/flight.md FL3). nullptr: x is the step's.
  const Eigen::VectorXd* undamped = nullptr;
  double dampingShift = 0.0;  // with undamped: beta, x = *undamped + beta v (to round-off)
  const Eigen::VectorXd& stepPositions() const { return undamped ? *undamped : x; }
  // A Newton iteration's Jacobian may give tension-only parts on the kink their taut tangent
  // (RG10); off for the iteration that confirms convergence with the exact tangent.
  bool kinkTangent = false;
  // Every term's Term::updateCouplings has just run at these positions x (StructuralSystem's
  // assembly): a term that keeps lists by position need not check them again.
  bool couplingsUpdated = false;
  // Given to Term::beforeHalves only (its passes run before the halves, on no runner's thread).
  const InHalves* inHalves = nullptr;

  // The state (x, v, a) at t as it is: residual r(x, v, a, t), Jacobian dr/dx (output, the
  // energy balance, checks).
  static EvalPoint state(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                         const Eigen::VectorXd& a, double t) {
    return EvalPoint(x, v, a, t);
  }
  // An implicit step of length dt (generalized-alpha): Jacobian cx dr/dx + cv dr/dv + ca dr/da.
  static EvalPoint implicitStep(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                                const Eigen::VectorXd& a, double t, Derivatives d, double dt) {
    EvalPoint p(x, v, a, t);
    p.cx = d.cx, p.cv = d.cv, p.ca = d.ca, p.dt = dt;
    return p;
  }
  // An energy-momentum step (EM1-EM2) from positions xStart: (x, v) the midpoint, a the step's
  // mean acceleration, chi the energy-decaying parameter (EM8).
  static EvalPoint energyMomentumStep(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                                      const Eigen::VectorXd& a, double t, Derivatives d, double dt,
                                      const Eigen::VectorXd& xStart, double chi) {
    EvalPoint p = implicitStep(x, v, a, t, d, dt);
    p.xStart = &xStart;
    p.emDissipation = chi;
    return p;
  }
  // The forces of an explicit step of length dt at a = 0 (EX2; zeroA must be zero at every dof),
  // residual only; dt = 0 for the forces of a start or after a cut. undamped: the step's own
  // positions when x is shifted by stiffness damping (EX7).
  static EvalPoint explicitForces(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                                  const Eigen::VectorXd& zeroA, double t, double dt,
                                  const Eigen::VectorXd* undamped = nullptr,
                                  double dampingShift = 0.0) {
    EvalPoint p(x, v, zeroA, t);
    p.undamped = undamped;
    p.dampingShift = undamped ? dampingShift : 0.0;
    p.cx = p.cv = p.ca = 0.0;
    p.dt = dt;
    p.explicitStep = dt;
    p.zeroAcceleration = true;
    return p;
  }
  // The residual at a = zeroA = 0 with the mass matrix as Jacobian (cx = cv = 0, ca = 1): the
  // consistent acceleration of an implicit start, M a = -r.
  static EvalPoint massMatrix(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                              const Eigen::VectorXd& zeroA, double t) {
    EvalPoint p(x, v, zeroA, t);
    p.cx = 0.0, p.cv = 0.0, p.ca = 1.0;
    return p;
  }
  // M a without loads (load factor 0), residual only: the lumped mass as r(a = 1) - r(a = 0)
  // (EX2). movingMassOnly: only the terms whose mass moves with x, and only their M(x) a.
  static EvalPoint inertiaOf(const Eigen::VectorXd& x, const Eigen::VectorXd& zeroV,
                             const Eigen::VectorXd& a, double t, bool movingMassOnly) {
    EvalPoint p(x, zeroV, a, t);
    p.cx = p.cv = p.ca = 0.0;
    p.loadFactor = 0.0;
    p.inertiaOnly = movingMassOnly;
    return p;
  }
  // Statics: no velocity, no inertia, the loads scaled by loadFactor; Jacobian dr/dx.
  static EvalPoint statics(const Eigen::VectorXd& x, const Eigen::VectorXd& zero, double t,
                           double loadFactor) {
    EvalPoint p(x, zero, zero, t);
    p.inertia = false;
    p.loadFactor = loadFactor;
    return p;
  }
  // The same point with other loads (the part of the residual scaled by the load factor), with or
  // without inertia, or for a step of length h (rate-dependent history).
  EvalPoint withLoadFactor(double f) const {
    EvalPoint p = *this;
    p.loadFactor = f;
    return p;
  }
  EvalPoint withInertia(bool on) const {
    EvalPoint p = *this;
    p.inertia = on;
    return p;
  }
  EvalPoint withStep(double h) const {
    EvalPoint p = *this;
    p.dt = h;
    return p;
  }

 private:
  EvalPoint(const Eigen::VectorXd& x_, const Eigen::VectorXd& v_, const Eigen::VectorXd& a_,
            double t_)
      : x(x_), v(v_), a(a_), t(t_) {}
};

// A converged step, as its terms commit it: the end positions, the end time, the step length
// and the time at which the integrator evaluated the step's forces (t_{n+1-alpha_f}; t for
// Bossak and statics).
struct CommitPoint {
  const Eigen::VectorXd& x;
  double t = 0.0;
  double dt = 0.0;
  double tForces = 0.0;
  const Eigen::VectorXd* v = nullptr;  // the end velocities, where the integrator has them
  const InHalves* inHalves = nullptr;  // set by the system for its terms
};

// What a term may adapt to the integrator that steps it, told once before the first step
// (Term::prepareFor).
struct IntegrationTraits {
  bool explicitSteps = false;      // central differences: residual-only steps, a stable step (EX5)
  bool discreteGradients = false;  // energy-momentum: strain energies by discrete gradients (EM5)
};

struct EnergyBreakdown {
  double kinetic = 0.0;
  double strain = 0.0;
  double gravity = 0.0;  // potential of gravity, -sum f_g . x
  // Energy that entered with mass the structure took on, not through a force's work (the kinetic
  // energy of air a canopy captured, docs/flight.md FL12): the balance counts it as supplied.
  double supplied = 0.0;
  double total() const { return kinetic + strain + gravity - supplied; }
};

class Term {
 public:
  virtual ~Term() = default;
  virtual const char* name() const = 0;
  // Node cliques this term may ever couple (for the sparsity pattern built once).
  virtual void addCouplings(std::vector<std::vector<int>>& cliques) const = 0;
  // Couplings that move with the configuration (contact pairs): brings them up to date for
  // positions x before an assembly and returns whether they changed since the last call; the
  // pattern is then built again from every term's addCouplings(). Only terms that say
  // dynamicCouplings() are asked.
  virtual bool dynamicCouplings() const { return false; }
  virtual bool updateCouplings(const Eigen::VectorXd& /*x*/) { return false; }
  // Updates configuration-dependent state (e.g. the active sliding elements) for trial positions
  // x; returns how many discrete changes were made.
  virtual int updateState(const Eigen::VectorXd& /*x*/) { return 0; }
  // How many searches one updateState() makes (0: it has no configuration-dependent state; fixed
  // for the term's life), for the work counters; a system without any skips the updates.
  virtual long searchesPerUpdate() const { return 0; }
  virtual void assemble(const EvalPoint& p, SystemAssembler& out) = 0;
  // Energy of the state (x, v) at time t (after any event at t: a set cut at t is gone).
  virtual void addEnergy(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double t,
                         EnergyBreakdown& e) const = 0;
  // Whether the Jacobian this term adds is symmetric (CHOLMOD may be used when all are).
  virtual bool symmetricJacobian() const { return true; }
  // Whether assemble() depends on EvalPoint::loadFactor (loads, gravity). A term that says false
  // is left out of the evaluations that separate applied loads from the rest (output frames).
  virtual bool loadDependent() const { return true; }
  // Whether this term's forces are loads that do work on the structure without an energy in
  // addEnergy (pressure, drag, a flow's loads): the energy balance (solver/EnergyMonitor.hpp)
  // adds up their work.
  virtual bool doesExternalWork() const { return false; }
  // Kinks of the energy crossed by the motion (sliders at nodes, slack / taut): nullptr for
  // terms without any.
  virtual EventSource* events() { return nullptr; }

  // ---- what the integrators ask of every term (the defaults: a term without such a part) ----
  // Told once, before the first step, which kind of integrator steps the system.
  virtual void prepareFor(const IntegrationTraits& /*traits*/) {}
  // Whether the term's mass matrix changes with the positions (a sliding element's follows its
  // slider, F10): the explicit path evaluates the lumped mass of such terms at every step's
  // positions (EvalPoint::inertiaOf with movingMassOnly, which only they honour) and that of the
  // others once (EX2).
  virtual bool massMovesWithPositions() const { return false; }
  // Whether the term's lumped mass changes only when it commits, not with the positions (the air
  // moving with a canopy, docs/flight.md FL11): the explicit path re-forms it wherever it forms a
  // new lumped mass, from committedNodalMass, with no positions of its own to compare and no
  // assembly. It is per node: the same mass on each of a node's dofs, and never negative.
  virtual bool massChangesAtCommit() const { return false; }
  // The nodes that mass sits on (fixed for the run), and each one's mass as last committed,
  // at [i] for committedMassNodes()[i] (the term's own array, made as it commits: a pass that
  // copied it out cost a pass over the canopy's nodes at every step).
  virtual const std::vector<int>& committedMassNodes() const {
    static const std::vector<int> none;
    return none;
  }
  virtual const double* committedNodalMass() const { return nullptr; }
  // Adds to S, per node, the row sum of this term's stiffness at positions x and time t that
  // bounds the explicit step's highest frequency, omega^2 <= max_i S_i / m_i (EX5-EX6); free[i]
  // says whether node i has a free dof (rows of fixed nodes are not part of the free system).
  virtual void addStiffnessBound(const Eigen::VectorXd& /*x*/, double /*t*/,
                                 const std::vector<char>& /*free*/,
                                 std::vector<double>& /*S*/) const {}
  // Whether addStiffnessBound is a function of (x, t) alone, not of state the step's commit
  // changes (a slider's place, the contact pairs): then the explicit step may evaluate it at its
  // end positions alongside its assembly, for the next step's estimate. A term that adds nothing
  // reads nothing; a term whose bound reads such state says false.
  virtual bool stiffnessBoundOfPositions() const { return true; }
  // A bound on the squared frequency of modes that couple many nodes at once, which the nodal
  // bounds above cannot see (a gas spring over a whole canopy: docs/flight.md FL12), given the
  // lumped nodal masses; 0: none.
  virtual double frequencySquaredBound(const Eigen::VectorXd& /*x*/, double /*t*/,
                                       const std::vector<double>& /*nodalMass*/) const {
    return 0.0;
  }
  // The cost of one residual assembly, in units of an explicit step's membrane triangle (the
  // two-part split of the assembly, docs/performance.md "Two threads"): each term's per-element
  // figure is its time per element over the triangle's in one profile of the explicit C-9 slider
  // case (one thread, the triangles' AVX2 copy), or of the generated C-9 in free flight for the
  // airflow's loads. 0: negligible or unknown.
  virtual double assemblyCost() const { return 0.0; }
  // Whether assemble() reads only the model and state that no assembly writes (its own, or
  // another term's that is set between assemblies, as the sliding groups' active elements), and
  // writes only its own, so that it may run on the assembly's second thread.
  virtual bool assemblesApart() const { return false; }
  // Whether assemble() may also be made in two halves, one in each of the assembly's two parts
  // (StructuralSystem::splitAssembly): assembleHalf(p, out, 0) and (p, out, 1), at once on two
  // threads or one after the other, each into its part's assembler, writing only data of its own
  // half, after beforeHalves(p, out) on the first thread with the first part's assembler; then,
  // once both are done, afterHalves(p) on the first thread, and, where it returned true,
  // afterHalvesPart(p, out, half) for each half again with its part's assembler (at once or one
  // after the other; a hand-over to the second thread costs about 0.5 us, so none for nothing).
  // Together what assemble() gives, to round-off. Only for a term that assemblesApart.
  virtual bool assemblesInHalves() const { return false; }
  virtual void assembleHalf(const EvalPoint& p, SystemAssembler& out, int half) {
    if (half == 0) assemble(p, out);
  }
  virtual void beforeHalves(const EvalPoint& /*p*/, const SystemAssembler& /*out*/) {}
  virtual bool afterHalves(const EvalPoint& /*p*/) { return false; }
  virtual void afterHalvesPart(const EvalPoint& /*p*/, SystemAssembler& /*out*/, int /*half*/) {}
  // addEnergy in the same two halves (the energy balance's evaluation on two threads): each
  // half's sums added to e; together addEnergy's, to round-off.
  virtual void addEnergyHalf(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double t,
                             EnergyBreakdown& e, int half) const {
    if (half == 0) addEnergy(x, v, t, e);
  }
  // addStiffnessBound in the same two halves, each half's bounds added to S; together
  // addStiffnessBound's, to round-off.
  virtual void addStiffnessBoundHalf(const Eigen::VectorXd& x, double t,
                                     const std::vector<char>& free, std::vector<double>& S,
                                     int half) const {
    if (half == 0) addStiffnessBound(x, t, free, S);
  }

  // ---- history (model/History.hpp) ----
  // commit(): the converged step becomes the state later steps start from; revert(): the trial
  // changes of a failed solve are dropped. save() writes everything the term remembers (trial
  // and committed), load() restores it exactly and checks every value (a checkpoint file may be
  // forged). A term that remembers nothing between steps keeps the defaults.
  virtual bool hasHistory() const { return false; }
  virtual void commit(const CommitPoint& /*c*/) {}
  // Whether commit() reads only c, the model and the term's own state and writes only its own
  // state, and no other term's commit reads that state: such terms' commits may run after the
  // others', on the explicit step's two threads at once (StructuralSystem::commit). Such a commit
  // does not use c.inHalves.
  virtual bool commitsApart() const { return false; }
  virtual void revert() {}
  virtual void save(History& /*h*/) const {}
  virtual void load(HistoryReader& /*h*/) {}
};

// Marks in `nodes` (one flag per model node) every node of t's couplings (Term::addCouplings):
// the nodes it may write to.
inline void markCoupledNodes(const Term& t, std::vector<char>& nodes) {
  std::vector<std::vector<int>> cliques;
  t.addCouplings(cliques);
  for (const auto& c : cliques)
    for (int n : c) nodes[n] = 1;
}

}  // namespace chute
