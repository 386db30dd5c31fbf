// Face-drag kernel (docs/formulation.md FD1): position and velocity tangents against central
// differences of the force, the force against an independent evaluation (area vector by 2x2
// Gauss quadrature of the bilinear map, normal from other edges), and its invariants.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "kernels/FaceDrag.hpp"
#include "support/FiniteDifference.hpp"

using namespace chute::kernels;
using chute::testing::fdJacobian;
using chute::testing::flat;
using chute::testing::relativeError;
using chute::testing::unflat;
using Vec3 = Eigen::Vector3d;

namespace {

constexpr double kHalfRhoCd = 0.5 * 0.0023769 * 1.2;

// Area vector by quadrature: int x_,xi x x_,eta over the parent element (triangle: constant;
// quad: bilinear map on [-1, 1]^2, the integrand is bilinear so 2x2 Gauss is exact).
template <int N>
Vec3 areaByQuadrature(const std::array<Vec3, N>& x) {
  if constexpr (N == 3) {
    return 0.5 * (x[2] - x[1]).cross(x[0] - x[1]);  // other edges than the kernel's
  } else {
    const double g = 1.0 / std::sqrt(3.0);
    const double xi[4][2] = {{-1, -1}, {1, -1}, {-1, 1}, {1, 1}};  // node corners
    Vec3 a = Vec3::Zero();
    for (double s : {-g, g})
      for (double t : {-g, g}) {
        Vec3 dxs = Vec3::Zero(), dxt = Vec3::Zero();
        const int order[4] = {0, 1, 3, 2};  // corners (-1,-1), (1,-1), (1,1), (-1,1) = nodes 0..3
        for (int k = 0; k < 4; ++k) {
          const double* c = xi[order[k]];
          dxs += 0.25 * c[0] * (1 + c[1] * t) * x[k];
          dxt += 0.25 * c[1] * (1 + c[0] * s) * x[k];
        }
        a += dxs.cross(dxt);  // weight 1 per point
      }
    return a;
  }
}

// Independent nodal forces -r: f_i = -(c / N) (|u| u - s |u0| u0) |a| n.
template <int N>
Eigen::VectorXd independentForce(const std::array<Vec3, N>& x, const std::array<Vec3, N>& v,
                                 const Vec3& wind, double c, bool s) {
  const Vec3 a = areaByQuadrature<N>(x);
  const Vec3 n = a.normalized();
  Vec3 vm = Vec3::Zero();
  for (const auto& vi : v) vm += vi / N;
  const double u = (vm - wind).dot(n), u0 = -wind.dot(n);
  const double p = -c * (std::abs(u) * u - (s ? std::abs(u0) * u0 : 0.0));
  Eigen::VectorXd f(3 * N);
  for (int i = 0; i < N; ++i) f.segment<3>(3 * i) = p * a.norm() * n / N;
  return f;
}

template <int N>
void checkKernel(const char* label) {
  std::mt19937 rng(N * 17 + 3);
  std::normal_distribution<double> nd(0, 1);
  double worstX = 0, worstV = 0, worstF = 0, worstFlip = 0;
  for (int s = 0; s < 2; ++s)
    for (int trial = 0; trial < 20; ++trial) {
      std::array<Vec3, N> x, v;
      const Vec3 base[4] = {Vec3(0, 0, 0), Vec3(1.1, 0.05, 0), Vec3(1.2, 0.9, 0.02),
                            Vec3(-0.1, 1.0, 0)};
      const Eigen::Matrix3d R =
          Eigen::Quaterniond(nd(rng), nd(rng), nd(rng), nd(rng)).normalized().toRotationMatrix();
      for (int i = 0; i < N; ++i) {
        x[i] = R * (N == 3 && i == 2 ? base[3] : base[i]) + 0.2 * Vec3(nd(rng), nd(rng), nd(rng));
        v[i] = 8.0 * Vec3(nd(rng), nd(rng), nd(rng));
      }
      const Vec3 wind = 9.0 * Vec3(nd(rng), nd(rng), nd(rng));
      const auto d = faceDrag<N>(x, v, wind, kHalfRhoCd, s == 1, true);
      auto fx = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
        return faceDrag<N>(unflat<N>(y), v, wind, kHalfRhoCd, s == 1, false).residual;
      };
      auto fv = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
        return faceDrag<N>(x, unflat<N>(y), wind, kHalfRhoCd, s == 1, false).residual;
      };
      worstX = std::max(worstX, relativeError(d.dPosition, fdJacobian(fx, flat<N>(x), 1e-6)));
      worstV = std::max(worstV, relativeError(d.dVelocity, fdJacobian(fv, flat<N>(v), 1e-5)));
      const Eigen::VectorXd f = independentForce<N>(x, v, wind, kHalfRhoCd, s == 1);
      worstF = std::max(worstF, relativeError(-d.residual, f));
      // Reversed node order (normal flipped): the same nodal forces.
      std::array<Vec3, N> xr, vr;
      for (int i = 0; i < N; ++i) xr[i] = x[N - 1 - i], vr[i] = v[N - 1 - i];
      const auto dr = faceDrag<N>(xr, vr, wind, kHalfRhoCd, s == 1, false);
      Eigen::VectorXd back(3 * N);
      for (int i = 0; i < N; ++i)
        back.segment<3>(3 * i) = dr.residual.template segment<3>(3 * (N - 1 - i));
      worstFlip = std::max(worstFlip, relativeError(back, d.residual));
    }
  std::printf(
      "%s face drag: worst relative error dr/dx %.2e, dr/dv %.2e, force vs independent "
      "%.2e, flipped normal %.2e\n",
      label, worstX, worstV, worstF, worstFlip);
  EXPECT_LE(worstX, 1e-6);
  EXPECT_LE(worstV, 1e-6);
  EXPECT_LE(worstF, 1e-12);
  EXPECT_LE(worstFlip, 1e-12);
}

}  // namespace

TEST(FaceDrag, TriangleTangentsAndForce) {
  checkKernel<3>("triangle");
}
TEST(FaceDrag, QuadTangentsAndForce) {
  checkKernel<4>("quad");
}

// A flat square plate moving along its normal at V: total drag (1/2) rho Cd A V^2 against the
// motion; no drag for motion in its plane; with the steady part subtracted, none at rest in a
// wind, and the linearised damping rho Cd |w.n| A for a small normal velocity.
TEST(FaceDrag, FlatPlateInvariants) {
  const std::array<Vec3, 4> x = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 2, 0), Vec3(0, 2, 0)};
  const double V = 7.0, A = 4.0;
  std::array<Vec3, 4> v;
  v.fill(Vec3(0, 0, -V));
  const auto d = faceDrag<4>(x, v, Vec3::Zero(), kHalfRhoCd, false, false);
  Vec3 total = Vec3::Zero();
  for (int i = 0; i < 4; ++i) total -= d.residual.segment<3>(3 * i);
  const double expected = kHalfRhoCd * A * V * V;
  std::printf("plate normal drag %.10g lbf, expected %.10g\n", total.z(), expected);
  EXPECT_NEAR(total.z(), expected, 1e-12 * expected);
  EXPECT_NEAR(total.head<2>().norm(), 0.0, 1e-15);
  v.fill(Vec3(3, -4, 0));
  EXPECT_EQ(faceDrag<4>(x, v, Vec3::Zero(), kHalfRhoCd, false, false).residual.norm(), 0.0);
  const Vec3 wind(0, 0, 9.173);
  v.fill(Vec3::Zero());
  EXPECT_EQ(faceDrag<4>(x, v, wind, kHalfRhoCd, true, false).residual.norm(), 0.0);
  v.fill(Vec3(0, 0, 1e-3));
  const auto small = faceDrag<4>(x, v, wind, kHalfRhoCd, true, true);
  double damping = 0;  // d(total residual z) / d(plate velocity z)
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) damping += small.dVelocity(3 * i + 2, 3 * j + 2);
  const double linear = 2.0 * kHalfRhoCd * 9.173 * A;
  std::printf("plate linearised damping in a wind %.6g, expected rho Cd |w| A %.6g\n", damping,
              linear);
  EXPECT_NEAR(damping, linear, 2e-4 * linear);
}

// The residual-only variant (explicit steps) is the kernel's residual, bit for bit, on every node:
// random faces, velocities and winds, plain and steady-subtracted, and the degenerate cases.
template <int N>
void checkNodeResidual() {
  std::mt19937 rng(N * 31 + 7);
  std::normal_distribution<double> nd(0, 1);
  int compared = 0;
  for (int s = 0; s < 2; ++s)
    for (int trial = 0; trial < 200; ++trial) {
      std::array<Vec3, N> x, v;
      for (int i = 0; i < N; ++i) {
        x[i] = Vec3(nd(rng), nd(rng), nd(rng));
        v[i] = 8.0 * Vec3(nd(rng), nd(rng), nd(rng));
      }
      if (trial == 0) x.fill(Vec3(0.3, -0.2, 1.0));  // no area
      const Vec3 wind = 9.0 * Vec3(nd(rng), nd(rng), nd(rng));
      const double c = trial == 1 ? 0.0 : kHalfRhoCd;
      const auto d = faceDrag<N>(x, v, wind, c, s == 1, false);
      const Vec3 r = faceDragNodeResidual<N>(x, v, wind, c, s == 1);
      for (int i = 0; i < N; ++i) {
        EXPECT_EQ(r, Vec3(d.residual.template segment<3>(3 * i))) << "trial " << trial;
        ++compared;
      }
    }
  EXPECT_EQ(compared, 2 * 200 * N);
}

TEST(FaceDrag, NodeResidualIsTheKernelsResidualBitForBit) {
  checkNodeResidual<3>();
  checkNodeResidual<4>();
}
