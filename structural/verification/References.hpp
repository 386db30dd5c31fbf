#pragma once
// Independent references for the paper's verification problems (docs/formulation.md section 8).
// They share no code with the finite-element solver.
#include <Eigen/Core>
#include <vector>

namespace chute::verification {

using Vec3 = Eigen::Vector3d;

// F13: an inextensible rope of length L over a fixed frictionless pulley, released from rest with
// L1 on one side: l1(t) = L/2 + (L1 - L/2) cosh(sqrt(2 g / L) t).
struct PulleyReference {
  double L, L1, g;
  Vec3 pulley;     // pulley position
  Vec3 direction;  // unit vector from the pulley to the end being tracked
  double hangingLength(double t) const;
  Vec3 endPosition(double t) const { return pulley + hangingLength(t) * direction; }
};

// A bead on an inextensible massless rope whose ends are fixed at the foci f1, f2: the bead moves
// on the ellipse with those foci through its initial position. One degree of freedom (the
// ellipse angle theta), integrated with classical RK4 at a fixed small step that lands on every
// requested time. Released from rest.
class BeadEllipseReference {
 public:
  BeadEllipseReference(const Vec3& f1, const Vec3& f2, const Vec3& bead0, const Vec3& gravity);
  // Positions at ascending times (t >= 0); step h of the RK4 integration.
  std::vector<Vec3> positions(const std::vector<double>& times, double h = 1e-5) const;
  // The same integration one time at a time (a run's rows as they come): the state of a walk
  // from the release, and the position at the next time (>= the walk's), the walk moved there.
  struct Walk {
    Eigen::Vector2d y;  // (theta, theta_dot)
    double t = 0.0;
  };
  Walk release() const { return {Eigen::Vector2d(theta0_, 0.0), 0.0}; }
  Vec3 walkTo(Walk& w, double target, double h = 1e-5) const;
  double semiMajor() const { return a_; }
  double semiMinor() const { return b_; }

 private:
  Vec3 at(double theta) const;
  Eigen::Vector2d rhs(const Eigen::Vector2d& y) const;  // (theta, theta_dot)'
  Vec3 centre_, u_, w_, g_;
  double a_ = 0, b_ = 0, theta0_ = 0;
};

}  // namespace chute::verification
