#pragma once
// Kinks of a term's energy that the motion crosses (a slider passing a node, a tension-only
// cable going slack or taut) and how the time stepper deals with them. Only the terms with such
// kinks implement it (SlidingGroupTerm, CableTerm); the others have none (Term::events()).
#include <Eigen/Core>

namespace chute {

class EventSource {
 public:
  virtual ~EventSource() = default;
  // Given a Newton update dx from positions x, the fraction of dx at which the update would pass
  // a kink (1 if none); the step is then cut to end there. A source may also note discrete
  // changes that cost nothing now (a slider exactly on a node leaving on the other side) for the
  // next updateState.
  virtual double passageFraction(const Eigen::VectorXd& /*x*/, const Eigen::VectorXd& /*dx*/) {
    return 1.0;
  }
  // Events located along the step's whole motion (a cable's slack / taut switch): given the
  // positions the step started from and the motion from there to a trial end, the fraction of
  // the step at which the motion passes one (1 if none).
  virtual double stepEventFraction(const Eigen::VectorXd& /*start*/,
                                   const Eigen::VectorXd& /*motion*/) {
    return 1.0;
  }
  // On a converged iterate: may move x by a negligible amount onto a kink reached at the end of
  // the step, and schedule the discrete change there for commit(). Returns whether it moved x.
  virtual bool onConverged(Eigen::VectorXd& /*x*/) { return false; }
  // The update reached a kink (the fraction passageFraction gave) and the solve crosses it in
  // place (statics, or sliders handed over inside the step): make the discrete change now.
  virtual bool crossNow(Eigen::VectorXd& /*x*/) { return false; }
  // Kinks passed by prescribed motion, whose time needs no locating (a driven slider passing a
  // node), crossed by the motion from `from` to `to`: the change is noted for the next
  // updateState, and `to` may be adjusted to the new state. Returns how many changes were noted.
  // drivesKinks() is fixed when the source is made (the system asks once).
  virtual bool drivesKinks() const { return false; }
  virtual int crossDriven(const Eigen::VectorXd& /*from*/, Eigen::VectorXd& /*to*/) { return 0; }
  // Explicit steps, which have no iterations that would land a kink on a step's end (EX3): the
  // step moved the positions from x by `motion` to xEnd (xEnd = x + motion up to round-off;
  // `motion` is given at the nodes of the watchers' couplings, zero elsewhere).
  // A source notes the kinks passed, for the next updateState, and may move xEnd by a negligible
  // amount onto a kink reached. Only sources that say they watch the motion are asked.
  // The noting first, for every source (noteExplicitMotion: it reads x and motion and writes only
  // the source's own state, so the sources' notes may run on two threads at once), then each
  // source's afterExplicitMotion in order (the moves onto kinks, which may touch shared nodes).
  virtual bool watchesExplicitMotion() const { return false; }
  virtual void noteExplicitMotion(const Eigen::VectorXd& /*x*/, const Eigen::VectorXd& /*motion*/) {
  }
  virtual void afterExplicitMotion(const Eigen::VectorXd& /*x*/, const Eigen::VectorXd& /*motion*/,
                                   Eigen::VectorXd& /*xEnd*/) {}
  // Round-off floor of a Newton update at the last assembly (length units): a very short, stiff
  // part (a slider with friction next to a node, docs/friction.md FR16) computes its force from
  // positions that carry round-off, so no update resolves positions finer than this. 0: none.
  virtual double displacementFloor() const { return 0.0; }
};

}  // namespace chute
