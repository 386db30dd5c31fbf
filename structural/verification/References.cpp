#include "verification/References.hpp"

#include <cmath>
#include <stdexcept>

namespace chute::verification {

double PulleyReference::hangingLength(double t) const {
  return 0.5 * L + (L1 - 0.5 * L) * std::cosh(std::sqrt(2.0 * g / L) * t);
}

BeadEllipseReference::BeadEllipseReference(const Vec3& f1, const Vec3& f2, const Vec3& bead0,
                                           const Vec3& gravity)
    : g_(gravity) {
  centre_ = 0.5 * (f1 + f2);
  const double c = 0.5 * (f2 - f1).norm();
  u_ = (f2 - f1).normalized();
  // The ellipse lies in the plane of the foci and the bead; w points from the axis to the bead.
  const Vec3 r0 = bead0 - centre_;
  const Vec3 perp = r0 - r0.dot(u_) * u_;
  if (perp.norm() <= 1e-14 * (c + r0.norm()))
    throw std::invalid_argument("bead starts on the line through the rope ends");
  w_ = perp.normalized();
  a_ = 0.5 * ((bead0 - f1).norm() + (bead0 - f2).norm());
  b_ = std::sqrt(a_ * a_ - c * c);
  theta0_ = std::atan2(r0.dot(w_) / b_, r0.dot(u_) / a_);
}

Vec3 BeadEllipseReference::at(double theta) const {
  return centre_ + a_ * std::cos(theta) * u_ + b_ * std::sin(theta) * w_;
}

Eigen::Vector2d BeadEllipseReference::rhs(const Eigen::Vector2d& y) const {
  // Lagrange: T = m/2 |p'|^2 thdot^2, V = -m g.p, p' = -a sin u + b cos w:
  // |p'|^2 thddot + (a^2 - b^2) sin cos thdot^2 = g . p'
  const double s = std::sin(y[0]), c = std::cos(y[0]);
  const Vec3 dp = -a_ * s * u_ + b_ * c * w_;
  const double acc = (g_.dot(dp) - (a_ * a_ - b_ * b_) * s * c * y[1] * y[1]) / dp.squaredNorm();
  return {y[1], acc};
}

std::vector<Vec3> BeadEllipseReference::positions(const std::vector<double>& times,
                                                  double h) const {
  std::vector<Vec3> out;
  out.reserve(times.size());
  Walk w = release();
  for (double target : times) out.push_back(walkTo(w, target, h));
  return out;
}

Vec3 BeadEllipseReference::walkTo(Walk& w, double target, double h) const {
  if (target < w.t) throw std::invalid_argument("reference times must ascend from 0");
  Eigen::Vector2d& y = w.y;
  double& t = w.t;
  while (t < target) {
    const double dt = std::min(h, target - t);
    const Eigen::Vector2d k1 = rhs(y), k2 = rhs(y + 0.5 * dt * k1), k3 = rhs(y + 0.5 * dt * k2),
                          k4 = rhs(y + dt * k3);
    y += dt / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
    t = (target - t - dt) < 1e-15 ? target : t + dt;
  }
  return at(y[0]);
}

}  // namespace chute::verification
