// Static solve of a ring on a stiff rope (E A / W = 1e6) from starts far from equilibrium
// (docs/formulation.md ST1): the ring starts up to one rope length from its equilibrium, in
// several directions (on, inside and outside the ellipse of inextensible positions; the rope's
// reference length is the same for every start). The equilibrium is symmetric: the ring at the
// middle, depth h with 2 N h / s = W, s = sqrt(a^2 + h^2), N = E A eps l / L, eps = (l^2 - L^2) /
// (2 L^2), l = 2 s (F6, F8), solved here by bisection.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "app/RunCase.hpp"
#include "case/CaseSpec.hpp"

using namespace chute;

namespace {

constexpr double kSpan = 2.0, kEA = 1.0e7, kWeight = 10.0;
const double kL = std::sqrt(0.5) + std::sqrt(2.5);  // the rope of cases/bead_1.toml

double exactDepth() {
  const double a = 0.5 * kSpan;
  auto excess = [&](double h) {  // net upward force on the ring minus its weight
    const double s = std::hypot(a, h), l = 2.0 * s;
    const double eps = (l * l - kL * kL) / (2.0 * kL * kL);
    return 2.0 * kEA * eps * l / kL * h / s - kWeight;
  };
  double lo = std::sqrt(0.25 * kL * kL - a * a) - 1e-3, hi = lo + 2e-3;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (excess(mid) > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

std::string writeCase(double x, double z) {
  const double current = std::hypot(x, z) + std::hypot(kSpan - x, z);
  const std::string path = ::testing::TempDir() + "static_far_start.toml";
  std::ofstream f(path);
  f.precision(17);
  f << "name = \"static_far_start\"\n"
    << "[nodes]\nleft = [0.0, 0.0, 0.0]\nright = [" << kSpan << ", 0.0, 0.0]\n"
    << "ring = [" << x << ", 0.0, " << z << "]\n"
    << "[materials.rope]\nkind = \"cable\"\nE = " << kEA << "\narea = 1.0\ndensity = 0.0\n"
    << "[[sliding_groups]]\nname = \"rope\"\nmaterial = \"rope\"\n"
    << "path = [\"left\", \"ring\", \"right\"]\nsliders = [\"ring\"]\nelements = 1\n"
    << "prestrain = " << current / kL - 1.0 << "\n"  // reference length kL at every start
    << "[[point_masses]]\nnode = \"ring\"\nmass = 1.0\n"
    << "[boundary]\nfixed = [\"left\", \"right\"]\n"
    << "[loads]\ngravity = [0.0, 0.0, " << -kWeight << "]\n"
    << "[solver]\ntype = \"static\"\n"
    << "[[output.probes]]\nname = \"ring\"\nkind = \"node_position\"\n";
  return path;
}

}  // namespace

TEST(StaticFarStart, RingOnStiffRopeConvergesFromUpToOneRopeLengthAway) {
  const double h = exactDepth();
  constexpr double kTol = 1e-9;  // ft: the Newton tolerance's order
  double worst = 0.0;
  int mostIterations = 0;
  // Starts below the anchors' line or above it (the rope then stretched over the anchors).
  for (double d : {0.4, 1.0, 1.6, kL}) {
    for (double deg : {0.0, 60.0, 150.0, 210.0}) {
      const double x = 0.5 * kSpan + d * std::cos(deg * M_PI / 180.0);
      const double z = -h + d * std::sin(deg * M_PI / 180.0);
      const RunResult r = runCase(readCase(writeCase(x, z)), RunOptions{});
      ASSERT_EQ(r.status, RunStatus::Completed) << "start " << d << " ft at " << deg << " deg";
      const auto& row = r.rows.back();
      const double err = std::hypot(row[0] - 0.5 * kSpan, row[2] + h);
      std::printf("start %.3f ft at %5.1f deg: %3d Newton iterations, error %.2e ft\n", d, deg,
                  int(r.newtonIterations), err);
      EXPECT_LT(err, kTol) << "start " << d << " ft at " << deg << " deg";
      worst = std::max(worst, err);
      mostIterations = std::max(mostIterations, int(r.newtonIterations));
    }
  }
  std::printf("worst error %.2e ft (tolerance %.0e), most iterations %d\n", worst, kTol,
              mostIterations);
}
