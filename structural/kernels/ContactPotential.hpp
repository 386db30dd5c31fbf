#pragma once
// The normal response of one contact pair (docs/contact.md CT4-CT6): a penalty on the distance
// d below the contact thickness dHat, a normal damping that only takes energy out, and for an
// edge-edge pair the mollifier that keeps the potential C1 where the edges turn parallel.
//
//   CT4  E(d) = 1/2 k (dHat - d)^2        for d < dHat, 0 beyond:
//        force k (dHat - d) along grad d, zero at d = dHat (C1: the force does not jump; the
//        stiffness does, from 0 to k). Finite at d = 0: a pair is kept apart by the energy
//        1/2 k dHat^2 (CT9 sizes k so that this holds the relative motion).
//   CT5  edge-edge: E_ee = m(c) E(d), c = |e1 x e2|^2, eps_x = 1e-3 |E1|^2 |E2|^2 on the reference
//        edges, m = (2 - c / eps_x) c / eps_x for c < eps_x, else 1 (the mollifier of Li et al.
//        2020, IPC): grad m = 0 where the edges are parallel, so m E is C1 although d has a kink
//        there. Point-triangle pairs carry the contact of parallel edges.
//   CT6  damping, Hunt-Crossley type: r_d = m c (dHat - d) / dHat min(ddot, 0) grad d with
//        ddot = grad d . v. It acts only while the pair approaches (ddot < 0), grows from zero
//        at d = dHat (no jump in the force) and its power is -m c (dHat - d) / dHat ddot^2 <= 0.
//
// Residuals are r = dE/dx + r_d (the force on the nodes is -r), with their exact derivatives
// with respect to positions and velocities (the integrator combines them as cx dr/dx + cv dr/dv).
#include <array>

#include "kernels/ContactDistance.hpp"

namespace chute::kernels {

enum class ContactPairKind { PointTriangle, EdgeEdge };

struct ContactLaw {
  double stiffness = 0.0;  // k of CT4 (force per length)
  double thickness = 0.0;  // dHat
  double damping = 0.0;    // c of CT6 (force per speed); 0: none
};

// The mollifier of CT5 and its derivatives with respect to the four nodes (a0, a1, b0, b1).
struct Mollifier {
  double value = 1.0;
  Vec12 gradient = Vec12::Zero();
  Mat12 hessian = Mat12::Zero();  // set only withHessian
};
Mollifier edgeEdgeMollifier(const std::array<Vec3, 4>& x, double epsX, bool withHessian);
// eps_x of CT5 from the edges' reference vectors.
double mollifierThreshold(const Vec3& e1Reference, const Vec3& e2Reference);

struct PairResponse {
  bool active = false;       // d < dHat: the rest is zero otherwise
  double energy = 0.0;       // CT4 (times m for an edge-edge pair)
  double normalForce = 0.0;  // m k (dHat - d): what friction's lag keeps (CT7)
  Distance distance;         // d, the unit separation n and the closest-point weights
  Vec12 residual = Vec12::Zero();
  Mat12 dPosition = Mat12::Zero();  // set only withTangent
  Mat12 dVelocity = Mat12::Zero();  // set only withTangent
};

// x, v: the pair's four nodes (point, a, b, c) or (a0, a1, b0, b1). epsX: CT5's threshold (edge
// pairs only). The distance is computed first; a pair at d >= dHat returns inactive.
PairResponse contactPair(ContactPairKind kind, const std::array<Vec3, 4>& x,
                         const std::array<Vec3, 4>& v, const ContactLaw& law, double epsX,
                         bool withTangent);

// The distance alone (the broad phase's narrow check, the stable-step bound, output).
Distance pairDistance(ContactPairKind kind, const std::array<Vec3, 4>& x, bool withHessian);
// Its square alone, without derivatives: the cheap test of every candidate.
double pairSquaredDistance(ContactPairKind kind, const std::array<Vec3, 4>& x);

}  // namespace chute::kernels
