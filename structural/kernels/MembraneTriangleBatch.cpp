#include "kernels/MembraneTriangleBatch.hpp"

#include <cstddef>

#include "kernels/LaneVectors.hpp"

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
// The lanes' vectors and their helpers (kernels/LaneVectors.hpp).
static_assert(kTriangleLanes == lanes::kLanes);
using lanes::abs;
using lanes::all;
using lanes::load;
using lanes::loadMask;
using lanes::M;
using lanes::sqrt;
using lanes::store;
using lanes::V;

// triangleFaceLoad (TriangleFaceLoads.hpp) lane by lane, the same operations in the same order,
// from the lanes' edges x1 - x0, x2 - x0 already formed and the velocities at v.
[[gnu::always_inline]] inline void faceLoads(const V (&e1)[3], const V (&e2)[3], const double* v,
                                             const MembraneTriangleLanes& t,
                                             const TriangleFaceLoadLanes& q, V (&f)[3]) {
  const double* pv[3][kTriangleLanes];
  for (int i = 0; i < 3; ++i)
    for (int l = 0; l < kTriangleLanes; ++l) pv[i][l] = v + 3 * t.nodes[l][i];
  V vf[3];
  for (int c = 0; c < 3; ++c) {
    const V v0 = {pv[0][0][c], pv[0][1][c], pv[0][2][c], pv[0][3][c]};
    const V v1 = {pv[1][0][c], pv[1][1][c], pv[1][2][c], pv[1][3][c]};
    const V v2 = {pv[2][0][c], pv[2][1][c], pv[2][2][c], pv[2][3][c]};
    vf[c] = (v0 + v1) + v2;
  }
  const V half = all(0.5), zero = all(0.0), third = all(1.0 / 3.0);
  const V A[3] = {half * (e1[1] * e2[2] - e1[2] * e2[1]), half * (e1[2] * e2[0] - e1[0] * e2[2]),
                  half * (e1[0] * e2[1] - e1[1] * e2[0])};
  const V aa = (A[0] * A[0] + A[1] * A[1]) + A[2] * A[2];
  V rel[3], w[3];
  for (int c = 0; c < 3; ++c) {
    w[c] = load(q.wind[c]);
    rel[c] = vf[c] * third - w[c];
  }
  const V ua = (rel[0] * A[0] + rel[1] * A[1]) + rel[2] * A[2];
  const V u0a = -((w[0] * A[0] + w[1] * A[1]) + w[2] * A[2]);
  const V num = abs(ua) * ua - load(q.steady) * (abs(u0a) * u0a);
  const M positive = aa > zero;
  const V g = positive ? num / (positive ? aa : all(1.0)) : zero;
  const V k = (load(q.drag) * g - load(q.pressure)) * third;
  for (int c = 0; c < 3; ++c) f[c] = k * A[c];
}

// triangleFlowLoad (TriangleFlowLoads.hpp) lane by lane, the same operations in the same order,
// from the lanes' edges x1 - x0, x2 - x0 and sums x0 + x1 + x2 already formed, the velocities at
// v: f, each lane's residual per node; sums, its sums.
[[gnu::always_inline]] inline void flowLoads(const V (&edge1)[3], const V (&edge2)[3],
                                             const V (&xsum)[3], const double* v,
                                             const MembraneTriangleLanes& t,
                                             const TriangleFlowParameters& q, V (&f)[3],
                                             V (&sums)[8]) {
  const double* pv[3][kTriangleLanes];
  for (int i = 0; i < 3; ++i)
    for (int l = 0; l < kTriangleLanes; ++l) pv[i][l] = v + 3 * t.nodes[l][i];
  const V b = all(q.dampingShift), third = all(1.0 / 3.0), zero = all(0.0), one = all(1.0);
  V e1[3], e2[3], vs[3], xs[3];
  for (int c = 0; c < 3; ++c) {
    const V v0 = {pv[0][0][c], pv[0][1][c], pv[0][2][c], pv[0][3][c]};
    const V v1 = {pv[1][0][c], pv[1][1][c], pv[1][2][c], pv[1][3][c]};
    const V v2 = {pv[2][0][c], pv[2][1][c], pv[2][2][c], pv[2][3][c]};
    e1[c] = edge1[c] - b * (v1 - v0);
    e2[c] = edge2[c] - b * (v2 - v0);
    vs[c] = (v0 + v1) + v2;
    xs[c] = xsum[c] - b * vs[c];
  }
  const V half = all(0.5);
  const V A[3] = {half * (e1[1] * e2[2] - e1[2] * e2[1]), half * (e1[2] * e2[0] - e1[0] * e2[2]),
                  half * (e1[0] * e2[1] - e1[1] * e2[0])};
  const V aa = (A[0] * A[0] + A[1] * A[1]) + A[2] * A[2];
  const V area = sqrt(aa);
  const M positive = aa > zero;
  const V inv = one / (positive ? area : one);
  V n[3], rel[3];
  for (int c = 0; c < 3; ++c) {
    n[c] = A[c] * inv;
    rel[c] = vs[c] * third - all(q.canopyVelocity[c]);
  }
  const V c = (n[0] * all(q.flowDirection[0]) + n[1] * all(q.flowDirection[1])) +
              n[2] * all(q.flowDirection[2]);
  const V un = (rel[0] * n[0] + rel[1] * n[1]) + rel[2] * n[2];
  const V into = zero < c ? zero : c;
  const V band = abs(c) * all(1.0 / kAttachedFlowBand);
  const V base = band < one ? band : one;
  const V cb = all(q.baseCoefficient);
  const V cout = cb * base + ((one - cb) * into) * into;
  const V ps = zero - all(q.dynamicPressure) * cout;
  const V net = ps - (all(q.normalDrag) * abs(un)) * un;
  const V k = positive ? -((all(q.loadFactor) * net) * third) : zero;
  for (int i = 0; i < 3; ++i) f[i] = k * A[i];
  // sums: A / 3 (three), |A| / 3, the volume, |A|, the cloth's outflow and its derivative.
  V cloth = zero, dCloth = zero;
  if (q.permeable) {
    const V dp = all(q.clothGauge) + ps;
    V u, du;
    if (q.inertial == 0.0) {
      u = dp * all(q.perViscous);
      du = all(q.perViscous);
    } else {
      const V root = sqrt(all(q.viscous) * all(q.viscous) + all(4.0 * q.inertial) * abs(dp));
      const V magnitude = (all(2.0) * abs(dp)) / (all(q.viscous) + root);
      u = dp < zero ? -magnitude : magnitude;
      du = one / root;
    }
    cloth = positive ? area * u : zero;
    dCloth = positive ? area * du : zero;
  }
  for (int i = 0; i < 3; ++i) sums[i] = A[i] * third;
  sums[3] = area * third;
  sums[4] = ((xs[0] * A[0] + xs[1] * A[1]) + xs[2] * A[2]) * all(1.0 / 9.0);
  sums[5] = area;
  sums[6] = cloth;
  sums[7] = dCloth;
}

// The lanes' strain state (triangleStrainState, MembraneTriangleForce.hpp) lane by lane, the same
// operations in the same order; with it the edges x1 - x0, x2 - x0 and the sums x0 + x1 + x2 the
// face loads use (dropped where unused).
struct LaneStrain {
  V dN[3][2], F[3][2], edge1[3], edge2[3], xsum[3];
  V e0, e1, e2, u, w, R, l1;
  M taut, slack;
};
[[gnu::always_inline]] inline void laneStrain(const double* x, const MembraneTriangleLanes& t,
                                              LaneStrain& s) {
  const double* at[3][kTriangleLanes];
  for (int i = 0; i < 3; ++i)
    for (int l = 0; l < kTriangleLanes; ++l) at[i][l] = x + 3 * t.nodes[l][i];
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 2; ++c) s.dN[i][c] = load(t.dN[i][c]);
  // M1: F = sum_i x_i dN_i^T and C = F^T F.
  for (int r = 0; r < 3; ++r) {
    const V x0 = {at[0][0][r], at[0][1][r], at[0][2][r], at[0][3][r]};
    const V x1 = {at[1][0][r], at[1][1][r], at[1][2][r], at[1][3][r]};
    const V x2 = {at[2][0][r], at[2][1][r], at[2][2][r], at[2][3][r]};
    for (int c = 0; c < 2; ++c) s.F[r][c] = (x0 * s.dN[0][c] + x1 * s.dN[1][c]) + x2 * s.dN[2][c];
    s.edge1[r] = x1 - x0;
    s.edge2[r] = x2 - x0;
    s.xsum[r] = (x0 + x1) + x2;
  }
  const auto& F = s.F;
  const V c00 = (F[0][0] * F[0][0] + F[1][0] * F[1][0]) + F[2][0] * F[2][0];
  const V c11 = (F[0][1] * F[0][1] + F[1][1] * F[1][1]) + F[2][1] * F[2][1];
  const V c01 = (F[0][0] * F[0][1] + F[1][0] * F[1][1]) + F[2][0] * F[2][1];
  const V half = all(0.5), one = all(1.0), zero = all(0.0);
  s.e0 = half * (c00 - one), s.e1 = half * (c11 - one), s.e2 = c01;
  // The principal strains l1 >= l2.
  const V a = s.e0, d = s.e1;
  s.w = half * s.e2, s.u = half * (a - d);
  const V q = s.u * s.u + s.w * s.w;
  s.R = sqrt(q);
  s.l1 = half * (a + d) + s.R;
  const V l2 = half * (a + d) - s.R;
  const V nu = load(t.nu);
  s.taut = loadMask(t.noWrinkling) | (l2 + nu * s.l1 > zero);
  s.slack = ~s.taut & (s.l1 <= zero);
}

// membraneTriangleEnergy (MembraneTriangleForce.hpp) lane by lane, the same operations in the
// same order.
[[gnu::always_inline]] inline void energies(const double* x, const MembraneTriangleLanes& t,
                                            double (&energy)[kTriangleLanes]) {
  LaneStrain s;
  laneStrain(x, t, s);
  const V half = all(0.5), zero = all(0.0);
  const V d00 = load(t.d00), d01 = load(t.d01), d22 = load(t.d22);
  const V t0 = d00 * s.e0 + d01 * s.e1, t1 = d01 * s.e0 + d00 * s.e1, t2 = d22 * s.e2;
  const V taut = half * ((s.e0 * t0 + s.e1 * t1) + s.e2 * t2);
  const V wrinkled = ((half * load(t.E)) * s.l1) * s.l1;
  store(energy, load(t.weight) * (s.taut ? taut : (s.slack ? zero : wrinkled)));
}

// membraneTriangleForce (MembraneTriangleForce.hpp) lane by lane: the same operations in the
// same order, the wrinkling state selected by masks as its select() does by bits.
// With face loads (v and q given): fs gets each lane's face load added, loads the load alone.
[[gnu::always_inline]] inline void forces(
    const double* x, const MembraneTriangleLanes& t, TriangleLaneVectors& fs, WrinkleState* state,
    const double* v = nullptr, const TriangleFaceLoadLanes* faceLoad = nullptr,
    double (*loads)[kTriangleLanes] = nullptr, const TriangleFlowParameters* flow = nullptr,
    const TriangleFlowBatch* batch = nullptr, TriangleFlowAccumulators* acc = nullptr,
    double* records = nullptr) {
  LaneStrain s;
  laneStrain(x, t, s);
  const auto& F = s.F;
  const auto& dN = s.dN;
  const auto &edge1 = s.edge1, &edge2 = s.edge2, &xsum = s.xsum;
  const V e0 = s.e0, e1 = s.e1, e2 = s.e2, u = s.u, w = s.w, R = s.R, l1 = s.l1;
  const M taut = s.taut, slack = s.slack;
  const V half = all(0.5), zero = all(0.0);
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
  if (faceLoad) {
    // P2 added to each node's force, as the triangles one at a time add it.
    V f[3];
    faceLoads(edge1, edge2, v, t, *faceLoad, f);
    for (int i = 0; i < 3; ++i)
      for (int r = 0; r < 3; ++r)
        store(fs.v[i][r], (P[r][0] * dN[i][0] + P[r][1] * dN[i][1]) + f[r]);
    for (int r = 0; r < 3; ++r) store(loads[r], f[r]);
  } else if (flow) {
    // FL13 added to each node's force in the flow's lanes, as the triangles one at a time add it.
    V f[3], sums[8];
    flowLoads(edge1, edge2, xsum, v, t, *flow, f, sums);
    const M in = loadMask(batch->inFlow);
    for (int i = 0; i < 3; ++i)
      for (int r = 0; r < 3; ++r) {
        const V force = P[r][0] * dN[i][0] + P[r][1] * dN[i][1];
        store(fs.v[i][r], in ? force + f[r] : force);
      }
    for (int r = 0; r < 3; ++r) store(loads[r], f[r]);
    double* accumulated[4] = {acc->volume, acc->area, acc->cloth, acc->dCloth};
    for (int k = 0; k < 4; ++k) {
      const V before = load(accumulated[k]);
      store(accumulated[k], in ? before + sums[4 + k] : before);
    }
    // Each lane's record (A / 3, |A| / 3) as four consecutive doubles, lane after lane: the
    // four sums' vectors transposed (each node gathers its triangles' records after the pass;
    // adding them at the nodes here, lane by lane, had cost 19 instructions a lane).
    const M lo = {0, 4, 2, 6}, hi = {1, 5, 3, 7}, first = {0, 1, 4, 5}, second = {2, 3, 6, 7};
    const V s01lo = __builtin_shuffle(sums[0], sums[1], lo);
    const V s01hi = __builtin_shuffle(sums[0], sums[1], hi);
    const V s23lo = __builtin_shuffle(sums[2], sums[3], lo);
    const V s23hi = __builtin_shuffle(sums[2], sums[3], hi);
    store(records, __builtin_shuffle(s01lo, s23lo, first));
    store(records + 4, __builtin_shuffle(s01hi, s23hi, first));
    store(records + 8, __builtin_shuffle(s01lo, s23lo, second));
    store(records + 12, __builtin_shuffle(s01hi, s23hi, second));
  } else {
    for (int i = 0; i < 3; ++i)
      for (int r = 0; r < 3; ++r) store(fs.v[i][r], P[r][0] * dN[i][0] + P[r][1] * dN[i][1]);
  }
  if (state)
    for (int l = 0; l < kTriangleLanes; ++l)
      state[l] =
          taut[l] ? WrinkleState::Taut : (slack[l] ? WrinkleState::Slack : WrinkleState::Wrinkled);
}

using Forces = void (*)(const double*, const MembraneTriangleLanes&, TriangleLaneVectors&,
                        WrinkleState*);
using Energies = void (*)(const double*, const MembraneTriangleLanes&, double (&)[kTriangleLanes]);
using ForcesAndLoads = void (*)(const double*, const double*, const MembraneTriangleLanes&,
                                const TriangleFaceLoadLanes&, TriangleLaneVectors&,
                                double (&)[3][kTriangleLanes]);
[[gnu::always_inline]] inline void gatherRecords(const double* records, const int* start,
                                                 const int* at, size_t begin, size_t end,
                                                 double perArea, double* out, size_t stride) {
  const V scale = {1.0, 1.0, 1.0, perArea};
  for (size_t i = begin; i < end; ++i) {
    V sum = all(0.0);
    for (int k = start[i]; k < start[i + 1]; ++k) sum += load(records + at[k]);
    store(out + stride * i, sum * scale);
  }
}

using Gather = void (*)(const double*, const int*, const int*, size_t, size_t, double, double*,
                        size_t);
using ForcesAndFlow = void (*)(const double*, const double*, const MembraneTriangleLanes&,
                               const TriangleFlowBatch&, const TriangleFlowParameters&,
                               TriangleLaneVectors&, double (&)[3][kTriangleLanes],
                               TriangleFlowAccumulators&, double*);
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

void membraneTriangleEnergiesBaseline(const double* x, const MembraneTriangleLanes& t,
                                      double (&energy)[kTriangleLanes]) {
  energies(x, t, energy);
}

[[gnu::target("avx2")]] void membraneTriangleEnergiesAvx2(const double* x,
                                                          const MembraneTriangleLanes& t,
                                                          double (&energy)[kTriangleLanes]) {
  energies(x, t, energy);
}

void membraneTriangleEnergies(const double* x, const MembraneTriangleLanes& t,
                              double (&energy)[kTriangleLanes]) {
  static const Energies copy =
      useAvx2() ? &membraneTriangleEnergiesAvx2 : &membraneTriangleEnergiesBaseline;
  copy(x, t, energy);
}

void membraneTriangleForcesAndLoadsBaseline(const double* x, const double* v,
                                            const MembraneTriangleLanes& t,
                                            const TriangleFaceLoadLanes& q, TriangleLaneVectors& f,
                                            double (&loads)[3][kTriangleLanes]) {
  forces(x, t, f, nullptr, v, &q, loads);
}

[[gnu::target("avx2")]] void membraneTriangleForcesAndLoadsAvx2(
    const double* x, const double* v, const MembraneTriangleLanes& t,
    const TriangleFaceLoadLanes& q, TriangleLaneVectors& f, double (&loads)[3][kTriangleLanes]) {
  forces(x, t, f, nullptr, v, &q, loads);
}

void membraneTriangleForcesAndLoads(const double* x, const double* v,
                                    const MembraneTriangleLanes& t, const TriangleFaceLoadLanes& q,
                                    TriangleLaneVectors& f, double (&loads)[3][kTriangleLanes]) {
  static const ForcesAndLoads copy =
      useAvx2() ? &membraneTriangleForcesAndLoadsAvx2 : &membraneTriangleForcesAndLoadsBaseline;
  copy(x, v, t, q, f, loads);
}

void membraneTriangleForcesAndFlowBaseline(const double* x, const double* v,
                                           const MembraneTriangleLanes& t,
                                           const TriangleFlowBatch& batch,
                                           const TriangleFlowParameters& q, TriangleLaneVectors& f,
                                           double (&loads)[3][kTriangleLanes],
                                           TriangleFlowAccumulators& acc, double* records) {
  forces(x, t, f, nullptr, v, nullptr, loads, &q, &batch, &acc, records);
}

[[gnu::target("avx2")]] void membraneTriangleForcesAndFlowAvx2(
    const double* x, const double* v, const MembraneTriangleLanes& t,
    const TriangleFlowBatch& batch, const TriangleFlowParameters& q, TriangleLaneVectors& f,
    double (&loads)[3][kTriangleLanes], TriangleFlowAccumulators& acc, double* records) {
  forces(x, t, f, nullptr, v, nullptr, loads, &q, &batch, &acc, records);
}

void membraneTriangleForcesAndFlow(const double* x, const double* v, const MembraneTriangleLanes& t,
                                   const TriangleFlowBatch& batch, const TriangleFlowParameters& q,
                                   TriangleLaneVectors& f, double (&loads)[3][kTriangleLanes],
                                   TriangleFlowAccumulators& acc, double* records) {
  static const ForcesAndFlow copy =
      useAvx2() ? &membraneTriangleForcesAndFlowAvx2 : &membraneTriangleForcesAndFlowBaseline;
  copy(x, v, t, batch, q, f, loads, acc, records);
}

void gatherTriangleRecordsBaseline(const double* records, const int* start, const int* at,
                                   size_t begin, size_t end, double perArea, double* out,
                                   size_t stride) {
  gatherRecords(records, start, at, begin, end, perArea, out, stride);
}

[[gnu::target("avx2")]] void gatherTriangleRecordsAvx2(const double* records, const int* start,
                                                       const int* at, size_t begin, size_t end,
                                                       double perArea, double* out, size_t stride) {
  gatherRecords(records, start, at, begin, end, perArea, out, stride);
}

void gatherTriangleRecords(const double* records, const int* start, const int* at, size_t begin,
                           size_t end, double perArea, double* out, size_t stride) {
  static const Gather copy =
      useAvx2() ? &gatherTriangleRecordsAvx2 : &gatherTriangleRecordsBaseline;
  copy(records, start, at, begin, end, perArea, out, stride);
}

}  // namespace chute::kernels
