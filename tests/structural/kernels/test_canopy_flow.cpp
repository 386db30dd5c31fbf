// Kernels of the airflow's loads on a canopy (docs/flight.md FL3-FL8): the face load's position
// and velocity tangents against central differences, its force against an independent
// evaluation and its invariants; the cloth law, the orifice law and the outside pressure
// coefficient against their definitions; the standard atmosphere against NOAA-S/T 76-1562's
// table.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "kernels/CanopyFlow.hpp"
#include "model/StandardAtmosphere.hpp"
#include "support/FiniteDifference.hpp"

using namespace chute::kernels;
using chute::testing::fdJacobian;
using chute::testing::flat;
using chute::testing::relativeError;
using chute::testing::unflat;
using Vec3 = Eigen::Vector3d;

namespace {

CanopyFlowState someFlow(const Vec3& direction) {
  CanopyFlowState s;
  s.canopyVelocity = Vec3(0.3, -0.2, -6.0);
  s.flowDirection = direction.normalized();
  s.dynamicPressure = 22.0;
  s.insideGauge = 21.0;
  s.baseCoefficient = -0.8;
  s.normalDrag = 0.5 * 1.225 * 1.17;
  return s;
}

template <int N>
std::array<Vec3, N> someFace() {
  if constexpr (N == 3)
    return {Vec3(0.0, 0.0, 0.0), Vec3(0.9, 0.1, 0.2), Vec3(0.2, 0.8, 0.35)};
  else
    return {Vec3(0.0, 0.0, 0.0), Vec3(0.9, 0.1, 0.2), Vec3(1.0, 0.9, 0.5), Vec3(0.1, 0.8, 0.35)};
}

// Tangents against central differences of the residual, for faces turned into the flow, in the
// lee, and at every regime of the outside coefficient (clear of its kinks).
template <int N>
void checkTangents(const Vec3& direction, double& worstX, double& worstV) {
  const auto x = someFace<N>();
  std::array<Vec3, N> v;
  for (int i = 0; i < N; ++i) v[i] = Vec3(0.4 * i, -0.3, -5.0 + 0.7 * i);
  const CanopyFlowState s = someFlow(direction);
  const auto f = canopyFaceLoad<N>(x, v, s, true);
  const Eigen::MatrixXd fdX = fdJacobian(
      [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
        return canopyFaceLoad<N>(unflat<N>(y), v, s, false).residual;
      },
      flat<N>(x), 1e-6);
  const Eigen::MatrixXd fdV = fdJacobian(
      [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
        return canopyFaceLoad<N>(x, unflat<N>(y), s, false).residual;
      },
      flat<N>(v), 1e-6);
  worstX = std::max(worstX, relativeError(Eigen::MatrixXd(f.dPosition), fdX));
  worstV = std::max(worstV, relativeError(Eigen::MatrixXd(f.dVelocity), fdV));
}

}  // namespace

TEST(CanopyFlowKernel, FaceLoadTangentsMatchFiniteDifferences) {
  double worstX = 0.0, worstV = 0.0;
  // The face's normal is about (-0.2, -0.3, 1): flow from below (lee of the outside), from above
  // (into the flow), and nearly along the face (within the attached band).
  for (const Vec3& d : {Vec3(0, 0, 1), Vec3(0.1, 0.2, -1), Vec3(1, 0.3, 0.45), Vec3(0.2, 1, 0.2)}) {
    checkTangents<3>(d, worstX, worstV);
    checkTangents<4>(d, worstX, worstV);
  }
  std::printf(
      "canopy face load, triangles and quads, 4 flow directions: worst relative tangent "
      "error %.2e (positions), %.2e (velocities)\n",
      worstX, worstV);
  EXPECT_LT(worstX, 1e-6);
  EXPECT_LT(worstV, 1e-6);
}

TEST(CanopyFlowKernel, FaceLoadIsTheNetPressureOnTheAreaShared) {
  // FL8 evaluated independently: the area vector from other edges, the outside coefficient from
  // its definition, the normal velocity relative to the canopy.
  const auto x = someFace<3>();
  std::array<Vec3, 3> v{Vec3(1, 0, -5), Vec3(0.5, 0.2, -5.5), Vec3(0, 0, -4)};
  const Vec3 d = Vec3(0.1, 0.2, 1).normalized();
  const CanopyFlowState s = someFlow(d);
  const auto f = canopyFaceLoad<3>(x, v, s, false);
  const Vec3 A = 0.5 * (x[2] - x[1]).cross(x[0] - x[1]);
  const Vec3 n = A.normalized();
  const double c = n.dot(d);
  const double base = s.baseCoefficient * std::min(1.0, std::abs(c) / kAttachedFlowBand);
  const double cout = c >= 0 ? base : base + (1.0 - s.baseCoefficient) * c * c;
  const double un = ((v[0] + v[1] + v[2]) / 3.0 - s.canopyVelocity).dot(n);
  const double net = s.insideGauge - s.dynamicPressure * cout - s.normalDrag * un * std::abs(un);
  double worst = 0.0;
  for (int i = 0; i < 3; ++i)
    worst = std::max(worst, (f.residual.segment<3>(3 * i) + net * A / 3.0).norm());
  std::printf("face load against the independent net pressure %.6g on area %.6g: %.2e\n", net,
              A.norm(), worst);
  EXPECT_LT(worst, 1e-12 * std::abs(net) * A.norm());
  EXPECT_NEAR(f.netPressure, net, 1e-12 * std::abs(net));
  // Rigid translation of the face with the canopy adds no normal drag; the loads of the nodes
  // add up to the net pressure on the area, which pushes along the normal.
  std::array<Vec3, 3> same{s.canopyVelocity, s.canopyVelocity, s.canopyVelocity};
  const auto g = canopyFaceLoad<3>(x, same, s, false);
  EXPECT_NEAR(g.netPressure, g.staticDifference, 1e-15);
  Vec3 total = Vec3::Zero();
  for (int i = 0; i < 3; ++i) total -= g.residual.segment<3>(3 * i);
  EXPECT_LT((total - g.netPressure * A).norm(), 1e-12 * g.netPressure * A.norm());
}

TEST(CanopyFlowKernel, OutsideCoefficientIsContinuousAndItsSlopeMatches) {
  // FL7: 0 along the flow, the base pressure over the wake, stagnation head on; the slope against
  // central differences away from its kinks (0 and the band's edges).
  const double cb = -0.75;
  EXPECT_EQ(outsidePressureCoefficient(0.0, cb), 0.0);
  EXPECT_DOUBLE_EQ(outsidePressureCoefficient(1.0, cb), cb);
  EXPECT_DOUBLE_EQ(outsidePressureCoefficient(-1.0, cb), 1.0);
  double worstJump = 0.0, worstSlope = 0.0;
  for (double c = -0.999; c < 1.0; c += 0.0137) {
    const double h = 1e-7;
    worstJump = std::max(worstJump, std::abs(outsidePressureCoefficient(c + h, cb) -
                                             outsidePressureCoefficient(c - h, cb)));
    if (std::abs(c) < 2e-6 || std::abs(std::abs(c) - kAttachedFlowBand) < 2e-6) continue;
    const double fd =
        (outsidePressureCoefficient(c + h, cb) - outsidePressureCoefficient(c - h, cb)) / (2 * h);
    worstSlope = std::max(worstSlope, std::abs(fd - dOutsidePressureCoefficient(c, cb)));
  }
  std::printf("outside coefficient: largest change over 2e-7 %.2e, slope error %.2e\n", worstJump,
              worstSlope);
  EXPECT_LT(worstJump, 1e-5);
  EXPECT_LT(worstSlope, 1e-6);
}

TEST(CanopyFlowKernel, ClothLawPassesThroughItsTestPointAndInverts) {
  // FL6: u(dp_ref) = u_ref, dp = a u + b u^2 recovered, odd in dp, du/ddp against differences.
  for (double b : {0.0, 30.0}) {
    const auto c = ClothPermeability::fromTest(0.508, 124.5, b);
    EXPECT_NEAR(c.velocity(124.5), 0.508, 1e-12);
    double worst = 0.0, worstSlope = 0.0;
    for (double dp : {-900.0, -124.5, -3.0, 0.5, 60.0, 1500.0}) {
      const double u = c.velocity(dp);
      worst = std::max(worst, std::abs(c.viscous * u + c.inertial * u * std::abs(u) - dp));
      EXPECT_DOUBLE_EQ(c.velocity(-dp), -u);
      const double fd = (c.velocity(dp + 1e-4) - c.velocity(dp - 1e-4)) / 2e-4;
      worstSlope = std::max(worstSlope, std::abs(fd - c.dVelocity(dp)) / c.dVelocity(dp));
    }
    std::printf("cloth law b = %g: residual of dp = a u + b |u| u %.2e, slope error %.2e\n", b,
                worst, worstSlope);
    EXPECT_LT(worst, 1e-10);
    EXPECT_LT(worstSlope, 1e-6);
  }
  EXPECT_FALSE(ClothPermeability::fromTest(0.0, 124.5, 0.0).permeable());
  EXPECT_THROW(ClothPermeability::fromTest(0.5, 124.5, 1000.0), std::invalid_argument);
}

TEST(CanopyFlowKernel, OrificeIsBernoulliWithItsDischargeCoefficient) {
  // FL4: Q = Cd A sqrt(2 dp / rho) beyond the linear zone, odd, continuous at its edge.
  const double A = 2.0, cd = 0.61, rho = 1.225, lin = 0.01;
  for (double dp : {0.5, 10.0, 400.0})
    EXPECT_NEAR(orificeFlow(dp, A, cd, rho, lin), cd * A * std::sqrt(2 * dp / rho), 1e-12);
  EXPECT_DOUBLE_EQ(orificeFlow(-7.0, A, cd, rho, lin), -orificeFlow(7.0, A, cd, rho, lin));
  EXPECT_NEAR(orificeFlow(lin * (1 - 1e-12), A, cd, rho, lin), orificeFlow(lin, A, cd, rho, lin),
              1e-9);
  const double fd =
      (orificeFlow(5.0 + 1e-5, A, cd, rho, lin) - orificeFlow(5.0 - 1e-5, A, cd, rho, lin)) / 2e-5;
  EXPECT_NEAR(dOrificeFlow(5.0, A, cd, rho, lin), fd, 1e-6 * fd);
}

TEST(StandardAtmosphere, MatchesTheTablesOfNoaaSt76_1562) {
  // NOAA-S/T 76-1562, table I (geometric altitude): T, p, rho at 0, 1, 5 and 11 km.
  struct Row {
    double z, T, p, rho;
  };
  const Row rows[] = {{0.0, 288.150, 101325.0, 1.2250},
                      {1000.0, 281.651, 89876.0, 1.1117},
                      {5000.0, 255.676, 54048.0, 0.73643},
                      {11000.0, 216.774, 22700.0, 0.36480}};
  double worst = 0.0;
  for (const auto& r : rows) {
    const auto a = chute::standardAtmosphere(r.z);
    worst = std::max({worst, std::abs(a.temperature / r.T - 1), std::abs(a.pressure / r.p - 1),
                      std::abs(a.density / r.rho - 1)});
  }
  std::printf("standard atmosphere against the 1976 tables at 0, 1, 5, 11 km: worst %.2e\n", worst);
  EXPECT_LT(worst, 2e-4);
  EXPECT_THROW(chute::standardAtmosphere(12000.0), std::out_of_range);
}
