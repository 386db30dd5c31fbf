#include "kernels/CableBatch.hpp"

#include "kernels/CableKernel.hpp"
#include "kernels/LaneVectors.hpp"
#include "kernels/Regularisations.hpp"

namespace chute::kernels {

void setCableLane(CableLanes& lanes, int lane, int a, int b, double L, const LineMaterial& mat,
                  const Eigen::Vector3d& weight, double dragCoefficient,
                  const Eigen::Vector3d& wind) {
  lanes.nodes[lane][0] = a, lanes.nodes[lane][1] = b;
  lanes.L[lane] = L;
  lanes.apex[lane] = kApexFraction * L;  // cableForceOnly's, to the bit
  lanes.E[lane] = mat.E;
  lanes.compressedE[lane] = mat.E * mat.compressionStiffnessRatio;
  lanes.area[lane] = mat.area;
  lanes.tensionOnly[lane] = mat.tensionOnly ? -1 : 0;
  for (int c = 0; c < 3; ++c) lanes.weight[c][lane] = weight[c];
  lanes.drag[lane] = dragCoefficient;
  for (int c = 0; c < 3; ++c) lanes.wind[c][lane] = wind[c];
}

void clearCableLane(CableLanes& lanes, int lane) {
  LineMaterial none;
  none.E = 0.0;
  none.area = 0.0;
  setCableLane(lanes, lane, 0, 0, 1.0, none, Eigen::Vector3d::Zero(), 0.0, Eigen::Vector3d::Zero());
}

namespace {
// The lanes' vectors and their helpers (kernels/LaneVectors.hpp).
static_assert(kCableLanes == lanes::kLanes);
using lanes::all;
using lanes::load;
using lanes::loadMask;
using lanes::M;
using lanes::sqrt;
using lanes::store;
using lanes::V;

// CB1: cableForceOnly, the weight and lineDragNodeResidual lane by lane, each in its own
// operations' order (Eigen's three-term sums and dot products run left to right).
[[gnu::always_inline]] inline void forcesAndDrag(const double* x, const double* v,
                                                 const CableLanes& t, double loadFactor,
                                                 double dragFactor,
                                                 const std::int64_t (&elastic)[kCableLanes],
                                                 CableLaneVectors& f) {
  V d[3], va[3], vb[3];
  for (int c = 0; c < 3; ++c) {
    const V xa = {x[3 * t.nodes[0][0] + c], x[3 * t.nodes[1][0] + c], x[3 * t.nodes[2][0] + c],
                  x[3 * t.nodes[3][0] + c]};
    const V xb = {x[3 * t.nodes[0][1] + c], x[3 * t.nodes[1][1] + c], x[3 * t.nodes[2][1] + c],
                  x[3 * t.nodes[3][1] + c]};
    d[c] = xb - xa;
    va[c] = V{v[3 * t.nodes[0][0] + c], v[3 * t.nodes[1][0] + c], v[3 * t.nodes[2][0] + c],
              v[3 * t.nodes[3][0] + c]};
    vb[c] = V{v[3 * t.nodes[0][1] + c], v[3 * t.nodes[1][1] + c], v[3 * t.nodes[2][1] + c],
              v[3 * t.nodes[3][1] + c]};
  }
  const V zero = all(0.0), two = all(2.0), half = all(0.5);
  // cableForceOnly (F1-F2 with RG1's apex).
  const V dd = (d[0] * d[0] + d[1] * d[1]) + d[2] * d[2];
  const V n = sqrt(dd);
  const V apex = load(t.apex);
  const M exact = n >= apex;
  const V length = exact ? n : (n * n + apex * apex) / (two * apex);
  const V by = exact ? n : apex;
  const V L = load(t.L);
  const V L2 = L * L;
  const V strain = (length * length - L2) / (two * L2);
  const M tensionOnly = loadMask(t.tensionOnly);
  V E = load(t.E);
  E = ((strain < zero) & tensionOnly) ? load(t.compressedE) : E;
  E = ((strain == zero) & tensionOnly) ? zero : E;
  const V EAoverL = E * load(t.area) / L;
  const M carries = loadMask(elastic);  // a cut cable has neither force nor weight
  const V N = carries ? EAoverL * strain * length : zero;
  // LD1: the drag's relative velocity normal to the chord.
  const V coefficient = load(t.drag) * all(dragFactor);
  const M none = (dd == zero) | (coefficient == zero);
  V rel[3];
  for (int c = 0; c < 3; ++c) rel[c] = half * (va[c] + vb[c]) - load(t.wind[c]);
  const V along = ((d[0] * rel[0] + d[1] * rel[1]) + d[2] * rel[2]) / dd;
  V u[3];
  for (int c = 0; c < 3; ++c) u[c] = rel[c] - along * d[c];
  const V uu = (u[0] * u[0] + u[1] * u[1]) + u[2] * u[2];
  const V k = half * coefficient * sqrt(dd * uu);
  const V lf = all(loadFactor);
  for (int c = 0; c < 3; ++c) {
    const V g = d[c] / by;
    const V weight = carries ? lf * load(t.weight[c]) : zero;
    const V drag = none ? zero : k * u[c];
    const V a = (N * (zero - g) - weight) + drag;
    const V b = (N * (zero + g) - weight) + drag;
    store(f.v[0][c], a);
    store(f.v[1][c], b);
    store(f.drag[c], drag);
  }
}

using Copy = void (*)(const double*, const double*, const CableLanes&, double, double,
                      const std::int64_t (&)[kCableLanes], CableLaneVectors&);
}  // namespace

void cableForcesAndDragBaseline(const double* x, const double* v, const CableLanes& t,
                                double loadFactor, double dragFactor,
                                const std::int64_t (&elastic)[kCableLanes], CableLaneVectors& f) {
  forcesAndDrag(x, v, t, loadFactor, dragFactor, elastic, f);
}

[[gnu::target("avx2")]] void cableForcesAndDragAvx2(const double* x, const double* v,
                                                    const CableLanes& t, double loadFactor,
                                                    double dragFactor,
                                                    const std::int64_t (&elastic)[kCableLanes],
                                                    CableLaneVectors& f) {
  forcesAndDrag(x, v, t, loadFactor, dragFactor, elastic, f);
}

void cableForcesAndDrag(const double* x, const double* v, const CableLanes& t, double loadFactor,
                        double dragFactor, const std::int64_t (&elastic)[kCableLanes],
                        CableLaneVectors& f) {
  static const Copy copy = useAvx2() ? &cableForcesAndDragAvx2 : &cableForcesAndDragBaseline;
  copy(x, v, t, loadFactor, dragFactor, elastic, f);
}

}  // namespace chute::kernels
