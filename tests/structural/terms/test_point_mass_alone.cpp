// A point mass on a node that no element uses (a free-flying payload, a ball) adds the only
// entries of its node to the matrix: its term must declare that node's block to the sparsity
// pattern (it did not, and the first implicit step failed with "SystemAssembler: entry (3, 4) is
// outside the sparsity pattern", exit 1). Such a node falls freely: z(t) = z0 - g t^2 / 2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "app/RunCase.hpp"
#include "case/CaseSpec.hpp"
#include "support/Scenes.hpp"

using namespace chute;

namespace {

const char* kCase = R"(
name = "free_ball"
units = "m, kg, s, N"
[nodes]
a = [0.0, 0.0, 0.0]
b = [1.0, 0.0, 0.0]
ball = [0.5, 2.0, 1.0]
[materials.rope]
E = 1.0e9
area = 1.0e-6
density = 1000.0
[[cables]]
name = "rope"
material = "rope"
path = ["a", "b"]
[[point_masses]]
node = "ball"
mass = 2.0
[boundary]
fixed = ["a", "b"]
[loads]
gravity = [0.0, 0.0, -9.81]
[solver]
dt = 0.01
t_end = 0.2
[[output.probes]]
name = "ball"
kind = "node_position"
)";

}  // namespace

TEST(PointMassTerm, AMassOnANodeNoElementUsesFallsFreely) {
  for (const std::string integrator : {"bossak", "generalized_alpha", "central_difference"}) {
    const std::string file = chute::testing::writeCase("free_ball", kCase);
    const CaseSpec spec = readCase(file, {"solver.integrator=\"" + integrator + "\""});
    const RunResult r = runCase(spec, RunOptions{});
    ASSERT_EQ(r.status, RunStatus::Completed) << integrator << ": " << r.reason;
    int zColumn = -1;
    for (size_t k = 0; k < r.columns.size(); ++k)
      if (r.columns[k] == "ball.z") zColumn = static_cast<int>(k);
    ASSERT_GE(zColumn, 0);
    double worst = 0.0;
    for (size_t i = 0; i < r.times.size(); ++i) {
      const double t = r.times[i];
      const double exact = 1.0 - 0.5 * 9.81 * t * t;
      worst = std::max(worst, std::abs(r.rows[i][zColumn] - exact));
    }
    const double drop = 0.5 * 9.81 * r.times.back() * r.times.back();
    std::printf("%s: %zu rows to t = %g, largest |z - (z0 - g t^2/2)| = %.3e (drop %.3f m)\n",
                integrator.c_str(), r.times.size(), r.times.back(), worst, drop);
    EXPECT_NEAR(r.times.back(), 0.2, 1e-12);
    // Constant acceleration is integrated exactly by these schemes up to rounding (and the
    // explicit start's half step): 1e-9 of the drop.
    EXPECT_LT(worst, 1e-9 * drop) << integrator;
  }
}
