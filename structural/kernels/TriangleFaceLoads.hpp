#pragma once
// A triangle's follower pressure (docs/formulation.md P1) and face drag (FD1) as one residual,
// for the explicit step (P2): both are multiples of the face's area vector A = (1/2) (x1 - x0) x
// (x2 - x0), shared equally by its three nodes, so every node gets the one vector
//   r = ((c g - p) / 3) A,   g = (|u_a| u_a - s |u0_a| u0_a) / |A|^2 (0 for A = 0),
// u_a = (v_f - w) . A, u0_a = -w . A (FD1's u and u0 times |A|), v_f the mean of the nodes'
// velocities, c = (1/2) rho_air Cd, s = 1 with the steady drag subtracted: what
// trianglePressureForce and faceDragNodeResidual give, summed (a test holds them to round-off).
// The membrane term adds it to its triangles' forces in the pass it makes anyway (one gather of
// the positions, one scatter), one triangle at a time (triangleFaceLoad) or four at a time in the
// membranes' own kernel (membraneTriangleForcesAndLoads, MembraneTriangleBatch.hpp), whose lanes
// give this function's bits (a test holds them).
#include <cmath>

namespace chute::kernels {

// One triangle's loads at an evaluation: the pressure p (0: none) and drag c (0: none) already
// scaled by the load factor; the wind w and s of its face drag.
struct TriangleFaceLoadParameters {
  double pressure = 0.0, drag = 0.0;
  double wind[3] = {0.0, 0.0, 0.0};
  double steady = 0.0;  // s: 1 or 0
};

// P2 at positions x0..x2 and velocities v0..v2 (three doubles each): r, each node's residual.
// Inline, and every operation written out in the order the four-lane kernel makes it.
inline void triangleFaceLoad(const double* x0, const double* x1, const double* x2, const double* v0,
                             const double* v1, const double* v2,
                             const TriangleFaceLoadParameters& q, double* r) {
  const double e1[3] = {x1[0] - x0[0], x1[1] - x0[1], x1[2] - x0[2]};
  const double e2[3] = {x2[0] - x0[0], x2[1] - x0[1], x2[2] - x0[2]};
  const double A[3] = {0.5 * (e1[1] * e2[2] - e1[2] * e2[1]), 0.5 * (e1[2] * e2[0] - e1[0] * e2[2]),
                       0.5 * (e1[0] * e2[1] - e1[1] * e2[0])};
  const double aa = (A[0] * A[0] + A[1] * A[1]) + A[2] * A[2];
  double rel[3];
  for (int c = 0; c < 3; ++c) rel[c] = ((v0[c] + v1[c]) + v2[c]) * (1.0 / 3.0) - q.wind[c];
  const double ua = (rel[0] * A[0] + rel[1] * A[1]) + rel[2] * A[2];
  const double u0a = -((q.wind[0] * A[0] + q.wind[1] * A[1]) + q.wind[2] * A[2]);
  const double num = std::abs(ua) * ua - q.steady * (std::abs(u0a) * u0a);
  const double g = aa > 0.0 ? num / aa : 0.0;
  const double k = (q.drag * g - q.pressure) * (1.0 / 3.0);
  for (int c = 0; c < 3; ++c) r[c] = k * A[c];
}

}  // namespace chute::kernels
