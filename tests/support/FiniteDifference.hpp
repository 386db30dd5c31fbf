#pragma once
// Central finite-difference checks used by every kernel test: a gradient against its function,
// a Jacobian against its vector function.
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>

namespace chute::testing {

// Relative error max|A - B| / max(max|B|, floor).
template <class A, class B>
double relativeError(const A& a, const B& b, double floor = 1e-300) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(b.cwiseAbs().maxCoeff(), floor);
}

// Central differences of a vector function f: R^n -> R^m at x with step h.
template <class F>
Eigen::MatrixXd fdJacobian(F&& f, const Eigen::VectorXd& x, double h) {
  const Eigen::VectorXd f0 = f(x);
  Eigen::MatrixXd J(f0.size(), x.size());
  for (int j = 0; j < x.size(); ++j) {
    Eigen::VectorXd xp = x, xm = x;
    xp[j] += h;
    xm[j] -= h;
    J.col(j) = (f(xp) - f(xm)) / (2 * h);
  }
  return J;
}

// Central differences of a scalar function.
template <class F>
Eigen::VectorXd fdGradient(F&& f, const Eigen::VectorXd& x, double h) {
  Eigen::VectorXd g(x.size());
  for (int j = 0; j < x.size(); ++j) {
    Eigen::VectorXd xp = x, xm = x;
    xp[j] += h;
    xm[j] -= h;
    g[j] = (f(xp) - f(xm)) / (2 * h);
  }
  return g;
}

// The nodes of a face as one vector (3 per node) and back: what fdJacobian differentiates.
template <int N>
Eigen::VectorXd flat(const std::array<Eigen::Vector3d, N>& a) {
  Eigen::VectorXd out(3 * N);
  for (int i = 0; i < N; ++i) out.template segment<3>(3 * i) = a[i];
  return out;
}
template <int N>
std::array<Eigen::Vector3d, N> unflat(const Eigen::VectorXd& y) {
  std::array<Eigen::Vector3d, N> out;
  for (int i = 0; i < N; ++i) out[i] = y.template segment<3>(3 * i);
  return out;
}

}  // namespace chute::testing
