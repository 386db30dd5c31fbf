// Generated parachutes (mesh/ParachuteGenerator): C-9 counts and figures at half and full scale,
// .msh write / read-back, the generated case read into a model, the stress-free start (flat,
// folded, inflated), and meshing speed for a 50 k-triangle canopy.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "GmshMesh.hpp"
#include "ParachuteCaseWriter.hpp"
#include "ParachuteGenerator.hpp"
#include "app/RunCase.hpp"
#include "case/CaseSpec.hpp"
#include "solver/StructuralSystem.hpp"

using namespace chute;
using namespace chute::mesh;

namespace {

// C-9 at scale s (1: 28 ft, 0.5: the paper's 14 ft half-scale model): 28 gores, lines 23 s ft.
ParachuteSpec c9(double scale) {
  ParachuteSpec s;
  s.gores = 28;
  s.diameter = 28.0 * scale;
  s.ventDiameter = 0.1 * s.diameter;
  s.lineLength = 23.0 * scale;
  s.lineElements = 8;
  s.elementSize = 0.035 * s.diameter;
  s.sliderSide = 0.1 * s.diameter;
  return s;
}

std::string temp(const std::string& name) {
  return ::testing::TempDir() + name;
}

int countPrefix(const GmshMesh& m, const std::string& prefix, int dim) {
  int n = 0;
  for (const auto& g : m.groups)
    if (g.dim == dim && g.name.rfind(prefix, 0) == 0 &&
        g.name.find_first_not_of("0123456789", prefix.size()) == std::string::npos)
      ++n;
  return n;
}

// |internal force| at the start X + u0, without external loads, and the largest line stiffness.
double startForce(CaseSpec& spec) {
  Model& m = spec.model;
  m.gravity.setZero();
  m.pressures.clear();
  m.drags.clear();
  StructuralSystem sys(m, spec.solver.search);
  Eigen::VectorXd x(3 * m.numNodes()), zero = Eigen::VectorXd::Zero(3 * m.numNodes());
  for (int i = 0; i < m.numNodes(); ++i) x.segment<3>(3 * i) = m.X[i] + m.u0[i];
  sys.assemble(EvalPoint::statics(x, zero, 0.0, 1.0), false);
  return sys.residual().norm();
}

double forceScale(const Model& m) {
  double s = 0.0;
  for (const auto& mat : m.materials) s = std::max(s, mat.E * mat.area);
  return s;
}

}  // namespace

TEST(ParachuteMesh, C9HalfAndFullScaleCountsAreaAndLineLengths) {
  for (double scale : {0.5, 1.0}) {
    const ParachuteSpec s = c9(scale);
    const auto g = generateParachute(s, "");
    const GmshMesh& m = g.mesh;
    const double areaError = g.canopyArea / g.flatArea - 1.0;
    std::printf(
        "C-9 %g ft: %zu nodes, %zu triangles, %zu groups; canopy area %.4f vs flat %.4f (%+.4f "
        "%%); max line length error %.2e ft; meshed in %.3f s\n",
        s.diameter, m.nodeTags.size(), g.triangles, m.groups.size(), g.canopyArea, g.flatArea,
        100 * areaError, g.maxLineLengthError, g.meshSeconds);
    EXPECT_EQ(countPrefix(m, "gore_", 2), 28);
    EXPECT_EQ(countPrefix(m, "line_", 1), 28);
    EXPECT_EQ(countPrefix(m, "grommet_", 0), 4);
    EXPECT_EQ(countPrefix(m, "skirt_", 0), 28);
    ASSERT_NE(m.group("grommets", 0), nullptr);
    EXPECT_EQ(m.group("grommets", 0)->nodes().size(), 4u);
    EXPECT_EQ(m.group("slider", 2)->elements.size(), 1u);  // one 4-node quad
    EXPECT_EQ(m.group("slider", 2)->elements[0].size(), 4u);
    EXPECT_EQ(m.group("slider_edges", 1)->elements.size(), 4u);
    EXPECT_EQ(m.group("radial_seams", 1)->nodes().size() > 28u * 2, true);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(g.linesPerGrommet[k], 7);
    // every group: canopy, 28 gores, seams, skirt band, vent band, lines, 28 lines, skirt
    // points, 28 skirt nodes, confluence, slider, slider edges, grommets, 4 grommets
    EXPECT_EQ(m.groups.size(), 1u + 28 + 3 + 1 + 28 + 1 + 28 + 1 + 2 + 1 + 4);
    for (int j = 0; j < 28; ++j)
      EXPECT_EQ(m.group("line_" + std::to_string(j), 1)->elements.size(), 8u);
    EXPECT_LT(std::abs(areaError), 0.005);
    EXPECT_LT(g.maxLineLengthError, 1e-12 * s.lineLength);
  }
}

TEST(ParachuteMesh, WrittenMshReadsBackAsTheSameMeshAndCase) {
  ParachuteSpec s = c9(0.5);
  s.start = "folded";
  s.payloadMass = 6.0;
  s.payloadBox = {1.0, 0.8, 0.6};
  s.riserLength = 2.0;
  const std::string msh = temp("c9_roundtrip.msh"), toml = temp("c9_roundtrip.toml");
  const auto g = generateParachute(s, msh);
  writeParachuteCase(s, g, toml, msh, {});
  const GmshMesh back = readMesh(msh);
  ASSERT_EQ(back.nodeTags, g.mesh.nodeTags);
  double dx = 0.0, du = 0.0;
  for (size_t i = 0; i < back.coords.size(); ++i)
    dx = std::max(dx, (back.coords[i] - g.mesh.coords[i]).norm());
  ASSERT_EQ(back.groups.size(), g.mesh.groups.size());
  for (size_t k = 0; k < back.groups.size(); ++k) {
    EXPECT_EQ(back.groups[k].name, g.mesh.groups[k].name);
    EXPECT_EQ(back.groups[k].dim, g.mesh.groups[k].dim);
    EXPECT_EQ(back.groups[k].elements, g.mesh.groups[k].elements) << back.groups[k].name;
  }
  const auto& u = back.views.at("initial_displacement");
  const auto& u1 = g.mesh.views.at("initial_displacement");
  ASSERT_EQ(u.size(), u1.size());
  for (const auto& [tag, v] : u) du = std::max(du, (v - u1.at(tag)).norm());
  std::printf("round trip: %zu nodes, %zu groups; max coordinate change %.2e, start %.2e\n",
              back.nodeTags.size(), back.groups.size(), dx, du);
  EXPECT_LT(dx, 1e-13 * s.diameter);
  EXPECT_LT(du, 1e-13 * s.diameter);

  // The generated case maps every part.
  const CaseSpec c = readCase(toml);
  const Model& m = c.model;
  size_t canopyTriangles = g.triangles, cables = 0;
  for (const char* n : {"radial_seams", "skirt_band", "vent_band", "risers", "payload_box"})
    cables += g.mesh.group(n, 1)->elements.size();
  EXPECT_EQ(m.membranes.size(), canopyTriangles + 1);
  EXPECT_EQ(m.cables.size(), cables);
  EXPECT_EQ(m.groups.size(), 28u);
  double payload = 0.0;
  for (double pm : m.pointMass) payload += pm;
  EXPECT_NEAR(payload, 6.0, 1e-12);
  for (const auto& grp : m.groups) {
    EXPECT_EQ(grp.numElements(), 8);
    double L = 0.0;
    for (double l : grp.refLength) L += l;
    EXPECT_NEAR(L, s.lineLength, 1e-12 * s.lineLength);
  }
  EXPECT_EQ(m.nodeName[m.nodeId("confluence")], "confluence");
}

TEST(ParachuteMesh, FlatFoldedAndInflatedStartsAreStressFree) {
  for (const char* start : {"flat", "folded", "inflated"}) {
    ParachuteSpec s = c9(0.5);
    s.start = start;
    s.payloadMass = 6.0;
    s.payloadBox = {1.0, 0.8, 0.6};
    s.riserLength = 2.0;
    const std::string msh = temp(std::string("c9_") + start + ".msh");
    const std::string toml = temp(std::string("c9_") + start + ".toml");
    const auto g = generateParachute(s, msh);
    writeParachuteCase(s, g, toml, msh, {});
    CaseSpec c = readCase(toml);
    const Model& m = c.model;
    // The start is what it claims: folded into a bundle, sliders on their elements and no line
    // element longer than its reference length.
    double radius = 0.0, worstLine = 0.0, sliderOff = 0.0;
    for (int n : m.nodeSets.at("canopy"))
      radius = std::max(radius, std::hypot((m.X[n] + m.u0[n]).x(), (m.X[n] + m.u0[n]).y()));
    for (const auto& grp : m.groups) {
      const int k = grp.initialActive[0];
      for (int e = 0; e < grp.numElements(); ++e) {
        const Vec3 a = m.X[grp.chain[e]] + m.u0[grp.chain[e]];
        const Vec3 b = m.X[grp.chain[e + 1]] + m.u0[grp.chain[e + 1]];
        const Vec3 x = m.X[grp.sliders[0]] + m.u0[grp.sliders[0]];
        const double l = e == k ? (x - a).norm() + (b - x).norm() : (b - a).norm();
        worstLine = std::max(worstLine, l / grp.refLength[e]);
        if (e == k)  // the slider on the chain's bent polyline: the element bends at it
          sliderOff = std::max(sliderOff, std::min((x - a).norm(), (b - x).norm()) / l);
      }
    }
    const double f = startForce(c), scale = forceScale(m);
    std::printf(
        "%s start: canopy radius %.3f ft (flat %.1f), max start stretch %.6f, longest line "
        "element %.6f of its length, slider >= %.4f of its element from a node; |internal force| "
        "%.3e lbf = %.2e of the largest EA\n",
        start, radius, s.diameter / 2, g.maxStartStretch, worstLine, sliderOff, f, f / scale);
    if (std::string(start) == "folded") {
      EXPECT_LT(radius, 1.01 * s.diameter / 40);
    }
    if (std::string(start) == "inflated") {  // the skirt at the projected radius 0.7 R
      EXPECT_NEAR(radius, s.inflatedRatio * s.diameter / 2, 0.01 * s.diameter / 2);
      const int conf = m.nodeId("confluence");  // the confluence starts at its reference point
      EXPECT_LT(m.u0[conf].norm(), 1e-12);
    }
    EXPECT_LE(g.maxStartStretch, 1.0 + 1e-12);
    EXPECT_LE(worstLine, 1.0);
    EXPECT_GT(sliderOff, 1e-3);
    EXPECT_LT(f / scale, 1e-12);
  }
}

TEST(ParachuteMesh, FiftyThousandTriangleCanopyMeshesInUnderTenSeconds) {
  ParachuteSpec s = c9(1.0);
  s.sliderSide = 0.0;
  // Equilateral triangles of side h cover sqrt(3)/4 h^2: 50 k of them cover the canopy at h ~
  s.elementSize = std::sqrt(4.0 / std::sqrt(3.0) * std::numbers::pi * 14.0 * 14.0 / 50000.0);
  const auto t0 = std::chrono::steady_clock::now();
  const auto g = generateParachute(s, "");
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%zu canopy triangles: gmsh %.2f s, with read-out and figures %.2f s (h = %.4f ft)\n",
              g.triangles, g.meshSeconds, total, s.elementSize);
  EXPECT_GT(g.triangles, 45000u);
  EXPECT_LT(total, 10.0);
}

TEST(ParachuteMesh, BadParametersNameTheOption) {
  ParachuteSpec s = c9(0.5);
  s.lineLength = 5.0;  // shorter than the radius
  try {
    generateParachute(s, "");
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--line-length"), std::string::npos) << e.what();
  }
}

TEST(ParachuteMesh, GeneratedFoldedCaseRunsAFewSteps) {
  ParachuteSpec s = c9(0.5);
  s.gores = 8;
  s.elementSize = 1.5;
  s.start = "folded";
  s.payloadMass = 6.0;
  const std::string msh = temp("small.msh"), toml = temp("small.toml");
  writeParachuteCase(s, generateParachute(s, msh), toml, msh, {});
  const CaseSpec c = readCase(toml, {"solver.t_end=0.003"});
  const auto r = runCase(c, RunOptions{});
  std::printf("generated folded 8-gore case: %s, %ld steps, %.2f Newton iterations/step\n",
              std::string(runStatusName(r.status)).c_str(), r.steps, r.newtonPerStep());
  EXPECT_EQ(r.status, RunStatus::Completed);
}
