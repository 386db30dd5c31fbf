// The packed start (mesh/PackedStart.hpp): stress-free (no element stretched, no internal force),
// free of intersections by the independent check, inside its bag, layers at least the gap apart,
// for the half-scale C-9 with its slider, a vent-less canopy and an odd number of gores; bad pack
// sizes name their option.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "PackedSceneChecks.hpp"
#include "PackedStart.hpp"
#include "ParachuteCaseWriter.hpp"
#include "ParachuteGenerator.hpp"

using namespace chute;
using namespace chute::mesh;

namespace {

ParachuteSpec halfScaleC9() {
  ParachuteSpec s;
  s.gores = 28;
  s.diameter = 14.0;
  s.ventDiameter = 1.4;
  s.lineLength = 11.5;
  s.elementSize = 0.49;
  s.sliderSide = 1.4;
  s.payloadMass = 6.0;
  s.start = "packed";
  s.packGap = 1e-3 / 0.3048;  // 1 mm in ft
  return s;
}

}  // namespace

TEST(PackedStart, StressFreeInsideItsBagAndFreeOfIntersections) {
  struct Variant {
    const char* name;
    ParachuteSpec spec;
  };
  ParachuteSpec c9 = halfScaleC9();
  ParachuteSpec ventless = halfScaleC9();
  ventless.gores = 8;
  ventless.ventDiameter = 0.0;
  ventless.sliderSide = 0.0;
  ventless.elementSize = 0.8;
  ParachuteSpec odd = halfScaleC9();
  odd.gores = 13;
  odd.sliderSide = 0.0;
  odd.packLength = 2.0;
  odd.packDiameter = 0.8;
  for (const auto& v :
       {Variant{"half-scale C-9, slider", c9}, Variant{"8 gores, no vent", ventless},
        Variant{"13 gores, 2 x 0.8 ft bag", odd}}) {
    const ParachuteSpec& s = v.spec;
    const std::string msh = ::testing::TempDir() + "packed.msh";
    const std::string toml = ::testing::TempDir() + "packed.toml";
    const auto g = generateParachute(s, msh);
    writeParachuteCase(s, g, toml, msh, {});
    const PackLayout pack = packLayout(s);
    const auto f = scenes::startFigures(toml);
    // The canopy inside the bag: above the skirt plane, below the bag's top, within its radius.
    const GmshMesh& m = g.mesh;
    const double H = std::sqrt(s.lineLength * s.lineLength - s.diameter * s.diameter / 4);
    double zLo = 1e300, zHi = -1e300, radius = 0.0;
    for (std::size_t t : m.group("canopy", 2)->nodes()) {
      const Vec3 x = m.at(t) + m.views.at("initial_displacement").at(t);
      zLo = std::min(zLo, x.z() - H);
      zHi = std::max(zHi, x.z() - H);
      radius = std::max(radius, std::hypot(x.x(), x.y()));
    }
    std::printf(
        "%s: %zu triangles, %d runs, pitch %.4f, layers %.4f x %.4f, pleats >= %.5f apart (gap "
        "%.5f); bag %.3f x %.3f: canopy z - H in [%.2e, %.4f], radius %.4f; stretch %.6f, longest "
        "line element %.6f; |internal force| %.2e of the largest EA; %zu triangles and %zu "
        "segments: %ld + %ld intersections\n",
        v.name, g.triangles, pack.runs, pack.pitch, 2 * pack.halfThickness, 2 * pack.halfWidth,
        pack.minSeparation, pack.gap, pack.length, pack.diameter, zLo, zHi, radius,
        g.maxStartStretch, f.worstLine, f.force / f.forceScale, f.triangles, f.segments,
        f.intersections.trianglePairs, f.intersections.segmentTriangle);
    EXPECT_LE(g.maxStartStretch, 1.0);
    EXPECT_LE(f.worstLine, 1.0);
    EXPECT_LT(f.force / f.forceScale, 1e-12);
    EXPECT_EQ(f.intersections.total(), 0);
    EXPECT_EQ(f.intersections.degenerateTriangles, 0);
    EXPECT_GE(zLo, -1e-12 * H);
    EXPECT_LE(zHi, pack.length);
    EXPECT_LE(radius, pack.diameter / 2);
    EXPECT_GE(pack.minSeparation, pack.gap);
  }
}

TEST(PackedStart, CreaseCirclesKeepTheCanopyArea) {
  // The packed start meshes its gores in bands between crease circles: more triangles, the same
  // canopy.
  ParachuteSpec s = halfScaleC9();
  s.start = "folded";
  const auto folded = generateParachute(s, "");
  s.start = "packed";
  const auto packed = generateParachute(s, "");
  std::printf("half-scale C-9: %zu triangles folded, %zu packed (%zu crease circles)\n",
              folded.triangles, packed.triangles, packLayout(s).foldRadii.size());
  EXPECT_GT(packed.triangles, folded.triangles);
  EXPECT_NEAR(packed.canopyArea, folded.canopyArea, 1e-3 * folded.canopyArea);
}

TEST(PackedStart, BagsThatCannotPackNameTheirOption) {
  ParachuteSpec s = halfScaleC9();
  for (const double d : {0.01, 1e6}) {  // too small for its layers; wider than the canopy
    s.packDiameter = d;
    try {
      generateParachute(s, "");
      FAIL() << "expected an error";
    } catch (const std::invalid_argument& e) {
      std::printf("%s\n", e.what());
      EXPECT_EQ(std::string(e.what()).rfind("--pack-diameter", 0), 0u) << e.what();
    }
  }
  s = halfScaleC9();
  s.packLength = 0.05;
  try {
    generateParachute(s, "");
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    std::printf("%s\n", e.what());
    EXPECT_EQ(std::string(e.what()).rfind("--pack-", 0), 0u) << e.what();
  }
}
