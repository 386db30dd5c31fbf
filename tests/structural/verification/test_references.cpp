// The analytic / independently integrated references themselves: the bead ODE reference is
// checked for step convergence and for staying on its ellipse with conserved energy.
#include <gtest/gtest.h>

#include "verification/References.hpp"

using namespace chute::verification;

TEST(BeadEllipseReference, ConvergedToTenDigitsAndConservesEnergy) {
  const Vec3 f1(0, 0, 0), f2(2, 0, 0), bead0(0.5, 0, -0.5), g(0, 0, -10);
  BeadEllipseReference ref(f1, f2, bead0, g);
  std::vector<double> times;
  for (int k = 0; k <= 200; ++k) times.push_back(0.1 * k);
  const auto fine = ref.positions(times, 1e-5);
  const auto coarse = ref.positions(times, 2e-5);
  double diff = 0, offEllipse = 0, energyDrift = 0;
  const double twoA = 2 * ref.semiMajor();
  for (size_t k = 0; k < times.size(); ++k) {
    diff = std::max(diff, (fine[k] - coarse[k]).norm());
    offEllipse =
        std::max(offEllipse, std::abs((fine[k] - f1).norm() + (fine[k] - f2).norm() - twoA));
  }
  // Energy: the bead is at rest at the ends of its swing, where it returns to its start height.
  // The turning points are where z is highest; the bead never rises above its release height.
  for (const auto& p : fine) energyDrift = std::max(energyDrift, p.z() - bead0.z());
  std::printf(
      "bead reference: RK4 h vs 2h difference %.2e ft over 20 s, off-ellipse %.2e ft, "
      "rise above release %.2e ft\n",
      diff, offEllipse, energyDrift);
  // RK4 error scales with h^4: the h = 1e-5 result is 16x closer than this difference.
  EXPECT_LE(diff, 1.6e-9);
  EXPECT_LE(offEllipse, 1e-12);
  EXPECT_LE(energyDrift, 1e-10);
}

TEST(PulleyReference, StartsAtRestAndSatisfiesItsOde) {
  PulleyReference ref{100.0, 40.0, 10.0, Vec3::Zero(), Vec3(0, 0, -1)};
  EXPECT_DOUBLE_EQ(ref.hangingLength(0), 40.0);
  // l1'' = (2 g / L)(l1 - L/2), checked by central differences.
  for (double t : {0.5, 1.7, 3.9}) {
    const double h = 1e-4;
    const double acc =
        (ref.hangingLength(t + h) - 2 * ref.hangingLength(t) + ref.hangingLength(t - h)) / (h * h);
    EXPECT_NEAR(acc, 0.2 * (ref.hangingLength(t) - 50.0), 1e-5);
  }
}
