// Membrane, pressure and drag kernels: tangents against central differences of forces, forces
// against differences of the energy, in the taut, wrinkled and slack states; patch tests.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "kernels/LineDragKernel.hpp"
#include "kernels/MembraneKernel.hpp"
#include "kernels/PressureKernel.hpp"
#include "support/FiniteDifference.hpp"

using namespace chute::kernels;
using chute::testing::fdGradient;
using chute::testing::fdJacobian;
using chute::testing::relativeError;

namespace {

const MembraneMaterial kFabric{4.32e6, 0.3, 5e-4, 1.6};

Mat3 randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> n(0, 1);
  return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
}

template <int N>
std::array<Vec3, N> referenceNodes() {
  if constexpr (N == 3)
    return {Vec3(0.1, 0.2, 0.0), Vec3(1.3, 0.1, 0.1), Vec3(0.4, 0.9, -0.05)};
  else
    return {Vec3(0.0, 0.0, 0.0), Vec3(1.1, 0.05, 0.0), Vec3(1.2, 0.9, 0.02), Vec3(-0.1, 1.0, 0.0)};
}

// Current nodes: a homogeneous stretch (lx, ly, shear) of the reference, rotated and with a
// small non-homogeneous perturbation (so that quads see varying strain).
template <int N>
std::array<Vec3, N> deformed(const std::array<Vec3, N>& X, double lx, double ly, double shear,
                             std::mt19937& rng, double noise) {
  Mat3 U;
  U << lx, shear, 0, 0, ly, 0, 0, 0, 1;
  const Mat3 Q = randomRotation(rng);
  std::uniform_real_distribution<double> u(-noise, noise);
  std::array<Vec3, N> x;
  for (int i = 0; i < N; ++i) x[i] = Q * (U * X[i]) + Vec3(u(rng), u(rng), u(rng)) + Vec3(2, -1, 3);
  return x;
}

template <int N>
Eigen::VectorXd stack(const std::array<Vec3, N>& x) {
  Eigen::VectorXd v(3 * N);
  for (int i = 0; i < N; ++i) v.segment<3>(3 * i) = x[i];
  return v;
}
template <int N>
std::array<Vec3, N> unstack(const Eigen::VectorXd& v) {
  std::array<Vec3, N> x;
  for (int i = 0; i < N; ++i) x[i] = v.segment<3>(3 * i);
  return x;
}

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

TEST(MembraneKernel, PlaneStressTangentMatchesItsStressAcrossStates) {
  // The relaxed energy is C1: stress continuous across the state boundaries; tangent = dS/de.
  double worst = 0;
  for (const Vec3& e :
       {Vec3(0.02, 0.01, 0.004), Vec3(0.03, -0.02, 0.01), Vec3(0.01, -0.004, 0.002)}) {
    const auto ps = planeStressSVK(e, 1e6, 0.3, true);
    auto stress = [](const Eigen::VectorXd& y) -> Eigen::VectorXd {
      return planeStressSVK(Vec3(y), 1e6, 0.3, true).stress;
    };
    worst =
        std::max(worst, relativeError(ps.tangent, fdJacobian(stress, Eigen::VectorXd(e), 1e-9)));
  }
  EXPECT_LE(worst, 1e-6);
  // Continuity of the stress at the taut/wrinkled boundary E2 = -nu E1.
  const double nu = 0.3, e1 = 0.02;
  const auto below = planeStressSVK(Vec3(e1, -nu * e1 - 1e-12, 0), 1e6, nu, true);
  const auto above = planeStressSVK(Vec3(e1, -nu * e1 + 1e-12, 0), 1e6, nu, true);
  EXPECT_EQ(below.state, WrinkleState::Wrinkled);
  EXPECT_EQ(above.state, WrinkleState::Taut);
  EXPECT_LE((below.stress - above.stress).norm(), 1e-5 * above.stress.norm());
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

TEST(PressureKernel, LoadStiffnessMatchesFiniteDifferencesAndTotalsPressureTimesArea) {
  std::mt19937 rng(9);
  const double p = 3.7;
  double worst = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const auto x3 = deformed<3>(referenceNodes<3>(), 1.1, 0.9, 0.2, rng, 0.05);
    const auto x4 = deformed<4>(referenceNodes<4>(), 1.1, 0.9, 0.2, rng, 0.05);
    const auto l3 = pressureLoad<3>(x3, p, true);
    const auto l4 = pressureLoad<4>(x4, p, true);
    auto f3 = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
      return pressureLoad<3>(unstack<3>(y), p, false).force;
    };
    auto f4 = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
      return pressureLoad<4>(unstack<4>(y), p, false).force;
    };
    worst = std::max(worst, relativeError(l3.dForce, fdJacobian(f3, stack<3>(x3), 1e-6)));
    worst = std::max(worst, relativeError(l4.dForce, fdJacobian(f4, stack<4>(x4), 1e-6)));
    // Total force = p times the vector area.
    const Vec3 area3 = 0.5 * (x3[1] - x3[0]).cross(x3[2] - x3[0]);
    Vec3 total = Vec3::Zero();
    for (int i = 0; i < 3; ++i) total += l3.force.segment<3>(3 * i);
    EXPECT_LE((total - p * area3).norm(), 1e-12 * p * area3.norm());
  }
  std::printf("pressure load stiffness: worst relative error vs FD %.2e\n", worst);
  EXPECT_LE(worst, 1e-6);
}

TEST(DragKernel, PositionAndVelocityTangentsMatchFiniteDifferences) {
  std::mt19937 rng(2);
  std::normal_distribution<double> n(0, 1);
  const double c = 0.5 * 0.0023769 * 1.2 * 0.03;
  double worstX = 0, worstV = 0;
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::VectorXd x(6), v(6);
    for (int k = 0; k < 6; ++k) x[k] = n(rng), v[k] = 20 * n(rng);
    const Vec3 wind(3, -2, 1);
    auto at = [&](const Eigen::VectorXd& xx, const Eigen::VectorXd& vv, bool t) {
      return lineDrag(xx.head<3>(), xx.tail<3>(), vv.head<3>(), vv.tail<3>(), wind, c, t);
    };
    const auto d = at(x, v, true);
    auto fx = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd { return at(y, v, false).residual; };
    auto fv = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd { return at(x, y, false).residual; };
    worstX = std::max(worstX, relativeError(d.dPosition, fdJacobian(fx, x, 1e-6)));
    worstV = std::max(worstV, relativeError(d.dVelocity, fdJacobian(fv, v, 1e-5)));
    // Drag opposes the normal relative motion.
    const Vec3 e = (x.tail<3>() - x.head<3>()).normalized();
    Vec3 vr = 0.5 * (v.head<3>() + v.tail<3>()) - wind;
    vr -= vr.dot(e) * e;
    EXPECT_GT(d.residual.head<3>().dot(vr), 0.0);
  }
  std::printf("line drag: worst relative error dr/dx %.2e, dr/dv %.2e\n", worstX, worstV);
  EXPECT_LE(worstX, 1e-6);
  EXPECT_LE(worstV, 1e-6);
}
