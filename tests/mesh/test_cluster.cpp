// Clusters (mesh/ClusterGenerator.hpp): two and three canopies with distinct groups, risers to one
// payload, canopy centres at the asked spacing; the written .msh reads back with the same groups;
// the generated case reads, starts stress-free and free of intersections, and runs a few steps.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "ClusterCaseWriter.hpp"
#include "ClusterGenerator.hpp"
#include "PackedSceneChecks.hpp"
#include "app/RunCase.hpp"

using namespace chute;
using namespace chute::mesh;

TEST(Cluster, TwoAndThreeCanopiesOnRisersStartStressFreeAndApart) {
  for (int n : {2, 3}) {
    for (const char* start : {"folded", "packed"}) {
      ClusterSpec c;
      c.canopies = n;
      c.parachute.gores = 12;
      c.parachute.diameter = 14.0;
      c.parachute.ventDiameter = 1.4;
      c.parachute.lineLength = 11.5;
      c.parachute.elementSize = 0.9;
      c.parachute.sliderSide = n == 2 ? 1.4 : 0.0;
      c.parachute.start = start;
      c.payloadMass = 12.0;
      const std::string msh = ::testing::TempDir() + "cluster.msh";
      const std::string toml = ::testing::TempDir() + "cluster.toml";
      const auto g = generateCluster(c, msh);
      writeClusterCase(c, g, toml, msh, {});
      const GmshMesh& m = g.mesh;
      // Distinct sets per canopy; every canopy a copy of the single parachute.
      for (int i = 1; i <= n; ++i) {
        const auto* canopy = m.group("canopy_" + std::to_string(i), 2);
        ASSERT_NE(canopy, nullptr);
        EXPECT_EQ(canopy->elements.size(), g.single.mesh.group("canopy", 2)->elements.size());
        ASSERT_NE(m.group("confluence_" + std::to_string(i), 0), nullptr);
        ASSERT_NE(m.group("riser_" + std::to_string(i), 1), nullptr);
      }
      EXPECT_EQ(m.group("canopy", 2), nullptr);
      EXPECT_EQ(m.group("risers", 1)->elements.size(), size_t(n * c.riserElements));
      // Neighbouring canopies' skirt centres (reference) are `spacing` apart.
      auto centre = [&](int i) {
        Vec3 sum = Vec3::Zero();
        const auto nodes = m.group("skirt_points_" + std::to_string(i), 0)->nodes();
        for (auto t : nodes) sum += m.at(t);
        return Vec3(sum / double(nodes.size()));
      };
      const double spacing = (centre(1) - centre(2)).norm();
      // The .msh reads back with the same groups (chute's own reader).
      const GmshMesh back = readMesh(msh);
      ASSERT_EQ(back.groups.size(), m.groups.size());
      size_t mismatched = 0;
      for (const auto& grp : m.groups) {
        const auto* b = back.group(grp.name, grp.dim);
        if (!b || b->elements.size() != grp.elements.size()) ++mismatched;
      }
      const auto f = scenes::startFigures(toml);
      CaseSpec spec =
          readCase(toml, {"solver.t_end=" + std::to_string(5 * readCase(toml).solver.dt)});
      const auto r = runCase(spec, RunOptions{});
      std::printf(
          "%d canopies, %s: %zu nodes, %zu groups (%zu read back differently); centres %.4f apart "
          "(asked %.4f), tilt %.2f deg; longest line element %.6f; |internal force| %.2e of the "
          "largest EA; %zu triangles, %zu segments: %ld + %ld intersections; 5 steps %s\n",
          n, start, m.nodeTags.size(), m.groups.size(), mismatched, spacing, g.spacing,
          g.tilt * 180 / std::numbers::pi, f.worstLine, f.force / f.forceScale, f.triangles,
          f.segments, f.intersections.trianglePairs, f.intersections.segmentTriangle,
          std::string(runStatusName(r.status)).c_str());
      EXPECT_EQ(mismatched, 0u);
      EXPECT_NEAR(spacing, g.spacing, 1e-9 * g.spacing);
      EXPECT_LE(f.worstLine, 1.0 + 1e-12);
      EXPECT_LT(f.force / f.forceScale, 1e-12);
      EXPECT_EQ(f.intersections.total(), 0);
      EXPECT_EQ(r.status, RunStatus::Completed);
    }
  }
}

TEST(Cluster, BadOptionsNameTheOption) {
  ClusterSpec c;
  c.canopies = 4;
  c.parachute.gores = 12;
  c.parachute.diameter = 14.0;
  c.parachute.lineLength = 11.5;
  c.parachute.elementSize = 0.9;
  try {
    generateCluster(c, "");
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    std::printf("%s\n", e.what());
    EXPECT_EQ(std::string(e.what()).rfind("--canopies", 0), 0u);
  }
}
