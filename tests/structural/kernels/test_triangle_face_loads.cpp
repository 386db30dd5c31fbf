// The explicit step's face loads of a triangle in the membranes' pass (docs/formulation.md P2):
// one residual per node that is the follower pressure's (P1) and the face drag's (FD1) summed,
// to round-off of the two kernels that define them; and four at a time inside the membranes'
// own four-lane kernel, each lane membraneTriangleForce's forces plus triangleFaceLoad's load,
// bit for bit, on the baseline copy and on the AVX2 copy where the processor has it.
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

#include "kernels/FaceDrag.hpp"
#include "kernels/MembraneKernel.hpp"
#include "kernels/MembraneTriangleBatch.hpp"
#include "kernels/PressureKernel.hpp"
#include "kernels/TriangleFaceLoads.hpp"
#include "support/MembraneGeometry.hpp"

using namespace chute::kernels;
using chute::testing::deformed;
using chute::testing::randomVector;

namespace {

const MembraneMaterial kFabric{4.32e6, 0.3, 5e-4, 1.6};

TriangleFaceLoadParameters randomLoads(std::mt19937& rng, int kind) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  TriangleFaceLoadParameters q;
  // kind 0: pressure and drag, 1: pressure alone, 2: drag alone.
  if (kind != 2) q.pressure = 50.0 + 400.0 * u(rng);
  if (kind != 1) {
    q.drag = 0.5 * 1.2 * (0.5 + u(rng));
    const Vec3 w = randomVector(rng, 30.0);
    for (int c = 0; c < 3; ++c) q.wind[c] = w[c];
    q.steady = u(rng) < 0.5 ? 1.0 : 0.0;
  }
  return q;
}

}  // namespace

// P2 is P1's and FD1's node residuals summed: -trianglePressureForce + faceDragNodeResidual, to
// the round-off of their different orders of operations; a degenerate face carries nothing.
TEST(TriangleFaceLoads, AreThePressureAndTheFaceDragSummed) {
  std::mt19937 rng(11);
  double worst = 0.0;
  int compared = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::array<Vec3, 3> x = {randomVector(rng, 2.0), randomVector(rng, 2.0),
                             randomVector(rng, 2.0)};
    if (trial % 100 == 0) x[2] = x[1];  // no area
    const std::array<Vec3, 3> v = {randomVector(rng, 20.0), randomVector(rng, 20.0),
                                   randomVector(rng, 20.0)};
    const TriangleFaceLoadParameters q = randomLoads(rng, trial % 3);
    double r[3];
    triangleFaceLoad(x[0].data(), x[1].data(), x[2].data(), v[0].data(), v[1].data(), v[2].data(),
                     q, r);
    const Vec3 wind(q.wind[0], q.wind[1], q.wind[2]);
    const Vec3 pressure = -trianglePressureForce(x, q.pressure);
    const Vec3 drag = faceDragNodeResidual<3>(x, v, wind, q.drag, q.steady == 1.0);
    const Vec3 expect = pressure + drag;
    const double scale = pressure.norm() + drag.norm();
    if (scale == 0.0) {
      EXPECT_EQ(Vec3(r[0], r[1], r[2]), Vec3::Zero()) << "trial " << trial;
      continue;
    }
    const double err = (Vec3(r[0], r[1], r[2]) - expect).norm() / scale;
    worst = std::max(worst, err);
    EXPECT_LE(err, 1e-14) << "trial " << trial;
    ++compared;
  }
  std::printf(
      "P2 against P1 + FD1 over %d faces: largest difference %.3g of the loads' size (bound "
      "1e-14)\n",
      compared, worst);
}

TEST(TriangleFaceLoads, FourAtATimeInTheMembranesPassAreTheTrianglesOneAtATimeBitForBit) {
  std::mt19937 rng(47);
  std::uniform_real_distribution<double> jitter(-0.4, 0.4);
  const double stretch[][3] = {{1.04, 1.02, 0.01}, {1.05, 0.97, 0.005}, {0.95, 0.97, 0.0}};
  using Copy =
      void (*)(const double*, const double*, const MembraneTriangleLanes&,
               const TriangleFaceLoadLanes&, TriangleLaneVectors&, double(&)[3][kTriangleLanes]);
  std::vector<std::pair<const char*, Copy>> copies = {
      {"baseline", &membraneTriangleForcesAndLoadsBaseline},
      {"dispatched", &membraneTriangleForcesAndLoads}};
  if (avx2Available()) copies.emplace_back("avx2", &membraneTriangleForcesAndLoadsAvx2);
  int compared = 0;
  for (int batch = 0; batch < 1500; ++batch) {
    MembraneTriangleLanes lanes;
    TriangleFaceLoadLanes loads;
    double x[3 * 3 * kTriangleLanes], v[3 * 3 * kTriangleLanes];  // lane l, node i: 4 (2 - i) + l
    std::array<MembraneTriangleRecord, kTriangleLanes> recs;
    std::array<std::array<Vec3, 3>, kTriangleLanes> xs, vs;
    std::array<TriangleFaceLoadParameters, kTriangleLanes> qs;
    for (int l = 0; l < kTriangleLanes; ++l) {
      const std::array<Vec3, 3> X = {Vec3(0, 0, 0), Vec3(1 + jitter(rng), jitter(rng), 0),
                                     Vec3(jitter(rng), 1 + jitter(rng), 0)};
      const auto ref = triangleReference(X, kFabric.thickness);
      const auto* s = stretch[(batch + 2 * l) % 3];
      xs[l] = deformed<3>(X, s[0], s[1], s[2], rng, 2e-2);
      if ((batch + l) % 97 == 0) xs[l][2] = xs[l][1];  // a lane without area
      for (int i = 0; i < 3; ++i) vs[l][i] = randomVector(rng, 20.0);
      recs[l] = membraneTriangleRecord(ref, kFabric, (batch + l) % 3 != 0);
      qs[l] = randomLoads(rng, (batch + l) % 4 == 3 ? 0 : (batch + l) % 3);
      const std::array<int, 3> nodes = {8 + l, 4 + l, l};
      setLane(lanes, l, recs[l], nodes);
      loads.pressure[l] = qs[l].pressure, loads.drag[l] = qs[l].drag;
      for (int c = 0; c < 3; ++c) loads.wind[c][l] = qs[l].wind[c];
      loads.steady[l] = qs[l].steady;
      for (int i = 0; i < 3; ++i)
        for (int r = 0; r < 3; ++r) {
          x[3 * nodes[i] + r] = xs[l][i][r];
          v[3 * nodes[i] + r] = vs[l][i][r];
        }
    }
    for (const auto& [name, copy] : copies) {
      TriangleLaneVectors f;
      double load[3][kTriangleLanes];
      copy(x, v, lanes, loads, f, load);
      for (int l = 0; l < kTriangleLanes; ++l) {
        double force[9], r[3];
        membraneTriangleForce(xs[l][0].data(), xs[l][1].data(), xs[l][2].data(), recs[l], force);
        triangleFaceLoad(xs[l][0].data(), xs[l][1].data(), xs[l][2].data(), vs[l][0].data(),
                         vs[l][1].data(), vs[l][2].data(), qs[l], r);
        for (int c = 0; c < 3; ++c) {
          ASSERT_EQ(std::bit_cast<std::uint64_t>(load[c][l] + 0.0),
                    std::bit_cast<std::uint64_t>(r[c] + 0.0))
              << name << " lane " << l << " coordinate " << c;
          ++compared;
        }
        for (int i = 0; i < 3; ++i)
          for (int c = 0; c < 3; ++c) {
            ASSERT_EQ(std::bit_cast<std::uint64_t>(f.v[i][c][l] + 0.0),
                      std::bit_cast<std::uint64_t>(force[3 * i + c] + r[c] + 0.0))
                << name << " lane " << l << " node " << i << " coordinate " << c;
            ++compared;
          }
      }
    }
  }
  std::printf("%d entries compared bit for bit (%zu copies%s)\n", compared, copies.size(),
              avx2Available() ? ", AVX2 among them" : ", no AVX2 here");
}
