#pragma once
// Coulomb friction of one contact pair, regularised and lagged (docs/contact.md CT7-CT8), after
// the lagged friction of Li et al. 2020 (IPC, section 5): the normal force lambda, the unit normal
// n and the closest-point weights w_i are those of the pair at the step's start, so within a
// step friction is a function of the velocities alone.
//
//   CT7  u = (I - n n^T) sum_i w_i v_i            relative tangential velocity at the contact,
//        f_i = -mu lambda w_i f1(|u|) u / |u|     f1(y) = 2 y / eps_v - y^2 / eps_v^2 (y < eps_v),
//                                                 1 beyond,
//        a smooth stick (viscous below eps_v, slope 2 mu lambda / eps_v) to slip (|f| = mu lambda)
//        transition. Its power sum_i f_i . v_i = -mu lambda f1(|u|) |u| <= 0: friction never
//        supplies energy.
//   CT8  dr_i / dv_j = mu lambda w_i w_j [phi P + (phi' / y) u u^T], phi = f1(y) / y, P = I - n
//   n^T:
//        symmetric and positive semi-definite; no position derivative (lagged).
#include <array>

#include "kernels/ContactDistance.hpp"

namespace chute::kernels {

// What a pair keeps from the step's start for its friction (CT7).
struct FrictionLag {
  std::array<double, 4> weight{};
  Vec3 normal = Vec3::UnitZ();
  double normalForce = 0.0;  // lambda
};

struct FrictionResponse {
  Vec12 residual = Vec12::Zero();   // r = -f
  Mat12 dVelocity = Mat12::Zero();  // set only withTangent
  double slipSpeed = 0.0;           // |u|
};

FrictionResponse contactFriction(const FrictionLag& lag, const std::array<Vec3, 4>& v, double mu,
                                 double epsV, bool withTangent);

}  // namespace chute::kernels
