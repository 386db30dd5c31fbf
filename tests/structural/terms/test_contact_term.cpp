// The contact term (docs/contact.md) in small scenes: its assembled Jacobian against central
// differences of its residual (penalty, damping and lagged friction together), the energy of a
// sheet bouncing on a fixed sheet (conserved without damping and friction, never rising with
// them), the stable-step bound against the assembled system's highest frequency, restarts bit
// for bit (explicit and implicit), and no interpenetration of a crumpling sheet by an independent
// segment-triangle count (tests/support/Intersections.hpp), against many without contact.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/RunCase.hpp"
#include "case/CaseSpec.hpp"
#include "solver/StructuralSystem.hpp"
#include "support/AssembledJacobian.hpp"
#include "support/Intersections.hpp"
#include "support/Scenes.hpp"
#include "support/TempDir.hpp"
#include "support/VisitRun.hpp"
#include "terms/contact/ContactTerm.hpp"

using namespace chute;
using chute::testing::writeCase;
namespace fs = std::filesystem;

namespace {

// A 0.8 m sheet (6 x 6 x 2 triangles) 3 cm above a fixed 1.2 m floor (8 x 8 x 2), offset so that
// no vertex lies above a vertex; units m, kg, s, N. `contact` is the [contact] section.
std::string dropScene(const std::string& contact,
                      const std::string& integrator = "central_difference", double dt = 1e-3,
                      double tEnd = 0.3) {
  return R"(
name = "drop"
[materials.cloth]
kind = "membrane"
E = 5.0e8
nu = 0.3
thickness = 1.0e-4
density = 1000.0
[[membranes]]
name = "floor"
material = "cloth"
mesh = "rectangle"
corner = [-0.6, -0.6, 0.0]
size = [1.2, 1.2, 0.0]
divisions = [8, 8]
element = "triangle"
[[membranes]]
name = "sheet"
material = "cloth"
mesh = "rectangle"
corner = [-0.43, -0.41, 0.03]
size = [0.8, 0.8, 0.0]
divisions = [6, 6]
element = "triangle"
wrinkling = false
[[boundary.constraints]]
set = "floor"
dofs = "xyz"
[loads]
gravity = [0.0, 0.0, -9.81]
[contact]
thickness = 0.01
)" + contact +
         R"(
[solver]
integrator = ")" +
         integrator + "\"\ndt = " + std::to_string(dt) + "\nt_end = " + std::to_string(tEnd) + R"(
[output]
interval = 0.0025
[[output.probes]]
name = "energy"
kind = "energy"
[[output.probes]]
name = "mid"
kind = "node_position"
node = "sheet.center"
)";
}

int column(const RunResult& r, const std::string& name) {
  for (size_t c = 0; c < r.columns.size(); ++c)
    if (r.columns[c] == name) return static_cast<int>(c);
  ADD_FAILURE() << "no column " << name;
  return 0;
}

RunResult run(const std::string& name, const std::string& text,
              const RunOptions& o = RunOptions{}) {
  return runCase(readCase(writeCase(name, text)), o);
}

std::string readFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

// CT4-CT8 assembled: cx dr/dx + cv dr/dv of penalty, damping and the lagged friction of the pairs
// in contact at the step's start, against central differences of the residual along the
// integrator's path (tests/support/AssembledJacobian.hpp), with the sheet pressed into the floor.
TEST(ContactTerm, AssembledJacobianMatchesCentralDifferences) {
  const CaseSpec c = readCase(
      writeCase("contact_jacobian",
                dropScene("damping_ratio = 0.3\nfriction = 0.3\nslip_speed = 0.05", "bossak")));
  const Model& m = c.model;
  StructuralSystem sys(m, c.solver.search);
  ASSERT_NE(sys.termList().contact(), nullptr);
  // The sheet lowered to 4-9 mm above the floor (within dHat = 10 mm), moving down and sideways.
  chute::testing::MovingState s{Eigen::VectorXd(3 * m.numNodes()),
                                Eigen::VectorXd(3 * m.numNodes()),
                                Eigen::VectorXd::Zero(3 * m.numNodes())};
  for (int n = 0; n < m.numNodes(); ++n) {
    s.x.segment<3>(3 * n) = m.X[n];
    s.v.segment<3>(3 * n).setZero();
  }
  for (int n : m.nodeSets.at("sheet")) {
    s.x[3 * n + 2] = 0.0065 + 0.0025 * std::sin(7.1 * n);
    s.v.segment<3>(3 * n) = Vec3(0.3 * std::cos(1.3 * n), 0.2 * std::sin(0.9 * n), -0.4);
  }
  // One step's evaluation and commit: the friction's lag is then that of these positions.
  sys.updateState(s.x);
  const EvalPoint step = EvalPoint::implicitStep(s.x, s.v, s.a, 0.1, {1.0, 0.0, 0.0}, 1e-3);
  sys.assemble(step, false);
  sys.commit(CommitPoint{s.x, 0.1, 1e-3, 0.1});
  // Positions 1e-4 m off, so that the lag (from the commit) is not at the evaluation point.
  for (int n : m.nodeSets.at("sheet")) s.x[3 * n] += 1e-4;
  const double err = chute::testing::assembledJacobianError(sys, s, 0.8, 30.0, 4000.0, 1e-8);
  std::printf("contact Jacobian (penalty, damping, friction) against central differences: %.2e\n",
              err);
  EXPECT_LT(err, 1e-6);
}

// CT4 with central differences: undamped and frictionless, the sheet falls, bounces on the floor
// and rises; kinetic + strain (membranes and contact) + gravity stays within the integrator's
// error.
TEST(ContactTerm, UndampedBounceConservesEnergy) {
  const auto r = run("contact_bounce", dropScene("damping_ratio = 0.0\nfriction = 0.0"));
  ASSERT_EQ(r.status, RunStatus::Completed);
  const int e = column(r, "energy.total"), z = column(r, "mid.z");
  const double e0 = r.rows.front()[e];
  double worst = 0.0, lowest = 1.0, highestAfter = 0.0;
  bool bounced = false;
  for (const auto& row : r.rows) {
    worst = std::max(worst, std::abs(row[e] - e0) / e0);
    if (row[z] < lowest) lowest = row[z];
    if (lowest < 0.015) bounced = true;
    if (bounced) highestAfter = std::max(highestAfter, row[z]);
  }
  std::printf(
      "bounce: centre down to %.4f m (floor + dHat = 0.010), back up to %.4f m; largest "
      "|E - E0| / E0 %.2e over %zu rows; contact: closest d / dHat %.3f\n",
      lowest, highestAfter, worst, r.rows.size(), r.contact->closest);
  EXPECT_TRUE(bounced);
  EXPECT_GT(lowest, 0.0);
  EXPECT_GT(highestAfter, 0.028);  // back to nearly where it started (0.03)
  EXPECT_LT(worst, 5e-3);
}

// CT6-CT7, CT14: with damping and friction (gravity tilted so that the sheet slides on the floor)
// the energy never rises by more than the integrator's error, and friction and damping take a good
// part of it out.
TEST(ContactTerm, DampingAndFrictionNeverSupplyEnergy) {
  std::string text = dropScene("damping_ratio = 0.3\nfriction = 0.3");
  text.replace(text.find("gravity = [0.0, 0.0, -9.81]"), 27, "gravity = [3.0, 0.0, -9.81]");
  // Canopy cloth: wrinkling (a sheet that resists compression in its plane and is dragged by
  // friction against its fall rings at the stable step's limit without damping; not contact's).
  text.replace(text.find("wrinkling = false"), 17, "wrinkling = true");
  const auto r = run("contact_dissipation", text);
  ASSERT_EQ(r.status, RunStatus::Completed) << r.reason;
  const int e = column(r, "energy.total"), x = column(r, "mid.x");
  const double e0 = r.rows.front()[e];
  double worstRise = 0.0, lowestSoFar = e0;
  for (const auto& row : r.rows) {
    worstRise = std::max(worstRise, (row[e] - lowestSoFar) / e0);
    lowestSoFar = std::min(lowestSoFar, row[e]);
  }
  const double lost = (e0 - r.rows.back()[e]) / e0;
  std::printf(
      "damping and friction: sheet slid %.3f m; energy lost %.1f %%; largest rise over the "
      "lowest so far %.2e of E0\n",
      r.rows.back()[x] - r.rows.front()[x], 100 * lost, worstRise);
  EXPECT_LT(worstRise, 1e-3);
  EXPECT_GT(lost, 0.05);
}

// CT12: the stable-step bound with contact (EX5 plus CT12's row sums) bounds the highest
// frequency of the assembled stiffness (membranes and contact) over the lumped mass, the sheet
// resting in contact.
TEST(ContactTerm, StiffnessBoundCoversTheContactFrequencies) {
  const CaseSpec c = readCase(writeCase(
      "contact_bound",
      dropScene("damping_ratio = 0.0\nfriction = 0.0\nstiffness_scale = 0.05", "bossak")));
  const Model& m = c.model;
  StructuralSystem sys(m, c.solver.search);
  const long n = 3 * m.numNodes();
  Eigen::VectorXd x(n), zero = Eigen::VectorXd::Zero(n), ones = Eigen::VectorXd::Ones(n);
  for (int k = 0; k < m.numNodes(); ++k) x.segment<3>(3 * k) = m.X[k];
  for (int k : m.nodeSets.at("sheet")) x[3 * k + 2] = 0.004 + 0.003 * std::sin(3.7 * k);
  sys.updateState(x);
  sys.assemble(EvalPoint::state(x, zero, zero, 0.0), true);
  const Eigen::MatrixXd K = Eigen::MatrixXd(sys.matrix());
  sys.assemble(EvalPoint::inertiaOf(x, zero, ones, 0.0, false), false);
  const Eigen::VectorXd withMass = sys.residual();
  sys.assemble(EvalPoint::inertiaOf(x, zero, zero, 0.0, false), false);
  const Eigen::VectorXd mass = withMass - sys.residual();  // lumped: M 1
  const Eigen::VectorXd s = mass.cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd A = s.asDiagonal() * (0.5 * (K + K.transpose())) * s.asDiagonal();
  const double omega2 = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A).eigenvalues().maxCoeff();
  // The bound of every term but contact, then with it (CentralDifference's, EX5 and CT12).
  const std::vector<char> free(m.numNodes(), 1);
  std::vector<double> without(m.numNodes(), 0.0);
  for (const auto& t : sys.terms())
    if (std::string(t->name()) != "contact") t->addStiffnessBound(x, 0.0, free, without);
  const double withoutContact = *std::max_element(without.begin(), without.end());
  const auto S = sys.stiffnessBound(x, 0.0);

  double bound = 0.0;
  for (int k : m.nodeSets.at("sheet")) bound = std::max(bound, S[k] / mass[sys.dofs().eq(k, 2)]);
  std::printf(
      "highest omega^2 %.4g; bound %.4g (ratio %.2f); the contact raised the largest S by "
      "%.1f %%\n",
      omega2, bound, bound / omega2,
      100 * (*std::max_element(S.begin(), S.end()) / withoutContact - 1));
  EXPECT_GE(bound, omega2);
}

// Restart bit for bit with contact active: a run with checkpoints, continued from one taken while
// the sheet is on the floor, writes the same probes as the run in one go (explicit; then
// implicit, whose sparsity pattern follows the candidate list).
TEST(ContactTerm, RestartIsBitForBit) {
  for (const std::string integrator : {"central_difference", "bossak"}) {
    const std::string text =
        dropScene("friction = 0.3", integrator, integrator == "bossak" ? 5e-4 : 1e-3, 0.12);
    const auto whole = chute::testing::freshTempDir("chute_test_contact_", integrator + "_whole");
    const auto split = chute::testing::freshTempDir("chute_test_contact_", integrator + "_split");
    const auto a = run("contact_restart", text, RunOptions::writingTo(whole.string()));
    RunOptions withCheckpoints = RunOptions::writingTo(split.string());
    withCheckpoints.checkpointEvery = integrator == "bossak" ? 150 : 700;  // mid-bounce
    const auto b = run("contact_restart", text, withCheckpoints);
    ASSERT_GT(b.checkpoints, 0);
    RunOptions restart = RunOptions::writingTo(split.string());
    restart.restartFile = (split / "checkpoint.cbor").string();
    const auto c = run("contact_restart", text, restart);
    ASSERT_EQ(c.status, RunStatus::Completed);
    const std::string pa = readFile(whole / "probes.csv"), pc = readFile(split / "probes.csv");
    std::printf(
        "%s restart with contact: %ld steps, %ld checkpoints, %ld pairs in contact at most; "
        "probes.csv %zu bytes, %s\n",
        integrator.c_str(), a.steps, b.checkpoints, a.contact->largestActive, pa.size(),
        pa == pc ? "identical" : "DIFFERENT");
    EXPECT_GT(a.contact->largestActive, 100);
    EXPECT_EQ(pa, pc);
  }
}

// No interpenetration (the independent count of tests/support/Intersections.hpp) in any of the
// checked states of the crumpling square (cases/crumple_square.toml, its first 0.25 s), against
// many without contact.
TEST(ContactTerm, CrumplingSquareNeverInterpenetrates) {
  const std::string file = std::string(CHUTE_SOURCE_DIR) + "/cases/crumple_square.toml";
  for (const bool contact : {true, false}) {
    const CaseSpec spec = readCase(
        file, {"solver.t_end=0.25", contact ? "contact.enabled=true" : "contact.enabled=false"});
    const auto tris = chute::testing::modelTriangles(spec.model);
    long frames = 0, worst = 0, total = 0;
    const auto r =
        chute::testing::visitRun(spec, 250, [&](const StructuralState& s, const StructuralSystem&) {
          const auto n = chute::testing::countIntersections(s.x, tris, {});
          ++frames;
          worst = std::max(worst, n.trianglePairs);
          total += n.trianglePairs;
        });
    ASSERT_TRUE(r.reached);
    std::printf(
        "crumpling square %s contact: %ld states checked over %ld steps; intersecting "
        "triangle pairs: at most %ld in one state, %ld in all\n",
        contact ? "with" : "without", frames, r.steps, worst, total);
    if (contact)
      EXPECT_EQ(total, 0);
    else
      EXPECT_GT(worst, 10);
  }
}
