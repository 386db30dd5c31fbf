#include "kernels/MembraneTriangleBatch.hpp"

#include <cstring>

// GCC warns that a 32-byte vector returned without AVX changes the calling convention; in this
// file such vectors live only inside the inlined body and its helpers, never across a call (the
// helpers take them by reference: by value GCC notes the parameters' convention).
#pragma GCC diagnostic ignored "-Wpsabi"

namespace chute::kernels {

void setLane(MembraneTriangleLanes& lanes, int lane, const MembraneTriangleRecord& t,
             const std::array<int, 3>& nodes) {
  for (int i = 0; i < 3; ++i) lanes.nodes[lane][i] = nodes[i];
  for (int i = 0; i < 3; ++i)
    for (int a = 0; a < 2; ++a) lanes.dN[i][a][lane] = t.dN[i][a];
  lanes.weight[lane] = t.weight;
  lanes.d00[lane] = t.d00, lanes.d01[lane] = t.d01, lanes.d22[lane] = t.d22;
  lanes.E[lane] = t.E, lanes.nu[lane] = t.nu;
  lanes.noWrinkling[lane] = t.wrinkling ? 0 : -1;
}

namespace {
// GCC's vector extension: four doubles, and four 64-bit masks (all bits set: true). On the
// baseline instruction set each operation is made of two SSE2 ones, on AVX2 of one.
using V = double __attribute__((vector_size(8 * kTriangleLanes)));
using M = std::int64_t __attribute__((vector_size(8 * kTriangleLanes)));

[[gnu::always_inline]] inline V load(const double* p) {
  V v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
[[gnu::always_inline]] inline M loadMask(const std::int64_t* p) {
  M v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
[[gnu::always_inline]] inline void store(double* p, const V& v) {
  std::memcpy(p, &v, sizeof v);
}
[[gnu::always_inline]] inline V all(double s) {
  return V{s, s, s, s};
}
[[gnu::always_inline]] inline V sqrt(const V& a) {
  V r;
  for (int l = 0; l < kTriangleLanes; ++l) r[l] = __builtin_sqrt(a[l]);
  return r;
}

// membraneTriangleForce (MembraneTriangleForce.hpp) lane by lane: the same operations in the
// same order, the wrinkling state selected by masks as its select() does by bits.
[[gnu::always_inline]] inline void forces(const double* x, const MembraneTriangleLanes& t,
                                          TriangleLaneVectors& fs, WrinkleState* state) {
  const double* at[3][kTriangleLanes];
  for (int i = 0; i < 3; ++i)
    for (int l = 0; l < kTriangleLanes; ++l) at[i][l] = x + 3 * t.nodes[l][i];
  V dN[3][2];
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 2; ++c) dN[i][c] = load(t.dN[i][c]);
  // M1: F = sum_i x_i dN_i^T and C = F^T F.
  V F[3][2];
  for (int r = 0; r < 3; ++r) {
    const V x0 = {at[0][0][r], at[0][1][r], at[0][2][r], at[0][3][r]};
    const V x1 = {at[1][0][r], at[1][1][r], at[1][2][r], at[1][3][r]};
    const V x2 = {at[2][0][r], at[2][1][r], at[2][2][r], at[2][3][r]};
    for (int c = 0; c < 2; ++c) F[r][c] = (x0 * dN[0][c] + x1 * dN[1][c]) + x2 * dN[2][c];
  }
  const V c00 = (F[0][0] * F[0][0] + F[1][0] * F[1][0]) + F[2][0] * F[2][0];
  const V c11 = (F[0][1] * F[0][1] + F[1][1] * F[1][1]) + F[2][1] * F[2][1];
  const V c01 = (F[0][0] * F[0][1] + F[1][0] * F[1][1]) + F[2][0] * F[2][1];
  const V half = all(0.5), one = all(1.0), zero = all(0.0);
  const V e0 = half * (c00 - one), e1 = half * (c11 - one), e2 = c01;
  // The principal strains l1 >= l2.
  const V a = e0, d = e1;
  const V w = half * e2, u = half * (a - d);
  const V q = u * u + w * w;
  const V R = sqrt(q);
  const V l1 = half * (a + d) + R;
  const V l2 = half * (a + d) - R;
  const V nu = load(t.nu);
  const M taut = loadMask(t.noWrinkling) | (l2 + nu * l1 > zero);
  const M slack = ~taut & (l1 <= zero);
  // Taut: S = D e; wrinkled: S = E l1 d l1/de.
  const V d00 = load(t.d00), d01 = load(t.d01), d22 = load(t.d22);
  const V t0 = d00 * e0 + d01 * e1, t1 = d01 * e0 + d00 * e1, t2 = d22 * e2;
  const V El1 = load(t.E) * l1;
  const V w0 = El1 * (half + half * u / R), w1 = El1 * (half - half * u / R),
          w2 = El1 * (half * w / R);
  const V s0 = taut ? t0 : (slack ? zero : w0);
  const V s1 = taut ? t1 : (slack ? zero : w1);
  const V s2 = taut ? t2 : (slack ? zero : w2);
  // M3: f_i = w (F S) dN_i.
  const V weight = load(t.weight);
  V P[3][2];
  for (int r = 0; r < 3; ++r) {
    const V wf0 = weight * F[r][0], wf1 = weight * F[r][1];
    P[r][0] = wf0 * s0 + wf1 * s2;
    P[r][1] = wf0 * s2 + wf1 * s1;
  }
  for (int i = 0; i < 3; ++i)
    for (int r = 0; r < 3; ++r) store(fs.v[i][r], P[r][0] * dN[i][0] + P[r][1] * dN[i][1]);
  if (state)
    for (int l = 0; l < kTriangleLanes; ++l)
      state[l] =
          taut[l] ? WrinkleState::Taut : (slack[l] ? WrinkleState::Slack : WrinkleState::Wrinkled);
}

using Forces = void (*)(const double*, const MembraneTriangleLanes&, TriangleLaneVectors&,
                        WrinkleState*);
}  // namespace

void membraneTriangleForcesBaseline(const double* x, const MembraneTriangleLanes& t,
                                    TriangleLaneVectors& f, WrinkleState* state) {
  forces(x, t, f, state);
}

[[gnu::target("avx2")]] void membraneTriangleForcesAvx2(const double* x,
                                                        const MembraneTriangleLanes& t,
                                                        TriangleLaneVectors& f,
                                                        WrinkleState* state) {
  forces(x, t, f, state);
}

void membraneTriangleForces(const double* x, const MembraneTriangleLanes& t, TriangleLaneVectors& f,
                            WrinkleState* state) {
  static const Forces copy =
      useAvx2() ? &membraneTriangleForcesAvx2 : &membraneTriangleForcesBaseline;
  copy(x, t, f, state);
}

}  // namespace chute::kernels
