#pragma once
// The explicit step's membrane triangle (docs/formulation.md M1-M3, WR1-WR3): the internal force
// of a constant-strain triangle with the relaxed plane-stress St Venant-Kirchhoff law, residual
// only, from a record laid out for one pass over the canopy. It gives the bits membraneForce<3>
// gives with neither tangent nor principal values (a test holds the two bit for bit), in a third
// of its instructions: the law's constants are made once, the wrinkling state is selected without
// branches (on a folded canopy taut, wrinkled and slack triangles alternate at random, and the
// branches of planeStressSVK were mispredicted), and nothing goes through a result struct sized
// for the tangent.
#include <bit>
#include <cmath>
#include <cstdint>

#include "kernels/MembraneKernel.hpp"

namespace chute::kernels {

// What the triangle's force needs of its reference and its material.
struct MembraneTriangleRecord {
  double dN[3][2];  // dN_i / dX_alpha (MembraneReference<3>::dN)
  double weight;    // reference area times thickness
  double d00, d01,
      d22;  // the taut plane-stress matrix: c, c nu, c (1 - nu) / 2, c = E / (1 - nu^2)
  double E, nu;
  bool wrinkling;
};

inline MembraneTriangleRecord membraneTriangleRecord(const MembraneReference<3>& ref,
                                                     const MembraneMaterial& mat, bool wrinkling) {
  MembraneTriangleRecord r{};
  for (int i = 0; i < 3; ++i)
    for (int a = 0; a < 2; ++a) r.dN[i][a] = ref.dN[0](i, a);
  r.weight = ref.weight[0];
  // planeStressSVK's expressions, so the same bits.
  const double c = mat.E / (1.0 - mat.nu * mat.nu);
  r.d00 = c, r.d01 = c * mat.nu, r.d22 = c * (1.0 - mat.nu) / 2.0;
  r.E = mat.E, r.nu = mat.nu, r.wrinkling = wrinkling;
  return r;
}

namespace detail {
// a where pick, else b: by the bits, no branch (the discarded value may be NaN).
inline double select(bool pick, double a, double b) {
  const std::uint64_t mask = -static_cast<std::uint64_t>(pick);
  return std::bit_cast<double>((std::bit_cast<std::uint64_t>(a) & mask) |
                               (std::bit_cast<std::uint64_t>(b) & ~mask));
}
}  // namespace detail

// The relaxed law at the triangle's strain (M1-M2, WR1-WR3), in planeStressSVK's operations.
struct TriangleStrainState {
  double F[3][2];
  double e0, e1, e2;  // (E11, E22, 2 E12)
  double u, w, R, l1;
  bool taut, slack;
};
inline TriangleStrainState triangleStrainState(const double* x0, const double* x1, const double* x2,
                                               const MembraneTriangleRecord& t) {
  TriangleStrainState s;
  // M1: F = sum_i x_i dN_i^T and C = F^T F, in greenStrain's order.
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 2; ++c)
      s.F[r][c] = (x0[r] * t.dN[0][c] + x1[r] * t.dN[1][c]) + x2[r] * t.dN[2][c];
  const auto& F = s.F;
  const double c00 = (F[0][0] * F[0][0] + F[1][0] * F[1][0]) + F[2][0] * F[2][0];
  const double c11 = (F[0][1] * F[0][1] + F[1][1] * F[1][1]) + F[2][1] * F[2][1];
  const double c01 = (F[0][0] * F[0][1] + F[1][0] * F[1][1]) + F[2][0] * F[2][1];
  s.e0 = 0.5 * (c00 - 1.0), s.e1 = 0.5 * (c11 - 1.0), s.e2 = c01;
  // The principal strains l1 >= l2.
  const double a = s.e0, d = s.e1;
  s.w = 0.5 * s.e2, s.u = 0.5 * (a - d);
  s.R = std::sqrt(s.u * s.u + s.w * s.w);
  s.l1 = 0.5 * (a + d) + s.R;
  const double l2 = 0.5 * (a + d) - s.R;
  s.taut = !t.wrinkling || l2 + t.nu * s.l1 > 0.0;
  s.slack = !s.taut && s.l1 <= 0.0;
  return s;
}

// The triangle's strain energy (membraneEnergy<3>'s bits) at positions x0, x1, x2.
inline double membraneTriangleEnergy(const double* x0, const double* x1, const double* x2,
                                     const MembraneTriangleRecord& t) {
  const TriangleStrainState s = triangleStrainState(x0, x1, x2, t);
  const double t0 = t.d00 * s.e0 + t.d01 * s.e1, t1 = t.d01 * s.e0 + t.d00 * s.e1,
               t2 = t.d22 * s.e2;
  const double taut = 0.5 * ((s.e0 * t0 + s.e1 * t1) + s.e2 * t2);
  const double wrinkled = 0.5 * t.E * s.l1 * s.l1;
  return t.weight * detail::select(s.taut, taut, detail::select(s.slack, 0.0, wrinkled));
}

// The nodal forces f (node by node, xyz) of the triangle at positions x0, x1, x2; returns its
// wrinkling state.
inline WrinkleState membraneTriangleForce(const double* x0, const double* x1, const double* x2,
                                          const MembraneTriangleRecord& t, double* f) {
  const TriangleStrainState st = triangleStrainState(x0, x1, x2, t);
  const auto& F = st.F;
  const double e0 = st.e0, e1 = st.e1, e2 = st.e2, u = st.u, w = st.w, R = st.R, l1 = st.l1;
  const bool taut = st.taut, slack = st.slack;
  // Taut: S = D e (D's zeros add nothing to a product's sum).
  const double t0 = t.d00 * e0 + t.d01 * e1, t1 = t.d01 * e0 + t.d00 * e1, t2 = t.d22 * e2;
  // Wrinkled: S = E l1 d l1/de.
  const double El1 = t.E * l1;
  const double w0 = El1 * (0.5 + 0.5 * u / R), w1 = El1 * (0.5 - 0.5 * u / R),
               w2 = El1 * (0.5 * w / R);
  const double s0 = detail::select(taut, t0, detail::select(slack, 0.0, w0));
  const double s1 = detail::select(taut, t1, detail::select(slack, 0.0, w1));
  const double s2 = detail::select(taut, t2, detail::select(slack, 0.0, w2));
  // M3: f_i = w (F S) dN_i, as membraneForce's residual-only product w (F S2) dN^T forms it (Eigen
  // moves the scalar onto F: (w F) S2).
  double P[3][2];
  for (int r = 0; r < 3; ++r) {
    const double wf0 = t.weight * F[r][0], wf1 = t.weight * F[r][1];
    P[r][0] = wf0 * s0 + wf1 * s2;
    P[r][1] = wf0 * s2 + wf1 * s1;
  }
  for (int i = 0; i < 3; ++i)
    for (int r = 0; r < 3; ++r) f[3 * i + r] = P[r][0] * t.dN[i][0] + P[r][1] * t.dN[i][1];
  return taut ? WrinkleState::Taut : (slack ? WrinkleState::Slack : WrinkleState::Wrinkled);
}

}  // namespace chute::kernels
