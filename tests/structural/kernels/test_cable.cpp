// Finite-difference and invariant checks of the two-node cable kernel (F1-F5) at many random
// configurations, and the location of its slack / taut switch (RG4).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <bit>
#include <cstdint>
#include <cstring>
#include <random>
#include <utility>
#include <vector>

#include "kernels/CableBatch.hpp"
#include "kernels/CableKernel.hpp"
#include "kernels/LineDragKernel.hpp"
#include "support/FiniteDifference.hpp"
#include "support/LineGeometry.hpp"

using namespace chute;
using namespace chute::kernels;
using chute::testing::fdGradient;
using chute::testing::fdJacobian;
using chute::testing::randomUnit;
using chute::testing::relativeError;
using chute::testing::rope;

TEST(CableKernel, TangentMatchesFiniteDifferenceOfForceAndForceOfEnergy) {
  std::mt19937 rng(1);
  double worstK = 0, worstF = 0;
  for (bool tensionOnly : {true, false})
    for (double strain : {0.03, 1e-4, -0.02}) {
      if (tensionOnly && strain < 0) continue;
      for (int trial = 0; trial < 50; ++trial) {
        const double L = 0.5 + trial * 0.05;
        const Vec3 xa(0.3, -0.2, 1.1);
        const Vec3 xb = xa + L * std::sqrt(1 + 2 * strain) * randomUnit(rng);
        Eigen::VectorXd x(6);
        x << xa, xb;
        const auto mat = rope(tensionOnly);
        const auto r = cableForce(xa, xb, L, mat, true);
        auto force = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
          return cableForce(y.head<3>(), y.tail<3>(), L, mat, false).force;
        };
        auto energy = [&](const Eigen::VectorXd& y) {
          return cableForce(y.head<3>(), y.tail<3>(), L, mat, false).energy;
        };
        const double h = 1e-6 * L;
        worstK = std::max(worstK, relativeError(r.stiffness, fdJacobian(force, x, h)));
        worstF = std::max(worstF, relativeError(r.force, fdGradient(energy, x, h)));
      }
    }
  std::printf("cable: worst relative error  K vs FD(f) %.2e   f vs FD(W) %.2e\n", worstK, worstF);
  EXPECT_LE(worstK, 1e-6);
  EXPECT_LE(worstF, 1e-6);
}

TEST(CableKernel, SlackCableCarriesNothingTrussCarriesCompression) {
  const Vec3 xa(0, 0, 0), xb(0.9, 0, 0);
  const auto slack = cableForce(xa, xb, 1.0, rope(true), true);
  EXPECT_EQ(slack.force.norm(), 0.0);
  EXPECT_EQ(slack.stiffness.norm(), 0.0);
  EXPECT_EQ(slack.energy, 0.0);
  const auto truss = cableForce(xa, xb, 1.0, rope(false), true);
  EXPECT_LT(truss.axialForce, 0.0);
  // f = dW/dx; the element pushes its nodes apart, so the force on node a, -f_a, points away
  // from b (along -x) and the one on b along +x.
  EXPECT_LT(-truss.force[0], 0.0);
  EXPECT_GT(-truss.force[3], 0.0);
}

TEST(CableKernel, RigidMotionInvariants) {
  std::mt19937 rng(7);
  const Vec3 xa(1, 2, 3), xb = xa + 1.05 * randomUnit(rng);
  const auto r = cableForce(xa, xb, 1.0, rope(), true);
  // Translation is in the null space; an infinitesimal rotation W x maps to W f.
  Eigen::VectorXd t(6), x(6), Wx(6), Wf(6);
  t << 1, -2, 0.5, 1, -2, 0.5;
  EXPECT_LE((r.stiffness * t).norm(), 1e-9 * r.stiffness.norm());
  const Vec3 w(0.3, -0.4, 0.8);
  x << xa, xb;
  Wx << w.cross(xa), w.cross(xb);
  Wf << w.cross(Vec3(r.force.head<3>())), w.cross(Vec3(r.force.tail<3>()));
  EXPECT_LE((r.stiffness * Wx - Wf).norm(), 1e-9 * r.stiffness.norm());
  EXPECT_LE((r.force.head<3>() + r.force.tail<3>()).norm(), 1e-12 * r.force.norm());
}

TEST(CableKernel, LumpedMassIsRowSumOfConsistentMass) {
  const auto mat = rope();
  const Mat6 Mc = cableMass(2.0, mat, MassKind::Consistent);
  const Mat6 Ml = cableMass(2.0, mat, MassKind::Lumped);
  EXPECT_LE((Mc.rowwise().sum() - Ml.diagonal()).norm(), 1e-14);
  EXPECT_NEAR(Ml.trace() / 3, mat.density * mat.area * 2.0, 1e-14);
}

TEST(SlackTautCrossing, FindsWhereTheLengthPassesTheReferenceLength) {
  // Random motions across |d| = L both ways: the fraction returned lands on |d + f delta| = L;
  // motions that stay on one side, or start or end within the band, give 1.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double L = 0.25;
  double worst = 0.0;
  int crossings = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 d = Vec3(u(rng), u(rng), u(rng)) * 0.3, delta = Vec3(u(rng), u(rng), u(rng)) * 0.2;
    const double f = slackTautCrossing(d, delta, L);
    const double l0 = d.norm(), l1 = (d + delta).norm();
    const bool crosses = (l0 < L) != (l1 < L) && std::abs(l0 - L) > kSlackTautBand * L &&
                         std::abs(l1 - L) > kSlackTautBand * L;
    if (!crosses) {
      EXPECT_EQ(f, 1.0);
      continue;
    }
    ++crossings;
    ASSERT_GT(f, 0.0);
    ASSERT_LT(f, 1.0);
    worst = std::max(worst, std::abs((d + f * delta).norm() - L) / L);
  }
  std::printf("slack/taut crossing: %d crossings, |l(f) - L| / L <= %.2e\n", crossings, worst);
  EXPECT_GT(crossings, 100);
  EXPECT_LE(worst, 1e-12);
  // Within the band at the start: on the switch, not across it.
  EXPECT_EQ(slackTautCrossing(Vec3(L * (1 + 0.5 * kSlackTautBand), 0, 0), Vec3(-0.1, 0, 0), L),
            1.0);
}

// Residual-only evaluations (explicit steps) skip the Hessians and the stiffness: everything else
// is bit for bit the evaluation with the tangent, taut, slack (cable) and compressed (truss), and
// with the ends inside the apex radius. cableMassTimes is cableMass * a, bit for bit.
TEST(CableKernel, ResidualOnlyIsTheFullEvaluationBitForBit) {
  std::mt19937 rng(17);
  std::normal_distribution<double> n(0, 1);
  for (int trial = 0; trial < 300; ++trial) {
    const double L = 0.5 + std::abs(n(rng));
    Vec3 xa(n(rng), n(rng), n(rng));
    const double stretch = trial % 3 == 0 ? 0.9 : (trial % 3 == 1 ? 1.05 : 1e-12);  // apex too
    Vec3 xb = xa + stretch * L * randomUnit(rng);
    if (trial == 1) xb = xa;                               // no length
    if (trial == 2) xa.setZero(), xb = Vec3(L, 0.0, 0.0);  // exactly zero strain: slack
    for (bool tension : {true, false}) {
      const auto mat = rope(tension);
      const auto full = cableForce(xa, xb, L, mat, true);
      const auto res = cableForce(xa, xb, L, mat, false);
      EXPECT_EQ(res.length, full.length);
      EXPECT_EQ(res.strain, full.strain);
      EXPECT_EQ(res.axialForce, full.axialForce);
      EXPECT_EQ(res.energy, full.energy);
      EXPECT_EQ(res.dLength, full.dLength);
      EXPECT_EQ(res.force, full.force) << trial;
      // cableForceOnly, the explicit path's: the same bits, signs of zeros included.
      const Vec6 only = cableForceOnly(xa, xb, L, mat);
      EXPECT_EQ(std::memcmp(only.data(), full.force.data(), sizeof(double) * 6), 0) << trial;
      // cableStrainEnergyOnly, the energy balance's: the same bits.
      const double energy = cableStrainEnergyOnly(xa, xb, L, mat);
      EXPECT_EQ(std::memcmp(&energy, &full.energy, sizeof(double)), 0) << trial;
    }
    Vec6 a;
    for (int k = 0; k < 6; ++k) a[k] = n(rng);
    if (trial == 0) a.setOnes();  // the explicit path's M 1
    for (auto kind : {MassKind::Lumped, MassKind::Consistent}) {
      const Vec6 product = cableMass(L, rope(), kind) * a;
      EXPECT_EQ(cableMassTimes(L, rope(), kind, a), product) << trial;
    }
  }
}

// CB1: the explicit step's cables four at a time give, lane by lane, cableForceOnly's force less
// the load factor times the weight (F5) plus lineDragNodeResidual's drag (LD1), bit for bit
// (signs of zeros aside: a sum with a zero drag), in every state the scalar path has: taut,
// slack, exactly zero strain, a compressed truss and a cable with compression stiffness, inside
// the apex, no length, no drag, a cut cable (drag only), an empty lane; with and without drag
// and weight; on every copy this processor runs.
TEST(CableBatch, LanesAreTheScalarKernelsBitForBit) {
  std::mt19937 rng(29);
  std::normal_distribution<double> n(0, 1);
  using Copy = void (*)(const double*, const double*, const CableLanes&, double, double,
                        const std::int64_t(&)[kCableLanes], CableLaneVectors&);
  std::vector<std::pair<const char*, Copy>> copies = {{"baseline", &cableForcesAndDragBaseline},
                                                      {"dispatched", &cableForcesAndDrag}};
  if (avx2Available()) copies.emplace_back("avx2", &cableForcesAndDragAvx2);
  auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v + 0.0); };
  const Vec3 g(0.0, 0.0, -9.81);
  int compared = 0, withDrag = 0, cut = 0;
  for (int batch = 0; batch < 400; ++batch) {
    // Eight nodes: lane l's cable from node 2l to node 2l + 1.
    Eigen::VectorXd x(24), v(24);
    for (int k = 0; k < 24; ++k) x[k] = n(rng), v[k] = n(rng);
    CableLanes lanes;
    std::int64_t elastic[kCableLanes];
    std::vector<LineMaterial> mats(kCableLanes);
    std::vector<double> Ls(kCableLanes), coefs(kCableLanes);
    std::vector<Vec3> weights(kCableLanes), winds(kCableLanes);
    std::vector<bool> empty(kCableLanes, false);
    for (int l = 0; l < kCableLanes; ++l) {
      const int kind = (batch * kCableLanes + l) % 11;
      const double L = 0.5 + std::abs(n(rng));
      const Vec3 xa = x.segment<3>(6 * l);
      const double stretch = kind == 0   ? 0.9
                             : kind == 1 ? 1.05
                             : kind == 2 ? 1e-12
                                         : 1.0 + 0.1 * n(rng);
      Vec3 xb = xa + stretch * L * randomUnit(rng);
      if (kind == 3) xb = xa;  // no length
      if (kind == 4) {         // exactly zero strain
        x.segment<3>(6 * l).setZero();
        xb = Vec3(L, 0.0, 0.0);
      }
      x.segment<3>(6 * l + 3) = xb;
      LineMaterial mat = rope(kind != 5);  // a truss
      if (kind == 6) mat.compressionStiffnessRatio = 0.5;
      if (kind == 7) mat.density = 0.0;
      mats[l] = mat, Ls[l] = L;
      weights[l] =
          mat.density > 0.0 && kind != 8 ? Vec3(cableGravity(L, mat, g).head<3>()) : Vec3::Zero();
      coefs[l] = kind == 9 ? 0.0 : 0.01 * std::abs(n(rng));
      winds[l] = Vec3(n(rng), n(rng), n(rng));
      empty[l] = kind == 10 && l == kCableLanes - 1;
      if (empty[l])
        clearCableLane(lanes, l);
      else
        setCableLane(lanes, l, 2 * l, 2 * l + 1, L, mat, weights[l], coefs[l], winds[l]);
      elastic[l] = batch % 5 == 4 && l == 1 ? 0 : -1;
    }
    for (double loadFactor : {1.0, 0.7})
      for (double dragFactor : {loadFactor, 0.0})
        for (const auto& [name, copy] : copies) {
          CableLaneVectors f;
          copy(x.data(), v.data(), lanes, loadFactor, dragFactor, elastic, f);
          for (int l = 0; l < kCableLanes; ++l) {
            if (empty[l]) {
              for (int k = 0; k < 3; ++k) {
                EXPECT_EQ(f.v[0][k][l] + 0.0, 0.0);
                EXPECT_EQ(f.v[1][k][l] + 0.0, 0.0);
              }
              continue;
            }
            const Vec3 xa = x.segment<3>(6 * l), xb = x.segment<3>(6 * l + 3);
            Vec6 expect = Vec6::Zero();
            if (elastic[l] != 0) {
              expect = cableForceOnly(xa, xb, Ls[l], mats[l]);
              Vec6 w;
              w << weights[l], weights[l];
              expect -= loadFactor * w;
            } else {
              ++cut;
            }
            const Vec3 drag =
                lineDragNodeResidual(xa, xb, v.segment<3>(6 * l), v.segment<3>(6 * l + 3), winds[l],
                                     coefs[l] * dragFactor);
            withDrag += drag.squaredNorm() > 0.0;
            for (int k = 0; k < 3; ++k) {
              ASSERT_EQ(bits(f.v[0][k][l]), bits(expect[k] + drag[k]))
                  << name << " batch " << batch << " lane " << l << " xyz " << k;
              ASSERT_EQ(bits(f.v[1][k][l]), bits(expect[3 + k] + drag[k]))
                  << name << " batch " << batch << " lane " << l;
              ASSERT_EQ(bits(f.drag[k][l]), bits(drag[k])) << name;
              compared += 3;
            }
          }
        }
  }
  std::printf("%d entries compared bit for bit (%zu copies%s): %d with drag, %d of cut cables\n",
              compared, copies.size(), avx2Available() ? ", AVX2 among them" : "", withDrag, cut);
}
