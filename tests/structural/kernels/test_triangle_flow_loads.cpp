// The airflow's loads of a canopy triangle in the membranes' pass (docs/formulation.md FL13): the
// face law of the airflow's term (canopyFaceLoad, FL7-FL8 at the ambient inside pressure) and
// its sums (FL2's volume, FL6's cloth outflow, FL11's shares) at the step's own positions,
// recovered from EX7's damped ones, to round-off; and four at a time inside the membranes' own
// four-lane kernel, each lane membraneTriangleForce's forces plus triangleFlowLoad's load where
// the lane is the flow's (the forces alone elsewhere), bit for bit, on the baseline copy and on
// the AVX2 copy where the processor has it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <utility>
#include <vector>

#include "kernels/CanopyFlow.hpp"
#include "kernels/MembraneKernel.hpp"
#include "kernels/MembraneTriangleBatch.hpp"
#include "kernels/TriangleFlowLoads.hpp"
#include "support/MembraneGeometry.hpp"

using namespace chute::kernels;
using chute::testing::deformed;
using chute::testing::randomVector;

namespace {

const MembraneMaterial kFabric{4.32e6, 0.3, 5e-4, 1.6};

// A canopy-wide state; cloth 0: impermeable, 1: linear, 2: with an inertial part.
TriangleFlowParameters randomFlow(std::mt19937& rng, int cloth) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  TriangleFlowParameters q;
  const Vec3 d = randomVector(rng, 1.0).normalized(), vc = randomVector(rng, 20.0);
  for (int c = 0; c < 3; ++c) q.flowDirection[c] = d[c], q.canopyVelocity[c] = vc[c];
  q.dynamicPressure = 50.0 + 500.0 * u(rng);
  q.baseCoefficient = -0.6 - 0.4 * u(rng);
  q.normalDrag = 0.5 * 1.225 * 1.17;
  q.clothGauge = 300.0 * (u(rng) - 0.3);
  if (cloth > 0) {
    const ClothPermeability law =
        ClothPermeability::fromTest(0.3 + 0.4 * u(rng), 124.5, cloth == 2 ? 100.0 * u(rng) : 0.0);
    q.permeable = true;
    q.viscous = law.viscous, q.inertial = law.inertial, q.perViscous = law.perViscous;
  }
  q.loadFactor = 0.5 + u(rng);
  q.dampingShift = u(rng) < 0.5 ? 0.0 : 1e-5 * (1.0 + u(rng));
  return q;
}

}  // namespace

TEST(TriangleFlowLoads, AreTheAirflowsFaceLawAndSumsAtTheStepsPositions) {
  std::mt19937 rng(11);
  double worstLoad = 0.0, worstSums = 0.0;
  int degenerate = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    TriangleFlowParameters q = randomFlow(rng, trial % 3);
    std::array<Vec3, 3> x, v, given;
    for (int i = 0; i < 3; ++i) x[i] = randomVector(rng, 1.0), v[i] = randomVector(rng, 30.0);
    if (trial % 101 == 0) {  // no area: no load, no share, no cloth (undamped: exactly none)
      x[2] = x[1], q.dampingShift = 0.0;
      ++degenerate;
    }
    for (int i = 0; i < 3; ++i) given[i] = x[i] + q.dampingShift * v[i];  // EX7's positions
    double r[3];
    TriangleFlowSums o;
    triangleFlowLoad(given[0].data(), given[1].data(), given[2].data(), v[0].data(), v[1].data(),
                     v[2].data(), q, r, o);
    // The reference: the term's face law at the ambient inside pressure, at the step's positions.
    CanopyFlowState s;
    s.flowDirection = Vec3(q.flowDirection[0], q.flowDirection[1], q.flowDirection[2]);
    s.canopyVelocity = Vec3(q.canopyVelocity[0], q.canopyVelocity[1], q.canopyVelocity[2]);
    s.dynamicPressure = q.dynamicPressure, s.baseCoefficient = q.baseCoefficient;
    s.normalDrag = q.normalDrag;
    const auto f = canopyFaceLoad<3>(x, v, s, false);
    const Vec3 A = 0.5 * (x[1] - x[0]).cross(x[2] - x[0]);
    if (!(A.norm() > 0.0)) {
      for (int c = 0; c < 3; ++c) EXPECT_EQ(r[c], 0.0);
      EXPECT_EQ(o.cloth, 0.0);
      continue;
    }
    const double scale = f.residual.cwiseAbs().maxCoeff();
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < 3; ++c)
        worstLoad =
            std::max(worstLoad, std::abs(r[c] - q.loadFactor * f.residual[3 * i + c]) / scale);
    ClothPermeability law;
    law.viscous = q.viscous, law.inertial = q.inertial, law.perViscous = q.perViscous;
    const double dp = q.clothGauge + f.staticDifference;
    const double cloth = q.permeable ? A.norm() * law.velocity(dp) : 0.0;
    const double dCloth = q.permeable ? A.norm() * law.dVelocity(dp) : 0.0;
    const double sums[][3] = {
        {o.volume, tetraVolume(x[0], x[1], x[2]), std::abs(tetraVolume(x[0], x[1], x[2])) + 1e-3},
        {o.area, A.norm(), A.norm()},
        {o.share, A.norm() / 3, A.norm()},
        {o.cloth, cloth, std::abs(cloth) + 1e-12},
        {o.dCloth, dCloth, std::abs(dCloth) + 1e-12},
        {o.nodeArea[0], A[0] / 3, A.norm()},
        {o.nodeArea[1], A[1] / 3, A.norm()},
        {o.nodeArea[2], A[2] / 3, A.norm()}};
    for (const auto& [got, want, size] : sums)
      worstSums = std::max(worstSums, std::abs(got - want) / size);
  }
  std::printf(
      "FL13 against the airflow's face law and sums at the step's positions: loads %.3g, sums %.3g "
      "(3000 triangles, %d without area; half at EX7's damped positions)\n",
      worstLoad, worstSums, degenerate);
  // The positions recovered from the damped ones, x + beta v - beta v, differ by their round-off
  // (relative 1e-16 of the positions, 1e-15 of a unit triangle's edges).
  EXPECT_LE(worstLoad, 1e-12);
  EXPECT_LE(worstSums, 1e-12);
}

TEST(TriangleFlowLoads, FourAtATimeInTheMembranesPassAreTheTrianglesOneAtATimeBitForBit) {
  // Batches of four triangles, some lanes not the canopy's; the lanes' sums go to accumulators
  // that already hold sums, which the triangles one at a time then add to in the same order, and
  // each lane's shares to its record.
  std::mt19937 rng(53);
  std::uniform_real_distribution<double> jitter(-0.4, 0.4), any(-10.0, 10.0);
  const double stretch[][3] = {{1.04, 1.02, 0.01}, {1.05, 0.97, 0.005}, {0.95, 0.97, 0.0}};
  using Copy =
      void (*)(const double*, const double*, const MembraneTriangleLanes&, const TriangleFlowBatch&,
               const TriangleFlowParameters&, TriangleLaneVectors&, double(&)[3][kTriangleLanes],
               TriangleFlowAccumulators&, double*);
  std::vector<std::pair<const char*, Copy>> copies = {
      {"baseline", &membraneTriangleForcesAndFlowBaseline},
      {"dispatched", &membraneTriangleForcesAndFlow}};
  if (avx2Available()) copies.emplace_back("avx2", &membraneTriangleForcesAndFlowAvx2);
  int compared = 0;
  for (int batch = 0; batch < 1500; ++batch) {
    const TriangleFlowParameters q = randomFlow(rng, batch % 3);
    MembraneTriangleLanes lanes;
    TriangleFlowBatch flow;
    double x[3 * 3 * kTriangleLanes], v[3 * 3 * kTriangleLanes];  // lane l, node i: 4 (2 - i) + l
    std::array<MembraneTriangleRecord, kTriangleLanes> recs;
    std::array<std::array<Vec3, 3>, kTriangleLanes> xs, vs;
    for (int l = 0; l < kTriangleLanes; ++l) {
      const std::array<Vec3, 3> X = {Vec3(0, 0, 0), Vec3(1 + jitter(rng), jitter(rng), 0),
                                     Vec3(jitter(rng), 1 + jitter(rng), 0)};
      const auto ref = triangleReference(X, kFabric.thickness);
      const auto* s = stretch[(batch + 2 * l) % 3];
      xs[l] = deformed<3>(X, s[0], s[1], s[2], rng, 2e-2);
      if ((batch + l) % 97 == 0) xs[l][2] = xs[l][1];  // a lane without area
      for (int i = 0; i < 3; ++i) vs[l][i] = randomVector(rng, 20.0);
      recs[l] = membraneTriangleRecord(ref, kFabric, (batch + l) % 3 != 0);
      flow.inFlow[l] = (batch + l) % 5 == 4 ? 0 : -1;  // some lanes not the canopy's
      const std::array<int, 3> nodes = {8 + l, 4 + l, l};
      setLane(lanes, l, recs[l], nodes);
      for (int i = 0; i < 3; ++i)
        for (int r = 0; r < 3; ++r) {
          x[3 * nodes[i] + r] = xs[l][i][r];
          v[3 * nodes[i] + r] = vs[l][i][r];
        }
    }
    TriangleFlowAccumulators start;
    for (int l = 0; l < kTriangleLanes; ++l)
      start.volume[l] = any(rng), start.area[l] = any(rng), start.cloth[l] = any(rng),
      start.dCloth[l] = any(rng);
    // One at a time.
    TriangleFlowAccumulators oneAcc = start;
    double oneRecords[4 * kTriangleLanes];
    double one[kTriangleLanes][3][3], oneLoad[kTriangleLanes][3];
    for (int l = 0; l < kTriangleLanes; ++l) {
      double force[9];
      TriangleFlowSums o;
      membraneTriangleForce(xs[l][0].data(), xs[l][1].data(), xs[l][2].data(), recs[l], force);
      triangleFlowLoad(xs[l][0].data(), xs[l][1].data(), xs[l][2].data(), vs[l][0].data(),
                       vs[l][1].data(), vs[l][2].data(), q, oneLoad[l], o);
      for (int i = 0; i < 3; ++i)
        for (int c = 0; c < 3; ++c)
          one[l][i][c] = flow.inFlow[l] ? force[3 * i + c] + oneLoad[l][c] : force[3 * i + c];
      for (int c = 0; c < 3; ++c) oneRecords[4 * l + c] = o.nodeArea[c];
      oneRecords[4 * l + 3] = o.share;
      if (!flow.inFlow[l]) continue;
      oneAcc.volume[l] += o.volume, oneAcc.area[l] += o.area;
      oneAcc.cloth[l] += o.cloth, oneAcc.dCloth[l] += o.dCloth;
    }
    for (const auto& [name, copy] : copies) {
      TriangleLaneVectors f;
      double load[3][kTriangleLanes];
      TriangleFlowAccumulators acc = start;
      double got[4 * kTriangleLanes];
      copy(x, v, lanes, flow, q, f, load, acc, got);
      auto same = [&](double a, double b, const char* what, int l) {
        ASSERT_EQ(std::bit_cast<std::uint64_t>(a), std::bit_cast<std::uint64_t>(b))
            << name << " lane " << l << " " << what;
        ++compared;
      };
      for (int l = 0; l < kTriangleLanes; ++l) {
        for (int c = 0; c < 3; ++c) same(load[c][l], oneLoad[l][c], "load", l);
        for (int i = 0; i < 3; ++i)
          for (int c = 0; c < 3; ++c) same(f.v[i][c][l], one[l][i][c], "force", l);
        same(acc.volume[l], oneAcc.volume[l], "volume", l);
        same(acc.area[l], oneAcc.area[l], "area", l);
        same(acc.cloth[l], oneAcc.cloth[l], "cloth", l);
        same(acc.dCloth[l], oneAcc.dCloth[l], "cloth derivative", l);
      }
      for (int k = 0; k < 4 * kTriangleLanes; ++k) same(got[k], oneRecords[k], "record", k / 4);
    }
  }
  std::printf("%d entries compared bit for bit (%zu copies%s)\n", compared, copies.size(),
              avx2Available() ? ", AVX2 among them" : ", no AVX2 here");
}

TEST(TriangleFlowLoads, EachNodesRecordsGatheredInOrderAreTheSumsOneAtATimeBitForBit) {
  // FL13's per-node shares after the pass: random records, each node with 0 to 9 of them in a
  // random order (some shared between nodes), summed record after record, the share scaled.
  std::mt19937 rng(61);
  std::uniform_real_distribution<double> any(-10.0, 10.0);
  std::uniform_int_distribution<int> many(0, 9);
  using Copy =
      void (*)(const double*, const int*, const int*, size_t, size_t, double, double*, size_t);
  std::vector<std::pair<const char*, Copy>> copies = {{"baseline", &gatherTriangleRecordsBaseline},
                                                      {"dispatched", &gatherTriangleRecords}};
  if (avx2Available()) copies.emplace_back("avx2", &gatherTriangleRecordsAvx2);
  constexpr int kRecords = 40, kNodes = 300, kStride = 8;
  int compared = 0;
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<double> records(4 * kRecords);
    for (double& r : records) r = any(rng);
    std::vector<int> start = {0}, at;
    for (int i = 0; i < kNodes; ++i) {
      const int n = many(rng);
      for (int k = 0; k < n; ++k)
        at.push_back(4 * std::uniform_int_distribution<int>(0, kRecords - 1)(rng));
      start.push_back(static_cast<int>(at.size()));
    }
    const double perArea = 1.0 / (1.0 + std::abs(any(rng)));
    const size_t begin = trial % 7, end = kNodes - trial % 5;
    std::vector<double> want(kStride * kNodes, -1.0);
    for (size_t i = begin; i < end; ++i) {
      double sum[4] = {0.0, 0.0, 0.0, 0.0};
      for (int k = start[i]; k < start[i + 1]; ++k)
        for (int c = 0; c < 4; ++c) sum[c] += records[at[k] + c];
      for (int c = 0; c < 3; ++c) want[kStride * i + c] = sum[c];
      want[kStride * i + 3] = sum[3] * perArea;
    }
    for (const auto& [name, copy] : copies) {
      std::vector<double> got(kStride * kNodes, -1.0);
      copy(records.data(), start.data(), at.data(), begin, end, perArea, got.data(), kStride);
      for (size_t k = 0; k < got.size(); ++k) {
        ASSERT_EQ(std::bit_cast<std::uint64_t>(got[k]), std::bit_cast<std::uint64_t>(want[k]))
            << name << " entry " << k;
        ++compared;
      }
    }
  }
  std::printf("%d entries compared bit for bit (%zu copies%s)\n", compared, copies.size(),
              avx2Available() ? ", AVX2 among them" : ", no AVX2 here");
}
