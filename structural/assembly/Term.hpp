#pragma once
// A time step is a sum of terms. Each term adds its residual r(x, v, a, t) and its Jacobian
//   J = cx dr/dx + cv dr/dv + ca dr/da
// where (cx, cv, ca) are the integrator's derivatives of the evaluation-point quantities with
// respect to the unknown positions. The integrator knows nothing of what a term models.
#include <Eigen/Core>
#include <vector>

#include "assembly/EventSource.hpp"
#include "assembly/SystemAssembler.hpp"
#include "model/History.hpp"

namespace chute {

struct EvalPoint {
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
  // x_{n+1} being 2 cx d r / d x_{n+1}; others are evaluated at the midpoint. nullptr otherwise.
  const Eigen::VectorXd* xStart = nullptr;
  double emDissipation = 0.0;  // EM8: energy-decaying parameter chi (0: energy conserving)
  // Only the inertia M(x) a, nothing else (no internal, external or damping force): the explicit
  // path's lumped mass of sliding elements, M(x) 1 (EX2). Honoured by the sliding group term,
  // the only term whose mass moves with x; the others are never asked.
  bool inertiaOnly = false;
  // > 0: an explicit step of this length evaluates the forces (velocity-dependent forces too
  // stiff for it cap themselves, RG8); 0 in implicit steps and statics.
  double explicitStep = 0.0;
  // a is zero at every dof (the explicit step evaluates its forces at a = 0, EX2): the terms skip
  // the inertia M a without gathering a at every element. Set only by the caller that made a.
  bool zeroAcceleration = false;
};

// A converged step, as its terms commit it: the end positions, the end time, the step length
// and the time at which the integrator evaluated the step's forces (t_{n+1-alpha_f}; t for
// Bossak and statics).
struct CommitPoint {
  const Eigen::VectorXd& x;
  double t = 0.0;
  double dt = 0.0;
  double tForces = 0.0;
};

struct EnergyBreakdown {
  double kinetic = 0.0;
  double strain = 0.0;
  double gravity = 0.0;  // potential of gravity, -sum f_g . x
  double total() const { return kinetic + strain + gravity; }
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

  // ---- history (model/History.hpp) ----
  // commit(): the converged step becomes the state later steps start from; revert(): the trial
  // changes of a failed solve are dropped. save() writes everything the term remembers (trial
  // and committed), load() restores it exactly and checks every value (a checkpoint file may be
  // forged). A term that remembers nothing between steps keeps the defaults.
  virtual bool hasHistory() const { return false; }
  virtual void commit(const CommitPoint& /*c*/) {}
  virtual void revert() {}
  virtual void save(History& /*h*/) const {}
  virtual void load(HistoryReader& /*h*/) {}
};

}  // namespace chute
