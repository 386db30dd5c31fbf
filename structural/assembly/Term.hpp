#pragma once
// A time step is a sum of terms. Each term adds its residual r(x, v, a, t) and its Jacobian
//   J = cx dr/dx + cv dr/dv + ca dr/da
// where (cx, cv, ca) are the integrator's derivatives of the evaluation-point quantities with
// respect to the unknown positions. The integrator knows nothing of what a term models.
#include <Eigen/Core>
#include <vector>

#include "assembly/SystemAssembler.hpp"

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
  // Updates configuration-dependent state (e.g. the active sliding elements) for trial positions
  // x; returns how many discrete changes were made.
  virtual int updateState(const Eigen::VectorXd& /*x*/) { return 0; }
  virtual void assemble(const EvalPoint& p, SystemAssembler& out) = 0;
  virtual void addEnergy(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                         EnergyBreakdown& e) const = 0;
  // Whether the Jacobian this term adds is symmetric (CHOLMOD may be used when all are).
  virtual bool symmetricJacobian() const { return true; }
  // Whether assemble() depends on EvalPoint::loadFactor (loads, gravity). A term that says false
  // is left out of the evaluations that separate applied loads from the rest (output frames).
  virtual bool loadDependent() const { return true; }
  // Event location for kinks of the term's energy crossed by the motion (a slider passing a
  // node). Given a Newton update dx from positions x, returns the fraction of dx at which the
  // update would pass such a kink (1 if none); the step is then cut to end there. A term may also
  // note discrete changes that cost nothing now (a slider exactly on a node leaving on the other
  // side) for the next updateState.
  virtual double passageFraction(const Eigen::VectorXd& /*x*/, const Eigen::VectorXd& /*dx*/) {
    return 1.0;
  }
  // Events located along the step's whole motion (a cable's slack / taut switch): given the
  // positions the step started from and the motion from there to a trial end, the fraction of
  // the step at which the motion passes one (1 if none); the step is then cut to end there.
  virtual double stepEventFraction(const Eigen::VectorXd& /*start*/,
                                   const Eigen::VectorXd& /*motion*/) {
    return 1.0;
  }
  // Called on a converged iterate; may move x by a negligible amount onto a kink reached at the
  // end of the step, and schedule the discrete change there for commit(). Returns whether it
  // moved x.
  virtual bool onConverged(Eigen::VectorXd& /*x*/) { return false; }
  // Static equilibrium: the update reached a kink (the fraction passageFraction gave); make the
  // discrete change now. Returns whether anything changed.
  virtual bool crossNow(Eigen::VectorXd& /*x*/) { return false; }
  // Dynamics: kinks passed by prescribed motion, whose time needs no locating (a driven slider
  // passing a node), crossed by the motion from positions `from` to `to`: the discrete change
  // is noted for the next updateState, and `to` may be adjusted to the new state (a passed node
  // put along the cable). Returns how many changes were noted.
  virtual bool drivesKinks() const { return false; }
  virtual int crossDriven(const Eigen::VectorXd& /*from*/, Eigen::VectorXd& /*to*/) { return 0; }
  // Round-off floor of a Newton update at the last assembly (length units): a very short, stiff
  // part (a slider with friction next to a node, docs/friction.md FR16) computes its force from
  // positions that carry round-off, so no update resolves positions finer than this. 0: none.
  virtual double displacementFloor() const { return 0.0; }
  virtual void commit(const Eigen::VectorXd& /*x*/) {}  // x: the converged positions
  virtual void revert() {}
};

}  // namespace chute
