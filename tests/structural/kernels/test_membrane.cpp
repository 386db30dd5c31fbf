// Membrane kernel: tangents against central differences of forces, forces against differences of
// the energy, in the taut, wrinkled and slack states; patch tests; mass.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <utility>
#include <vector>

#include "kernels/MembraneKernel.hpp"
#include "kernels/MembraneTriangleBatch.hpp"
#include "kernels/MembraneTriangleForce.hpp"
#include "support/FiniteDifference.hpp"
#include "support/MembraneGeometry.hpp"

using namespace chute::kernels;
using chute::testing::deformed;
using chute::testing::fdGradient;
using chute::testing::fdJacobian;
using chute::testing::referenceNodes;
using chute::testing::relativeError;
using chute::testing::stack;
using chute::testing::unstack;

namespace {

const MembraneMaterial kFabric{4.32e6, 0.3, 5e-4, 1.6};

template <int N>
MembraneReference<N> reference(const std::array<Vec3, N>& X) {
  if constexpr (N == 3)
    return triangleReference(X, kFabric.thickness);
  else
    return quadReference(X, kFabric.thickness);
}

struct StateCase {
  const char* name;
  double lx, ly, shear;
  WrinkleState expected;
};

template <int N>
void checkMembraneFD(const StateCase& c) {
  std::mt19937 rng(11);
  const auto X = referenceNodes<N>();
  const auto ref = reference<N>(X);
  double worstK = 0, worstF = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const auto x = deformed<N>(X, c.lx, c.ly, c.shear, rng, 1e-3);
    const auto r = membraneForce<N>(x, ref, kFabric, true, true);
    ASSERT_EQ(r.state, c.expected) << c.name;
    auto force = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
      return membraneForce<N>(unstack<N>(y), ref, kFabric, true, false).force;
    };
    auto energy = [&](const Eigen::VectorXd& y) {
      return membraneForce<N>(unstack<N>(y), ref, kFabric, true, false).energy;
    };
    const double h = 1e-7;
    if (c.expected == WrinkleState::Slack) {
      EXPECT_EQ(r.force.norm(), 0.0);
      EXPECT_EQ(r.stiffness.norm(), 0.0);
      continue;
    }
    worstK = std::max(worstK, relativeError(r.stiffness, fdJacobian(force, stack<N>(x), h)));
    worstF = std::max(worstF, relativeError(r.force, fdGradient(energy, stack<N>(x), h)));
  }
  std::printf("%s %s: worst relative error K vs FD(f) %.2e, f vs FD(W) %.2e\n",
              N == 3 ? "triangle" : "quad", c.name, worstK, worstF);
  EXPECT_LE(worstK, 1e-6);
  EXPECT_LE(worstF, 1e-6);
}

const StateCase kStates[] = {
    {"taut", 1.04, 1.02, 0.01, WrinkleState::Taut},
    {"wrinkled", 1.05, 0.97, 0.005, WrinkleState::Wrinkled},
    {"slack", 0.95, 0.97, 0.0, WrinkleState::Slack},
};

}  // namespace

TEST(MembraneKernel, TriangleTangentAndForceMatchFiniteDifferencesInEveryState) {
  for (const auto& c : kStates) checkMembraneFD<3>(c);
}

TEST(MembraneKernel, QuadTangentAndForceMatchFiniteDifferencesInEveryState) {
  for (const auto& c : kStates) checkMembraneFD<4>(c);
}

TEST(MembranePatch, UniformStretchGivesTheExactUniformStress) {
  const double lx = 1.03, ly = 1.01, nu = kFabric.nu, E = kFabric.E;
  const double e11 = 0.5 * (lx * lx - 1), e22 = 0.5 * (ly * ly - 1), c = E / (1 - nu * nu);
  const Eigen::Vector2d expected(c * (e11 + nu * e22), c * (e22 + nu * e11));
  std::mt19937 rng(5);
  const auto Xq = referenceNodes<4>();
  // A rectangle so that the stretch is along its sides.
  const std::array<Vec3, 4> X = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0.7, 0), Vec3(0, 0.7, 0)};
  (void)Xq;
  const auto ref = quadReference(X, kFabric.thickness);
  std::array<Vec3, 4> x = deformed<4>(X, lx, ly, 0.0, rng, 0.0);
  const auto r = membraneForce<4>(x, ref, kFabric, true, false);
  EXPECT_LE((r.principalStress - expected).norm(), 1e-9 * expected.norm());
  const std::array<Vec3, 3> Xt = {X[0], X[1], X[2]};
  const auto rt = membraneForce<3>({x[0], x[1], x[2]}, triangleReference(Xt, kFabric.thickness),
                                   kFabric, true, false);
  EXPECT_LE((rt.principalStress - expected).norm(), 1e-9 * expected.norm());
}

// The true stress resultant at a large stretch, where it differs from S t0 by lx / ly: a
// rectangle stretched by lx along x and ly along y (then rotated in space) carries
// n1 = t0 lx S11 / ly and n2 = t0 ly S22 / lx (force per current width). Uniaxial stress:
// ly = sqrt(1 - nu (lx^2 - 1)) makes S22 = 0, so n2 = 0 and n1 = t0 E e11 lx / ly.
TEST(MembranePatch, StressResultantIsTheTrueForcePerCurrentWidth) {
  const double nu = kFabric.nu, E = kFabric.E, t0 = kFabric.thickness;
  const double c = E / (1 - nu * nu);
  const std::array<Vec3, 4> X = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0.7, 0), Vec3(0, 0.7, 0)};
  const auto ref = quadReference(X, t0);
  const auto reft = triangleReference({X[0], X[1], X[2]}, t0);
  const double lxU = 1.2, lyU = std::sqrt(1.0 - nu * (lxU * lxU - 1.0));
  for (const auto& [lx, ly] : {std::pair{lxU, lyU}, std::pair{1.2, 1.1}}) {
    const double e11 = 0.5 * (lx * lx - 1), e22 = 0.5 * (ly * ly - 1);
    const double S11 = c * (e11 + nu * e22), S22 = c * (e22 + nu * e11);
    Eigen::Vector2d expected(t0 * lx * S11 / ly, t0 * ly * S22 / lx);
    if (expected[1] > expected[0]) std::swap(expected[0], expected[1]);
    std::mt19937 rng(7);
    const auto x = deformed<4>(X, lx, ly, 0.0, rng, 0.0);
    const auto r = membraneForce<4>(x, ref, kFabric, false, false);
    const auto rt = membraneForce<3>({x[0], x[1], x[2]}, reft, kFabric, false, false);
    const double errQ = (r.principalResultant - expected).norm() / expected.norm();
    const double errT = (rt.principalResultant - expected).norm() / expected.norm();
    std::printf(
        "stretch %.4f x %.4f: n = (%.9g, %.9g) N/m analytic (%.9g, %.9g); relative error "
        "quad %.2e, triangle %.2e; S t0 would be off by %.1f %%\n",
        lx, ly, r.principalResultant[0], r.principalResultant[1], expected[0], expected[1], errQ,
        errT, 100.0 * std::abs(t0 * r.principalStress[0] / expected[0] - 1.0));
    EXPECT_LE(errQ, 1e-12);
    EXPECT_LE(errT, 1e-12);
  }
}

TEST(MembranePatch, RigidRotationByNinetyDegreesGivesZeroStress) {
  const std::array<Vec3, 4> X = {Vec3(0, 0, 0), Vec3(1.1, 0.05, 0), Vec3(1.2, 0.9, 0),
                                 Vec3(-0.1, 1.0, 0)};
  const auto ref = quadReference(X, kFabric.thickness);
  const Mat3 Q = Eigen::AngleAxisd(M_PI / 2, Vec3(1, 2, -0.5).normalized()).toRotationMatrix();
  std::array<Vec3, 4> x;
  for (int i = 0; i < 4; ++i) x[i] = Q * X[i] + Vec3(3, 1, 2);
  for (bool wrinkling : {false, true}) {
    const auto r = membraneForce<4>(x, ref, kFabric, wrinkling, false);
    EXPECT_LE(r.principalStress.norm(), 1e-9 * kFabric.E);
    EXPECT_LE(r.force.norm(), 1e-9 * kFabric.E * kFabric.thickness);
  }
}

TEST(MembranePatch, UniaxialCompressionIsStressFreeWithWrinkling) {
  const std::array<Vec3, 3> X = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  const auto ref = triangleReference(X, kFabric.thickness);
  std::mt19937 rng(3);
  const auto x = deformed<3>(X, 0.9, 1.0, 0.0, rng, 0.0);
  const auto on = membraneForce<3>(x, ref, kFabric, true, false);
  const auto off = membraneForce<3>(x, ref, kFabric, false, false);
  // E1 = 0 exactly in exact arithmetic: slack, or wrinkled with E1 at round-off.
  EXPECT_NE(on.state, WrinkleState::Taut);
  EXPECT_LE(on.force.norm(), 1e-10 * off.force.norm());
  EXPECT_GT(off.force.norm(), 0.0);  // without wrinkling the fabric would push back
  // Compressed in both directions: slack, exactly zero.
  const auto both =
      membraneForce<3>(deformed<3>(X, 0.9, 0.99, 0.0, rng, 0.0), ref, kFabric, true, false);
  EXPECT_EQ(both.state, WrinkleState::Slack);
  EXPECT_EQ(both.force.norm(), 0.0);
}

TEST(MembraneKernel, LumpedMassIsRowSumOfConsistentAndTotalsTheElementMass) {
  const auto X3 = referenceNodes<3>();
  const auto r3 = triangleReference(X3, kFabric.thickness);
  const auto X4 = referenceNodes<4>();
  const auto r4 = quadReference(X4, kFabric.thickness);
  const double m3 = kFabric.density * kFabric.thickness * r3.area;
  const double m4 = kFabric.density * kFabric.thickness * r4.area;
  EXPECT_NEAR(membraneMass<3>(r3, kFabric.density, false).sum(), m3, 1e-14 * m3);
  EXPECT_NEAR(membraneMass<4>(r4, kFabric.density, false).sum(), m4, 1e-14 * m4);
  EXPECT_LE((membraneMass<4>(r4, kFabric.density, false).rowwise().sum() -
             membraneMass<4>(r4, kFabric.density, true).diagonal())
                .norm(),
            1e-15);
}

// membraneEnergy (the energy balance's and the probes' strain energy) is membraneForce's energy
// bit for bit, with and without the tangent, in every state, for triangles and quads.
template <int N>
void checkEnergyOnly() {
  std::mt19937 rng(29 + N);
  const auto X = referenceNodes<N>();
  const auto ref = reference<N>(X);
  for (const auto& c : kStates)
    for (int trial = 0; trial < 50; ++trial) {
      const auto x = deformed<N>(X, c.lx, c.ly, c.shear, rng, 1e-3);
      for (bool wrinkling : {true, false}) {
        const double W = membraneEnergy<N>(x, ref, kFabric, wrinkling);
        const auto res = membraneForce<N>(x, ref, kFabric, wrinkling, false, false);
        const auto full = membraneForce<N>(x, ref, kFabric, wrinkling, true, true);
        if (wrinkling) {
          EXPECT_EQ(full.state, c.expected) << c.name;
        }
        EXPECT_EQ(W, res.energy) << c.name;
        EXPECT_EQ(W, full.energy) << c.name;
        EXPECT_EQ(res.state, full.state) << c.name;
      }
    }
}

TEST(MembraneKernel, EnergyOnlyIsTheKernelsEnergyBitForBitInEveryState) {
  checkEnergyOnly<3>();
  checkEnergyOnly<4>();
}

// The kernel's strains are written out entry by entry (a stall-free form): its residual-only force
// and energy are bit for bit those of the matrix expressions F = sum_i x_i dN_i^T, C = F^T F,
// f = w F S dN^T, in every state, for triangles and quads.
template <int N>
void checkAgainstMatrixExpressions() {
  std::mt19937 rng(41 + N);
  const auto X = referenceNodes<N>();
  const auto ref = reference<N>(X);
  for (const auto& c : kStates)
    for (int trial = 0; trial < 50; ++trial) {
      const auto x = deformed<N>(X, c.lx, c.ly, c.shear, rng, 1e-3);
      for (bool wrinkling : {true, false}) {
        Eigen::Matrix<double, 3 * N, 1> force = Eigen::Matrix<double, 3 * N, 1>::Zero();
        double energy = 0.0;
        for (int k = 0; k < MembraneReference<N>::kGauss; ++k) {
          const auto& dN = ref.dN[k];
          Eigen::Matrix<double, 3, 2> F = Eigen::Matrix<double, 3, 2>::Zero();
          for (int i = 0; i < N; ++i) F += x[i] * dN.row(i);
          const Eigen::Matrix2d C = F.transpose() * F;
          const Vec3 e(0.5 * (C(0, 0) - 1.0), 0.5 * (C(1, 1) - 1.0), C(0, 1));
          const PlaneStress ps = planeStressSVK(e, kFabric.E, kFabric.nu, wrinkling);
          energy += ref.weight[k] * ps.energy;
          Eigen::Matrix2d S2;
          S2 << ps.stress[0], ps.stress[2], ps.stress[2], ps.stress[1];
          const Eigen::Matrix<double, 3, N> f = ref.weight[k] * (F * S2) * dN.transpose();
          for (int i = 0; i < N; ++i) force.template segment<3>(3 * i) += f.col(i);
        }
        const auto r = membraneForce<N>(x, ref, kFabric, wrinkling, false, false);
        EXPECT_EQ(r.force, force) << c.name;
        EXPECT_EQ(r.energy, energy) << c.name;
      }
    }
}

TEST(MembraneKernel, ResidualIsBitForBitThatOfTheMatrixExpressions) {
  checkAgainstMatrixExpressions<3>();
  checkAgainstMatrixExpressions<4>();
}

// The explicit step's triangle (MembraneTriangleForce.hpp) gives membraneForce<3>'s residual and
// state and membraneEnergy<3>'s energy bit for bit, in every state, with and without wrinkling, on
// skewed and stretched triangles of random shape and orientation.
TEST(MembraneKernel, ExplicitTriangleForceIsMembraneForceBitForBit) {
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> jitter(-0.4, 0.4);
  int counts[3] = {0, 0, 0}, compared = 0;
  for (int shape = 0; shape < 40; ++shape) {
    const std::array<Vec3, 3> X = {Vec3(0, 0, 0), Vec3(1 + jitter(rng), jitter(rng), 0),
                                   Vec3(jitter(rng), 1 + jitter(rng), 0)};
    const auto ref = triangleReference(X, kFabric.thickness);
    for (const auto& c : kStates)
      for (int trial = 0; trial < 25; ++trial) {
        const auto x = deformed<3>(X, c.lx, c.ly, c.shear, rng, 2e-2);
        for (bool wrinkling : {true, false}) {
          const auto res = membraneForce<3>(x, ref, kFabric, wrinkling, false, false);
          const MembraneTriangleRecord rec = membraneTriangleRecord(ref, kFabric, wrinkling);
          double f[9];
          const WrinkleState s =
              membraneTriangleForce(x[0].data(), x[1].data(), x[2].data(), rec, f);
          ASSERT_EQ(s, res.state);
          ++counts[static_cast<int>(s)];
          const double W = membraneTriangleEnergy(x[0].data(), x[1].data(), x[2].data(), rec);
          ASSERT_EQ(
              std::bit_cast<std::uint64_t>(W + 0.0),
              std::bit_cast<std::uint64_t>(membraneEnergy<3>(x, ref, kFabric, wrinkling) + 0.0))
              << W;
          for (int i = 0; i < 9; ++i) {
            ASSERT_EQ(std::bit_cast<std::uint64_t>(f[i] + 0.0),
                      std::bit_cast<std::uint64_t>(res.force[i] + 0.0))
                << "entry " << i << ": " << f[i] << " against " << res.force[i];
            ++compared;
          }
        }
      }
  }
  std::printf("%d entries compared bit for bit: %d taut, %d wrinkled, %d slack evaluations\n",
              compared, counts[0], counts[1], counts[2]);
  EXPECT_GT(counts[1], 100);
  EXPECT_GT(counts[2], 100);
}

// The explicit step's triangles four at a time (MembraneTriangleBatch.hpp): each lane gives
// membraneTriangleForce's forces and state, and membraneTriangleEnergy's energy, bit for bit, lanes
// of different shapes, states and wrinkling settings side by side, on the baseline copy and on the
// AVX2 copy where the processor has it.
TEST(MembraneKernel, FourTrianglesAtATimeAreTheExplicitTriangleBitForBit) {
  std::mt19937 rng(43);
  std::uniform_real_distribution<double> jitter(-0.4, 0.4);
  std::uniform_int_distribution<int> pickState(0, static_cast<int>(std::size(kStates)) - 1);
  using Copy =
      void (*)(const double*, const MembraneTriangleLanes&, TriangleLaneVectors&, WrinkleState*);
  std::vector<std::pair<const char*, Copy>> copies = {{"baseline", &membraneTriangleForcesBaseline},
                                                      {"dispatched", &membraneTriangleForces}};
  if (avx2Available()) copies.emplace_back("avx2", &membraneTriangleForcesAvx2);
  // And each lane's strain energy, membraneTriangleEnergy's bits (the energy balance).
  using EnergyCopy =
      void (*)(const double*, const MembraneTriangleLanes&, double(&)[kTriangleLanes]);
  std::vector<std::pair<const char*, EnergyCopy>> energyCopies = {
      {"baseline", &membraneTriangleEnergiesBaseline}, {"dispatched", &membraneTriangleEnergies}};
  if (avx2Available()) energyCopies.emplace_back("avx2", &membraneTriangleEnergiesAvx2);
  int counts[3] = {0, 0, 0}, compared = 0, energies = 0;
  for (int batch = 0; batch < 2000; ++batch) {
    MembraneTriangleLanes lanes;
    double x[3 * 3 * kTriangleLanes];  // lane l's node i is node 4 (2 - i) + l
    std::array<MembraneTriangleRecord, kTriangleLanes> recs;
    std::array<std::array<Vec3, 3>, kTriangleLanes> xs;
    for (int l = 0; l < kTriangleLanes; ++l) {
      const std::array<Vec3, 3> X = {Vec3(0, 0, 0), Vec3(1 + jitter(rng), jitter(rng), 0),
                                     Vec3(jitter(rng), 1 + jitter(rng), 0)};
      const auto ref = triangleReference(X, kFabric.thickness);
      const auto& c = kStates[pickState(rng)];
      xs[l] = deformed<3>(X, c.lx, c.ly, c.shear, rng, 2e-2);
      recs[l] = membraneTriangleRecord(ref, kFabric, (batch + l) % 3 != 0);
      const std::array<int, 3> nodes = {8 + l, 4 + l, l};
      setLane(lanes, l, recs[l], nodes);
      for (int i = 0; i < 3; ++i)
        for (int r = 0; r < 3; ++r) x[3 * nodes[i] + r] = xs[l][i][r];
    }
    for (const auto& [name, copy] : copies) {
      TriangleLaneVectors f;
      WrinkleState states[kTriangleLanes];
      copy(x, lanes, f, states);
      for (int l = 0; l < kTriangleLanes; ++l) {
        double expect[9];
        const WrinkleState s = membraneTriangleForce(xs[l][0].data(), xs[l][1].data(),
                                                     xs[l][2].data(), recs[l], expect);
        ASSERT_EQ(states[l], s) << name << " lane " << l;
        ++counts[static_cast<int>(s)];
        for (int i = 0; i < 3; ++i)
          for (int r = 0; r < 3; ++r) {
            ASSERT_EQ(std::bit_cast<std::uint64_t>(f.v[i][r][l] + 0.0),
                      std::bit_cast<std::uint64_t>(expect[3 * i + r] + 0.0))
                << name << " lane " << l << " node " << i << " coordinate " << r;
            ++compared;
          }
      }
    }
    for (const auto& [name, copy] : energyCopies) {
      double W[kTriangleLanes];
      copy(x, lanes, W);
      for (int l = 0; l < kTriangleLanes; ++l) {
        const double expect =
            membraneTriangleEnergy(xs[l][0].data(), xs[l][1].data(), xs[l][2].data(), recs[l]);
        ASSERT_EQ(std::bit_cast<std::uint64_t>(W[l] + 0.0),
                  std::bit_cast<std::uint64_t>(expect + 0.0))
            << name << " lane " << l << ": " << W[l] << " against " << expect;
        ++energies;
      }
    }
  }
  std::printf(
      "%d entries compared bit for bit (%zu copies%s): %d taut, %d wrinkled, %d slack; "
      "%d energies\n",
      compared, copies.size(), avx2Available() ? ", AVX2 among them" : ", no AVX2 here", counts[0],
      counts[1], counts[2], energies);
  EXPECT_GT(counts[1], 1000);
  EXPECT_GT(counts[2], 1000);
}
