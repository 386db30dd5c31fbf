#pragma once
// Shared by the line-element kernel tests: a rope material and random directions.
#include <Eigen/Core>
#include <random>

#include "kernels/UniformStrainPolyline.hpp"

namespace chute::testing {

using kernels::LineMaterial;
using kernels::Vec3;

inline LineMaterial rope(bool tensionOnly = true) {
  LineMaterial m;
  m.E = 2.5e5;
  m.area = 3e-3;
  m.density = 1.7;
  m.tensionOnly = tensionOnly;
  return m;
}

inline Vec3 randomUnit(std::mt19937& rng) {
  std::normal_distribution<double> n(0, 1);
  return Vec3(n(rng), n(rng), n(rng)).normalized();
}

}  // namespace chute::testing
