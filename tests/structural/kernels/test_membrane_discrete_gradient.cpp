// The energy-momentum force of the membranes (docs/formulation.md EM9-EM10): the discrete-
// gradient property W(x_{n+1}) - W(x_n) = f_alg . (x_{n+1} - x_n) to round-off for the taut
// St Venant-Kirchhoff law and across the tension-field states (taut / wrinkled / slack), the
// tangent d f_alg / d x_{n+1} against finite differences, the momentum invariants, and the
// limit x_{n+1} -> x_n (the ordinary force).
#include <gtest/gtest.h>

#include <random>

#include "kernels/MembraneDiscreteGradient.hpp"
#include "support/FiniteDifference.hpp"
#include "support/MembraneGeometry.hpp"

using namespace chute;
using namespace chute::kernels;
using chute::testing::deformed;
using chute::testing::fdJacobian;
using chute::testing::referenceNodes;
using chute::testing::relativeError;
using chute::testing::stack;
using chute::testing::unstack;

namespace {
MembraneMaterial fabric() {
  MembraneMaterial m;
  m.E = 4.3e7;
  m.nu = 0.3;
  m.thickness = 1e-4;
  m.density = 500;
  return m;
}
template <int N>
MembraneReference<N> reference() {
  if constexpr (N == 3)
    return triangleReference(referenceNodes<3>(), fabric().thickness);
  else
    return quadReference(referenceNodes<4>(), fabric().thickness);
}
// Stretches (lx, ly, shear) at the step's start and end: taut -> taut, taut -> wrinkled,
// wrinkled -> slack, slack -> taut, and a tiny step.
const std::vector<std::array<double, 6>> kSteps = {{1.02, 1.01, 0.01, 1.03, 1.015, 0.0},
                                                   {1.02, 1.01, 0.0, 1.03, 0.98, 0.02},
                                                   {1.02, 0.97, 0.01, 0.99, 0.98, 0.0},
                                                   {0.98, 0.99, 0.0, 1.01, 1.02, 0.01},
                                                   {1.02, 1.01, 0.01, 1.02, 1.01, 0.0101}};

template <int N>
void checkDiscreteGradient(bool wrinkling, double& worstDG, double& worstK) {
  std::mt19937 rng(17 + N);
  const auto ref = reference<N>();
  const auto mat = fabric();
  for (const auto& st : kSteps)
    for (int trial = 0; trial < 10; ++trial) {
      // Start and end share their rigid placement (generators seeded alike) and differ in
      // stretch and in the small non-homogeneous perturbation's draw.
      const unsigned seed = rng();
      std::mt19937 r0(seed), r1(seed);
      const auto x0 = deformed<N>(referenceNodes<N>(), st[0], st[1], st[2], r0, 0.01);
      const auto x1 = deformed<N>(referenceNodes<N>(), st[3], st[4], st[5], r1, 0.01);
      const auto r = membraneDiscreteGradient<N>(x0, x1, ref, mat, wrinkling, 0.0, true);
      const Eigen::VectorXd dx = stack<N>(x1) - stack<N>(x0);
      const double scale = std::max({std::abs(r.energy0), std::abs(r.energy1),
                                     r.force.cwiseAbs().dot(dx.cwiseAbs()), 1e-300});
      worstDG = std::max(worstDG, std::abs(r.energy1 - r.energy0 - r.force.dot(dx)) / scale);
      // Energies are the element's own.
      EXPECT_NEAR(r.energy1, membraneForce<N>(x1, ref, mat, wrinkling, false).energy,
                  1e-12 * std::max(r.energy1, 1e-20));
      auto force = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
        return membraneDiscreteGradient<N>(x0, unstack<N>(y), ref, mat, wrinkling, 0.0, false)
            .force;
      };
      worstK = std::max(worstK, relativeError(r.dForce, fdJacobian(force, stack<N>(x1), 1e-7)));
    }
}
}  // namespace

TEST(MembraneDiscreteGradient, EnergyDifferenceIsForceTimesMotionAndTangentIsConsistent) {
  for (bool wrinkling : {false, true}) {
    double dg3 = 0, k3 = 0, dg4 = 0, k4 = 0;
    checkDiscreteGradient<3>(wrinkling, dg3, k3);
    checkDiscreteGradient<4>(wrinkling, dg4, k4);
    std::printf(
        "membrane discrete gradient (%s): worst |dW - f.dx| / scale  tri %.2e quad %.2e; "
        "d f / d x_{n+1} vs FD  tri %.2e quad %.2e\n",
        wrinkling ? "wrinkling" : "SVK", dg3, dg4, k3, k4);
    EXPECT_LE(std::max(dg3, dg4), 1e-10);
    // Across a state change the relaxed energy is only C1: the tangent is piecewise and the
    // finite difference straddles no kink for these steps.
    EXPECT_LE(std::max(k3, k4), 1e-5);
  }
}

TEST(MembraneDiscreteGradient, ConservesMomentaAndTendsToTheForce) {
  std::mt19937 r0(3), r1(3);
  const auto ref = reference<4>();
  const auto x0 = deformed<4>(referenceNodes<4>(), 1.02, 1.0, 0.01, r0, 0.01);
  const auto x1 = deformed<4>(referenceNodes<4>(), 1.03, 0.97, 0.02, r1, 0.01);
  const auto r = membraneDiscreteGradient<4>(x0, x1, ref, fabric(), true, 0.3, false);
  Vec3 F = Vec3::Zero(), M = Vec3::Zero();
  for (int i = 0; i < 4; ++i) {
    const Vec3 f = r.force.segment<3>(3 * i);
    F += f;
    M += (0.5 * (x0[i] + x1[i])).cross(f);
  }
  const double fn = r.force.norm();
  EXPECT_LE(F.norm(), 1e-12 * fn);
  EXPECT_LE(M.norm(), 1e-11 * fn);
  const auto same = membraneDiscreteGradient<4>(x1, x1, ref, fabric(), true, 0.0, false);
  EXPECT_LE(relativeError(same.force, membraneForce<4>(x1, ref, fabric(), true, false).force),
            1e-12);
}

TEST(MembraneDiscreteGradient, DissipationNeverAddsEnergy) {
  const auto ref = reference<3>();
  for (const auto& st : kSteps) {
    std::mt19937 r0(5), r1(5);
    const auto x0 = deformed<3>(referenceNodes<3>(), st[0], st[1], st[2], r0, 0.01);
    const auto x1 = deformed<3>(referenceNodes<3>(), st[3], st[4], st[5], r1, 0.01);
    const auto r = membraneDiscreteGradient<3>(x0, x1, ref, fabric(), true, 0.5, false);
    const double work = r.force.dot(stack<3>(x1) - stack<3>(x0));
    EXPECT_GE(work - (r.energy1 - r.energy0), -1e-12 * std::abs(work));
  }
}
