#pragma once
// Shared by the membrane-face kernel tests: reference triangles and quads, their homogeneous
// stretches with a random rotation and perturbation, random vectors, and stacking of nodal
// coordinates.
#include <Eigen/Geometry>
#include <array>
#include <random>

namespace chute::testing {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

inline Mat3 randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> n(0, 1);
  return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
}

// A vector of independent components uniform in [-size, size] (velocities, winds).
inline Vec3 randomVector(std::mt19937& rng, double size) {
  std::uniform_real_distribution<double> u(-size, size);
  return Vec3(u(rng), u(rng), u(rng));
}

template <int N>
std::array<Vec3, N> referenceNodes() {
  if constexpr (N == 3)
    return {Vec3(0.1, 0.2, 0.0), Vec3(1.3, 0.1, 0.1), Vec3(0.4, 0.9, -0.05)};
  else
    return {Vec3(0.0, 0.0, 0.0), Vec3(1.1, 0.05, 0.0), Vec3(1.2, 0.9, 0.02), Vec3(-0.1, 1.0, 0.0)};
}

// Current nodes: a homogeneous stretch (lx, ly, shear) of the reference, rotated and with a
// small non-homogeneous perturbation (so that quads see varying strain).
template <int N>
std::array<Vec3, N> deformed(const std::array<Vec3, N>& X, double lx, double ly, double shear,
                             std::mt19937& rng, double noise) {
  Mat3 U;
  U << lx, shear, 0, 0, ly, 0, 0, 0, 1;
  const Mat3 Q = randomRotation(rng);
  std::uniform_real_distribution<double> u(-noise, noise);
  std::array<Vec3, N> x;
  for (int i = 0; i < N; ++i) x[i] = Q * (U * X[i]) + Vec3(u(rng), u(rng), u(rng)) + Vec3(2, -1, 3);
  return x;
}

template <int N>
Eigen::VectorXd stack(const std::array<Vec3, N>& x) {
  Eigen::VectorXd v(3 * N);
  for (int i = 0; i < N; ++i) v.segment<3>(3 * i) = x[i];
  return v;
}
template <int N>
std::array<Vec3, N> unstack(const Eigen::VectorXd& v) {
  std::array<Vec3, N> x;
  for (int i = 0; i < N; ++i) x[i] = v.segment<3>(3 * i);
  return x;
}

}  // namespace chute::testing
