#pragma once
// A canopy triangle's share of the airflow's loads (docs/flight.md FL2, FL6-FL8) for the explicit
// step's membranes' pass (docs/formulation.md FL13): at the step's own positions (EX7's damped
// positions less beta v, formed from the edges the membrane force already has) and the nodes'
// velocities, with the canopy-wide state of the evaluation (FL1, the cloth's linearisation FL9):
//   A = (1/2) e1 x e2,  n = A / |A|,  c = n . U_hat,  u_n = (v_f - v_c) . n,
//   C_out = C_b min(1, |c| / 0.2) + (1 - C_b) min(c, 0)^2,  p_s = -q C_out,
//   p_net = p_s - (1/2) rho C_n |u_n| u_n,   each node's residual r = -(lf p_net / 3) A,
// and what the captured air's update and inertia sum over the canopy: the volume (centroid . A /
// 3), |A|, the cloth's outflow |A| u(p_gauge + p_s) and its derivative, each node's A / 3 and
// |A| / 3. The inside pressure's part of FL8 (p_in A / 3) is added per node by the term once the
// captured air's update has found p_in. What CanopyFlowTerm's own pass over the faces gives, to
// round-off (a test holds them); the four-lane membrane kernel's lanes give this function's bits
// (membraneTriangleForcesAndFlow, MembraneTriangleBatch.hpp; a test holds them).
#include <cmath>

#include "kernels/CanopyFlow.hpp"

namespace chute::kernels {

// The canopy-wide state at an evaluation (FL1, FL7-FL9) and the load factor.
struct TriangleFlowParameters {
  double flowDirection[3] = {0.0, 0.0, 0.0};   // U_hat (zero: no relative flow)
  double canopyVelocity[3] = {0.0, 0.0, 0.0};  // v_c
  double dynamicPressure = 0.0;                // q
  double baseCoefficient = 0.0;                // C_b
  double normalDrag = 0.0;                     // (1/2) rho C_n
  double clothGauge = 0.0;  // FL6's inside gauge pressure of the linearisation (FL9)
  bool permeable = false;   // the cloth's law (ClothPermeability): viscous, inertial, 1 / viscous
  double viscous = 0.0, inertial = 0.0, perViscous = 0.0;
  double loadFactor = 1.0;
  double dampingShift = 0.0;  // beta: the positions given are the step's plus beta v (EX7)
};

// One triangle's sums (FL2, FL6, FL11).
struct TriangleFlowSums {
  double volume = 0.0, area = 0.0, cloth = 0.0, dCloth = 0.0;
  double nodeArea[3] = {0.0, 0.0, 0.0};  // A / 3
  double share = 0.0;                    // |A| / 3
};

// FL13 at positions x0..x2 (the step's plus beta v) and velocities v0..v2: r, each node's residual
// (three doubles), and the triangle's sums. Every operation written out in the order the
// four-lane kernel makes it.
inline void triangleFlowLoad(const double* x0, const double* x1, const double* x2, const double* v0,
                             const double* v1, const double* v2, const TriangleFlowParameters& q,
                             double* r, TriangleFlowSums& o) {
  const double b = q.dampingShift, third = 1.0 / 3.0;
  double e1[3], e2[3], vs[3], xs[3];
  for (int c = 0; c < 3; ++c) {
    e1[c] = (x1[c] - x0[c]) - b * (v1[c] - v0[c]);
    e2[c] = (x2[c] - x0[c]) - b * (v2[c] - v0[c]);
    vs[c] = (v0[c] + v1[c]) + v2[c];
    xs[c] = ((x0[c] + x1[c]) + x2[c]) - b * vs[c];
  }
  const double A[3] = {0.5 * (e1[1] * e2[2] - e1[2] * e2[1]), 0.5 * (e1[2] * e2[0] - e1[0] * e2[2]),
                       0.5 * (e1[0] * e2[1] - e1[1] * e2[0])};
  const double aa = (A[0] * A[0] + A[1] * A[1]) + A[2] * A[2];
  const double area = std::sqrt(aa);
  const bool positive = aa > 0.0;
  const double inv = 1.0 / (positive ? area : 1.0);
  double n[3], rel[3];
  for (int c = 0; c < 3; ++c) {
    n[c] = A[c] * inv;
    rel[c] = vs[c] * third - q.canopyVelocity[c];
  }
  const double c =
      (n[0] * q.flowDirection[0] + n[1] * q.flowDirection[1]) + n[2] * q.flowDirection[2];
  const double un = (rel[0] * n[0] + rel[1] * n[1]) + rel[2] * n[2];
  // FL7 (outsidePressureCoefficient): std::min's selections written out.
  const double into = 0.0 < c ? 0.0 : c;
  const double band = std::abs(c) * (1.0 / kAttachedFlowBand);
  const double base = band < 1.0 ? band : 1.0;
  const double cout = q.baseCoefficient * base + ((1.0 - q.baseCoefficient) * into) * into;
  const double ps = 0.0 - q.dynamicPressure * cout;
  const double net = ps - (q.normalDrag * std::abs(un)) * un;
  const double k = positive ? -((q.loadFactor * net) * third) : 0.0;
  for (int i = 0; i < 3; ++i) r[i] = k * A[i];
  o.cloth = 0.0, o.dCloth = 0.0;
  if (q.permeable) {
    // FL6 (ClothPermeability::velocity, dVelocity).
    const double dp = q.clothGauge + ps;
    double u, du;
    if (q.inertial == 0.0) {
      u = dp * q.perViscous;
      du = q.perViscous;
    } else {
      const double root = std::sqrt(q.viscous * q.viscous + (4.0 * q.inertial) * std::abs(dp));
      const double magnitude = (2.0 * std::abs(dp)) / (q.viscous + root);
      u = dp < 0.0 ? -magnitude : magnitude;
      du = 1.0 / root;
    }
    o.cloth = positive ? area * u : 0.0;
    o.dCloth = positive ? area * du : 0.0;
  }
  o.volume = ((xs[0] * A[0] + xs[1] * A[1]) + xs[2] * A[2]) * (1.0 / 9.0);
  o.area = area;
  for (int i = 0; i < 3; ++i) o.nodeArea[i] = A[i] * third;
  o.share = area * third;
}

}  // namespace chute::kernels
