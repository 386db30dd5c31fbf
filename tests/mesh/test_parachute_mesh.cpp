// Generated parachutes (mesh/ParachuteGenerator): C-9 counts and figures at half and full scale,
// .msh write / read-back, the generated case read into a model, the stress-free start (flat,
// folded, inflated), and meshing speed for a 50 k-triangle canopy.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "ClusterCaseWriter.hpp"
#include "ClusterGenerator.hpp"
#include "GmshMesh.hpp"
#include "MshReader.hpp"
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

namespace {
// A small parachute with every feature (vent, slider, payload box on risers), folded.
ParachuteSpec everything() {
  ParachuteSpec s;
  s.gores = 8;
  s.diameter = 2.0;
  s.ventDiameter = 0.4;
  s.lineLength = 2.0;
  s.lineElements = 4;
  s.elementSize = 0.4;
  s.sliderSide = 0.3;
  s.payloadMass = 1.0;
  s.payloadBox = {0.2, 0.2, 0.2};
  s.riserLength = 0.5;
  s.start = "folded";
  return s;
}
}  // namespace

// Every generator option over classes of values (tiny, subnormal, huge, near a bound, NaN, inf,
// negative): each is refused by name before gmsh runs (std::invalid_argument starting with the
// option), or yields a mesh and a case the reader takes. gmsh, given a vent ring 1e-9 wide,
// threw inside an OpenMP region and aborted chute (exit 134); a slider of 1e-12 gave a case that
// blew up at its first step.
TEST(ParachuteMesh, ExtremeValuesOfEveryOptionAreRefusedByNameOrGiveACaseThatReads) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> common = {5e-324, 1e-300, 1e-12, 1e-9, -1.0, -0.0,
                                      0.0,    1e6,    1e308, nan,  inf,  -inf};
  struct Option {
    const char* name;
    double ParachuteSpec::*field;
    std::vector<double> nearBounds;  // values near its bounds for this spec
  };
  const std::vector<Option> options = {
      {"--diameter", &ParachuteSpec::diameter, {1e-6, 0.8, 3.999}},
      {"--vent-diameter", &ParachuteSpec::ventDiameter, {1.999999999, 1.998, 0.002, 0.0019}},
      {"--line-length", &ParachuteSpec::lineLength, {1.000000001, 1.0000005, 1.01}},
      {"--element-size", &ParachuteSpec::elementSize, {1.0, 1.0000001, 0.01}},
      {"--slider", &ParachuteSpec::sliderSide, {0.002, 0.0019, 1.5, 3.0}},
      {"--payload-mass", &ParachuteSpec::payloadMass, {1e-6, 9e-7}},
      {"--riser-length", &ParachuteSpec::riserLength, {0.1415, 0.1414, 0.002}},
      {"--bundle-radius", &ParachuteSpec::bundleRadius, {0.999999, 0.002, 0.0019}},
      {"--slider-drop", &ParachuteSpec::sliderDrop, {1.9999, 5.0, 0.002}},
      {"--line-slack", &ParachuteSpec::lineSlack, {0.4999, 0.49}},
      {"--inflated-ratio", &ParachuteSpec::inflatedRatio, {0.63662, 0.6367, 0.99999999}}};
  int refused = 0, generated = 0;
  std::vector<std::string> wrong;
  const std::string msh = temp("extreme.msh"), toml = temp("extreme.toml");
  for (const auto& o : options) {
    std::vector<double> values = common;
    values.insert(values.end(), o.nearBounds.begin(), o.nearBounds.end());
    for (const double v : values) {
      ParachuteSpec s = everything();
      s.*o.field = v;
      if (std::string(o.name) == "--inflated-ratio") s.start = "inflated";
      s.caseLimits = {MshLimits{}.maxNodes, MshLimits{}.maxElements, 300000};
      const std::string what = std::string(o.name) + " " + std::to_string(v);
      try {
        const auto g = generateParachute(s, msh);
        writeParachuteCase(s, g, toml, msh, {});
        readCase(toml);
        ++generated;
      } catch (const std::invalid_argument& e) {
        ++refused;
        // Named by an option (this one, or the one it conflicts with).
        if (std::string(e.what()).rfind("--", 0) != 0) wrong.push_back(what + ": " + e.what());
      } catch (const std::exception& e) {
        wrong.push_back(what + ": " + e.what());
      }
    }
  }
  std::printf("%d values of %zu options: %d refused by name, %d generated a case that reads\n",
              refused + generated + static_cast<int>(wrong.size()), options.size(), refused,
              generated);
  for (const auto& w : wrong) ADD_FAILURE() << w;
  EXPECT_GT(generated, 10);
}

// The generated case's own options over the same classes of values, for the free flight (the
// default), the wind tunnel (--held) and the legacy --pressure frame: each is refused by name
// (std::invalid_argument starting with the option or the one it conflicts with), or gives a
// case the reader takes. A --speed beyond 200 m/s (or held, below 0.01 m/s), an altitude
// outside the troposphere, a negative permeability, an infinite interval are refused (a NaN
// --speed or --pressure means "the default" here: the command line refuses a number that is
// not finite).
TEST(ParachuteMesh, ExtremeValuesOfEveryCaseOptionAreRefusedByNameOrGiveACaseThatReads) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> common = {5e-324, 1e-300, 1e-12, 1e-9, -1.0, -0.0,
                                      0.0,    1e6,    1e308, nan,  inf,  -inf};
  struct Option {
    const char* name;
    double ParachuteCaseOptions::*field;
    std::vector<double> nearBounds;  // values near its bounds (ft units)
  };
  const std::vector<Option> options = {
      {"--speed", &ParachuteCaseOptions::speed, {656.16, 656.17, 1e4, 65.6, 0.0328, 0.0329}},
      {"--altitude", &ParachuteCaseOptions::altitude, {-1640.41, -1640.42, 36089.2, 36089.3}},
      {"--cloth-permeability", &ParachuteCaseOptions::clothPermeability, {1e4, 1.0001e4, 100}},
      {"--pressure", &ParachuteCaseOptions::pressure, {1e-6, 9.9e-7, 1e4, 1.01e4}},
      {"--ramp-time", &ParachuteCaseOptions::rampTime, {1e6, 1.01e6}},
      {"--dt", &ParachuteCaseOptions::dt, {2.0, 2.01, 2e-9, 1.99e-9}},
      {"--t-end", &ParachuteCaseOptions::tEnd, {1e6, 1.01e6, 2e-3, 1.99e-3}},
      {"--probe-interval", &ParachuteCaseOptions::probeInterval, {1e-3}},
      {"--vtu-interval", &ParachuteCaseOptions::vtuInterval, {1e-3}}};
  ParachuteSpec s = everything();
  const std::string msh = temp("extreme_case.msh"), toml = temp("extreme_case.toml");
  const auto g = generateParachute(s, msh);
  int refused = 0, written = 0;
  std::vector<std::string> wrong;
  for (const char* frame : {"free", "held", "pressure"})
    for (const auto& o : options) {
      std::vector<double> values = common;
      values.insert(values.end(), o.nearBounds.begin(), o.nearBounds.end());
      for (const double v : values) {
        ParachuteCaseOptions c;
        c.held = std::string(frame) == "held";
        if (std::string(frame) == "pressure") c.pressure = 0.1;
        c.*o.field = v;
        const std::string what = std::string(frame) + ": " + o.name + " " + std::to_string(v);
        try {
          writeParachuteCase(s, g, toml, msh, c);
          readCase(toml);
          ++written;
        } catch (const std::invalid_argument& e) {
          ++refused;
          if (std::string(e.what()).rfind("--", 0) != 0) wrong.push_back(what + ": " + e.what());
        } catch (const std::exception& e) {
          wrong.push_back(what + ": " + e.what());
        }
      }
    }
  std::printf(
      "%d values of %zu case options in 3 frames: %d refused by name, %d gave a case "
      "that reads\n",
      refused + written + static_cast<int>(wrong.size()), options.size(), refused, written);
  for (const auto& w : wrong) ADD_FAILURE() << w;
  EXPECT_GT(written, 30);
  // The speed's bounds (200 m/s, 656 ft/s; held, at least 0.01 m/s) in the case's units.
  ParachuteCaseOptions c;
  for (const double bad : {656.2, 1e4, 0.0, -1.0, inf}) {
    c.speed = bad;
    EXPECT_THROW(checkParachuteCaseOptions(c), std::invalid_argument) << bad;
  }
  c.speed = 1e-3;
  EXPECT_NO_THROW(checkParachuteCaseOptions(c));
  c.held = true;
  EXPECT_THROW(checkParachuteCaseOptions(c), std::invalid_argument);
  c.units = "si";
  c.speed = 0.01;
  EXPECT_NO_THROW(checkParachuteCaseOptions(c));
  c.speed = 201.0;
  EXPECT_THROW(checkParachuteCaseOptions(c), std::invalid_argument);
  c.speed = 200.0;
  EXPECT_NO_THROW(checkParachuteCaseOptions(c));
}

// Paths are written into the case as TOML strings with their quotes, backslashes and control
// characters escaped: a quote or newline in --out ended the string and broke the case.
TEST(ParachuteMesh, PathsWithQuotesBackslashesAndNewlinesReadBackAsThemselves) {
  ParachuteSpec s = c9(0.5);
  s.gores = 8;
  s.elementSize = 2.0;
  s.sliderSide = 0.0;
  const std::filesystem::path dir = temp("odd paths");
  std::filesystem::create_directories(dir);
  for (const std::string name :
       {"a\"b.msh", "back\\slash.msh", "new\nline.msh", "tab\tand \u00e9.msh"}) {
    const std::string msh = (dir / name).string();
    const std::string toml = (dir / ("case " + std::to_string(name.size()) + "\n\".toml")).string();
    const auto g = generateParachute(s, msh);
    writeParachuteCase(s, g, toml, msh, {});
    const CaseSpec c = readCase(toml);
    std::printf("mesh '%s': the case reads %d nodes (generated %zu), name '%s'\n", name.c_str(),
                c.model.numNodes(), g.mesh.nodeTags.size(), c.name.c_str());
    EXPECT_EQ(c.model.numNodes(), static_cast<int>(g.mesh.nodeTags.size()));
  }
  // The cluster's case writer escapes alike.
  ClusterSpec c;
  c.canopies = 2;
  c.parachute = s;
  c.parachute.start = "folded";
  c.payloadMass = 2.0;
  const std::string msh = (dir / "clu\"ster\n.msh").string();
  const std::string toml = (dir / "clu\"ster\\.toml").string();
  writeClusterCase(c, generateCluster(c, msh), toml, msh, {});
  const CaseSpec cluster = readCase(toml);
  std::printf("cluster over '%s': the case reads %d nodes, name '%s'\n", msh.c_str(),
              cluster.model.numNodes(), cluster.name.c_str());
  EXPECT_GT(cluster.model.numNodes(), 0);

  ParachuteCaseOptions o;
  o.dt = 3.0;  // larger than t_end = 2
  EXPECT_THROW(checkParachuteCaseOptions(o), std::invalid_argument);
  o.dt = 1e-12;
  o.tEnd = 1e6;  // 1e18 steps
  EXPECT_THROW(checkParachuteCaseOptions(o), std::invalid_argument);
  // A canopy pressure the generated case cannot fly: 1e6 psf (its explicit step blew up) or
  // 1e-12 psf (its energies are rounding noise); 0 is no pressure.
  o = ParachuteCaseOptions{};
  for (const double bad : {1e6, 1e-12, -1.01e4}) {
    o.pressure = bad;
    EXPECT_THROW(checkParachuteCaseOptions(o), std::invalid_argument) << bad;
  }
  for (const double fine : {0.0, 1e4, 1e-6, -0.5}) {
    o.pressure = fine;
    EXPECT_NO_THROW(checkParachuteCaseOptions(o)) << fine;
  }
  // A path that is not UTF-8 cannot be named in TOML: refused, not written.
  const std::string bad = (dir / "\xff.msh").string();
  EXPECT_THROW(writeParachuteCase(s, generateParachute(s, bad), (dir / "x.toml").string(), bad, {}),
               std::invalid_argument);
}

// A case is written only for a mesh `chute run` takes with its default limits: 1000 slider
// divisions (a million nodes, more than a case reads) are refused before gmsh runs, and so is a
// mesh estimated at more than 1.2 times the equations a run takes; one nearer the limit, once
// meshed, before anything is written. Lines,
// risers and slider quads finer than a tenth of the canopy's elements are refused (the explicit
// step follows the shortest element: 3,000 elements a line took minutes for 4 ms).
TEST(ParachuteMesh, ACaseBeyondTheRunsLimitsIsRefusedAtGeneration) {
  ParachuteSpec s = everything();
  s.sliderDivisions = 1000;
  s.caseLimits = {MshLimits{}.maxNodes, MshLimits{}.maxElements, 300000};
  try {
    generateParachute(s, "");
    FAIL() << "expected a refusal";
  } catch (const std::invalid_argument& e) {
    std::printf("%s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("--slider-divisions"), std::string::npos);
  }
  s.sliderDivisions = 200;  // 40,401 slider nodes: 121 k equations, within 300,000
  s.elementSize = 0.01;     // slider quads 1.5e-3 long: at least a tenth of the canopy's
  s.caseLimits.maxEquations = 100000;
  try {
    generateParachute(s, "");
    FAIL() << "expected a refusal";
  } catch (const std::invalid_argument& e) {
    std::printf("%s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("solver.max_equations"), std::string::npos);
  }
  // Within a fifth of the estimate the mesh is made, and its own count refuses it (checkForCase).
  s = everything();
  s.elementSize = 0.1;  // about 500 canopy nodes: the estimate's constant terms small beside them
  const std::size_t equations = 3 * (generateParachute(s, "").mesh.nodeTags.size() - 1);
  s.caseLimits = {MshLimits{}.maxNodes, MshLimits{}.maxElements, equations * 10 / 11};
  try {
    generateParachute(s, "");
    FAIL() << "expected a refusal";
  } catch (const std::invalid_argument& e) {
    std::printf("%s\n", e.what());
    EXPECT_EQ(std::string(e.what()).rfind("--case: the mesh has up to", 0), 0u);
  }
  s = everything();
  s.lineElements = 3000;  // 6.7e-4 ft elements under a canopy of 0.4 ft
  try {
    generateParachute(s, "");
    FAIL() << "expected a refusal";
  } catch (const std::invalid_argument& e) {
    std::printf("%s\n", e.what());
    EXPECT_EQ(std::string(e.what()).rfind("--line-elements: ", 0), 0u);
  }
}
