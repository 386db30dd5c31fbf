#pragma once
// Natural-coordinate shape functions and integration rules of the membrane faces, shared by the
// membrane and pressure kernels. Internal to kernels/.
#include <Eigen/Core>

namespace chute::kernels::shape_rules {

struct Rule3 {
  static constexpr int n = 1;
  static Eigen::Matrix<double, 3, 2> dNdXi(int) {
    Eigen::Matrix<double, 3, 2> d;
    d << -1, -1, 1, 0, 0, 1;
    return d;
  }
  static Eigen::Matrix<double, 3, 1> N(int) { return Eigen::Vector3d::Constant(1.0 / 3.0); }
  static double weight(int) { return 0.5; }
};
struct Rule4 {
  static constexpr int n = 4;
  static constexpr double g = 0.57735026918962576451;  // 1/sqrt(3)
  static Eigen::Vector2d point(int k) {
    const double xi[4] = {-g, g, g, -g}, eta[4] = {-g, -g, g, g};
    return {xi[k], eta[k]};
  }
  static Eigen::Matrix<double, 4, 2> dNdXi(int k) {
    const Eigen::Vector2d p = point(k);
    const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    Eigen::Matrix<double, 4, 2> d;
    for (int i = 0; i < 4; ++i) {
      d(i, 0) = 0.25 * sx[i] * (1 + sy[i] * p.y());
      d(i, 1) = 0.25 * sy[i] * (1 + sx[i] * p.x());
    }
    return d;
  }
  static Eigen::Matrix<double, 4, 1> N(int k) {
    const Eigen::Vector2d p = point(k);
    const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    Eigen::Matrix<double, 4, 1> n;
    for (int i = 0; i < 4; ++i) n[i] = 0.25 * (1 + sx[i] * p.x()) * (1 + sy[i] * p.y());
    return n;
  }
  static double weight(int) { return 1.0; }
};

}  // namespace chute::kernels::shape_rules
