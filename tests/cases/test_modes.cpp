// Static mode, prescribed motion and groups sharing a slider, through the case-file path.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "app/RunCase.hpp"
#include "case/CaseSpec.hpp"
#include "support/Scenes.hpp"

using namespace chute;
using chute::testing::writeCase;

namespace {

// A bead of weight W on a rope through its slider, ends fixed at (0,0,0) and (2,0,0).
std::string beadCase(const std::string& solver, const std::string& extra = "",
                     const std::string& fixed = R"(["a", "b"])") {
  return R"(
[nodes]
a = [0.0, 0.0, 0.0]
b = [2.0, 0.0, 0.0]
bead = [0.3, 0.0, -0.6]
[materials.rope]
E = 1.0e7
area = 1.0e-3
[[sliding_groups]]
name = "rope"
material = "rope"
path = ["a", "bead", "b"]
sliders = ["bead"]
elements = 5
prestrain = 1.0e-3
[[point_masses]]
node = "bead"
mass = 1.0
[boundary]
fixed = )" +
         fixed + R"(
[loads]
gravity = [0.0, 0.0, -10.0]
)" + extra +
         solver + R"(
[output]
[[output.probes]]
name = "bead"
[[output.probes]]
name = "N"
kind = "line_force"
set = "rope"
element = 0
[[output.probes]]
name = "b"
)";
}
}  // namespace

TEST(StaticMode, BeadSlidesToTheBottomOfItsRopeAndCarriesItsWeight) {
  // A frictionless bead comes to rest midway between the ends; the two parts share its weight:
  // 2 N sin(theta) = W with the same tension N on both sides. On its way from x = 0.3 the bead
  // crosses a rope node (arc length 0.67 -> 1.24, nodes every 0.49).
  const auto spec = readCase(writeCase("static_bead", beadCase(R"(
[solver]
type = "static"
load_steps = 4
)")));
  const auto r = runCase(spec, RunOptions{});
  ASSERT_EQ(r.status, RunStatus::Completed) << r.reason;
  const auto& row = r.rows.back();
  const double x = row[0], z = row[2], N = row[3];
  const double l1 = std::hypot(x, z);
  const double sinTheta = -z / l1;
  std::printf(
      "static bead: x = %.9f (expected 1), 2 N sin(theta) = %.9f (expected W = 10), "
      "%ld Newton iterations\n",
      x, 2 * N * sinTheta, r.newtonIterations);
  EXPECT_NEAR(x, 1.0, 1e-9);
  EXPECT_NEAR(2 * N * sinTheta, 10.0, 1e-8);
  EXPECT_GE(r.handovers.at(0), 1);
}

TEST(PrescribedMotion, AnchorDrivenSinusoidallyIsFollowedExactly) {
  // The right anchor is driven up and down; the prescribed dofs follow x(t) exactly and the bead,
  // hanging on the moving rope, stays within it.
  const auto spec = readCase(writeCase("driven_bead", beadCase(R"(
[solver]
dt = 1.0e-3
t_end = 0.5
)",
                                                               R"(
[[boundary.prescribed]]
nodes = ["b"]
amplitude = [0.0, 0.0, 0.1]
frequency = 2.0
)",
                                                               R"(["a"])")));
  const auto r = runCase(spec, RunOptions{});
  ASSERT_EQ(r.status, RunStatus::Completed) << r.reason;
  EXPECT_EQ(r.rejectedSteps, 0);
  double worst = 0.0;
  for (size_t k = 0; k < r.times.size(); ++k) {
    const double t = r.times[k];
    const double expectedZ = 0.1 * std::sin(2 * M_PI * 2.0 * t);
    worst = std::max(worst, std::abs(r.rows[k][5] - 2.0) + std::abs(r.rows[k][7] - expectedZ));
  }
  std::printf("prescribed anchor: worst deviation from x(t) over %zu outputs %.2e\n",
              r.times.size(), worst);
  EXPECT_LE(worst, 1e-14);
}

TEST(SharedSlider, BeadOnTwoRopesFollowsTheEllipse) {
  const auto r = runCase(readCase(CHUTE_SOURCE_DIR "/cases/bead_two_ropes.toml"), RunOptions{});
  ASSERT_EQ(r.status, RunStatus::Completed);
  std::printf(
      "bead on two ropes (two groups, one slider): max error %.3e = %.4f %% of the swing, "
      "hand-overs %ld and %ld\n",
      r.reference->maxError, 100 * r.reference->relative(), r.handovers.at(0), r.handovers.at(1));
  EXPECT_LE(r.reference->relative(), 5e-3);
  EXPECT_GT(r.handovers.at(0), 0);
  EXPECT_EQ(r.handovers.at(0), r.handovers.at(1));
}
