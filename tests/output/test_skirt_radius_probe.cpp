// The skirt_radius probe (distance of a node set from an axis through two node-set centroids),
// on a disk about a tilted axis and on the C-9 cases' folded start.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <string>

#include "app/RunCase.hpp"
#include "case/CaseSpec.hpp"

using namespace chute;

namespace {
// Probe columns "<name>.mean/min/max" of the first output row.
std::array<double, 3> firstRadius(const RunResult& r, const std::string& name) {
  const auto at = [&](const std::string& c) {
    const auto it = std::find(r.columns.begin(), r.columns.end(), name + "." + c);
    EXPECT_NE(it, r.columns.end()) << c;
    return r.rows.front()[it - r.columns.begin()];
  };
  return {at("mean"), at("min"), at("max")};
}
}  // namespace

TEST(SkirtRadiusProbe, MeasuresTheDistanceFromATiltedAxis) {
  const double tilt = 0.4, R = 2.0;
  const std::string file =
      (std::filesystem::temp_directory_path() / "chute_skirt_radius_probe.toml").string();
  std::ofstream(file) << std::setprecision(17) << "[nodes]\ntip = [" << std::sin(tilt) << ", 0.0, "
                      << std::cos(tilt) << "]\n"
                      << R"([materials.film]
kind = "membrane"
E = 1.0e5
nu = 0.3
thickness = 1.0e-3
density = 1.0
[[membranes]]
name = "disk"
material = "film"
mesh = "disk"
radius = 2.0
rings = 3
[boundary]
fixed = ["tip"]
[solver]
dt = 1.0e-3
t_end = 2.0e-3
[[output.probes]]
name = "rim"
kind = "skirt_radius"
set = "disk.rim"
axis = ["disk.center", "tip"]
)";
  const CaseSpec spec = readCase(file);
  const auto r = runCase(spec, RunOptions{});
  ASSERT_EQ(r.status, RunStatus::Completed);
  // Independent: |d x e| for every rim node (the probe projects d onto the axis instead).
  const Eigen::Vector3d e(std::sin(tilt), 0.0, std::cos(tilt));
  const auto& m = spec.model;
  const Eigen::Vector3d c = m.X[m.nodeId("disk.center")];
  double sum = 0.0, lo = 1e300, hi = 0.0;
  const auto& rim = m.nodeSets.at("disk.rim");
  for (int n : rim) {
    const double d = (m.X[n] - c).cross(e).norm();
    sum += d;
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  const auto got = firstRadius(r, "rim");
  std::printf(
      "tilted axis (%.1f rad), %zu rim nodes: mean %.15f (expected %.15f), min %.15f, "
      "max %.15f (bounds R cos(tilt) = %.6f, R = %.1f)\n",
      tilt, rim.size(), got[0], sum / rim.size(), got[1], got[2], R * std::cos(tilt), R);
  EXPECT_NEAR(got[0], sum / rim.size(), 1e-12);
  EXPECT_NEAR(got[1], lo, 1e-12);
  EXPECT_NEAR(got[2], hi, 1e-12);
}

TEST(SkirtRadiusProbe, C9CasesStartWithTheSkirtAtTheBundleRadius) {
  // Both cases are folded to a bundle of radius 0.7 ft (D/20, documented in their headers), the
  // skirt nodes on a circle about the confluence -> vent axis.
  for (const char* name : {"c9_slider", "c9_no_slider"}) {
    const std::string file = std::string(CHUTE_SOURCE_DIR "/cases/") + name + ".toml";
    const CaseSpec spec = readCase(file, {"solver.t_end=0.004"});
    const auto r = runCase(spec, RunOptions{});
    ASSERT_EQ(r.status, RunStatus::Completed) << name;
    const auto got = firstRadius(r, "skirt");
    std::printf("%s: folded skirt radius mean %.15f min %.15f max %.15f (bundle radius 0.7)\n",
                name, got[0], got[1], got[2]);
    EXPECT_NEAR(got[0], 0.7, 1e-12);
    EXPECT_NEAR(got[1], 0.7, 1e-12);
    EXPECT_NEAR(got[2], 0.7, 1e-12);
  }
}
