// Canopy mechanics through the whole stack: Hencky's membrane under refinement, the assembled
// Jacobian of membranes + pressure + drag against finite differences, energy conservation of a
// free-flying patch, momentum conservation of a pressurised closed surface.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "app/RunCase.hpp"
#include "case/CaseSpec.hpp"
#include "solver/StructuralSystem.hpp"
#include "support/AssembledJacobian.hpp"
#include "support/FiniteDifference.hpp"
#include "support/Scenes.hpp"

using namespace chute;
using chute::testing::writeCase;

TEST(Hencky, CentreDeflectionConvergesUnderRefinement) {
  std::vector<int> rings = {4, 8, 16};
  std::vector<double> err;
  for (int n : rings) {
    const auto spec =
        readCase(CHUTE_SOURCE_DIR "/cases/hencky.toml", {"membranes.0.rings=" + std::to_string(n)});
    const auto r = runCase(spec, RunOptions{});
    ASSERT_EQ(r.status, RunStatus::Completed) << r.reason;
    err.push_back(r.reference->relative());
    std::printf(
        "Hencky, %2d rings (%5d dofs): centre deflection error %.4f %% of w0 = %.5f, "
        "%.2f Newton iterations per load step\n",
        n, r.equations, 100 * err.back(), r.reference->motionSize, r.newtonPerStep());
  }
  for (size_t k = 1; k < err.size(); ++k)
    std::printf("  observed order %d -> %d rings: %.2f\n", rings[k - 1], rings[k],
                std::log(err[k - 1] / err[k]) / std::log(2.0));
  EXPECT_LT(err[1], err[0]);
  EXPECT_LT(err[2], err[1]);
  EXPECT_LE(err.back(), 1e-2);
}

TEST(CanopySystem, AssembledJacobianWithPressureAndDragMatchesFiniteDifferences) {
  const auto spec = readCase(writeCase("canopy_fd", R"(
[nodes]
a = [0.0, 0.0, 0.0]
b = [0.0, 0.0, -1.0]
[materials.fabric]
kind = "membrane"
E = 4.32e6
nu = 0.3
thickness = 5e-4
density = 1.6
[materials.line]
E = 1e6
area = 1e-4
density = 2.0
[[membranes]]
name = "patch"
material = "fabric"
mesh = "rectangle"
corner = [-0.5, -0.5, 0.0]
size = [1.0, 1.0, 0.0]
divisions = [2, 2]
element = "quad"
[[membranes]]
name = "tris"
material = "fabric"
mesh = "rectangle"
corner = [0.7, -0.5, 0.0]
size = [1.0, 1.0, 0.0]
divisions = [2, 1]
element = "triangle"
[[cables]]
name = "line"
material = "line"
path = ["a", "b"]
elements_per_segment = 2
[loads]
gravity = [0.0, 0.0, -32.2]
[[loads.pressure]]
membranes = "patch"
pressure = 0.7
[[loads.pressure]]
membranes = "tris"
pressure = -0.4
element_factors = [1.0, 0.5, 2.0, -1.0]
[[loads.drag]]
edge = "patch.xmax"
diameter = 1.0
cd = 1.0
air_density = 0.0023769
wind = [0.0, 2.0, 15.0]
[[loads.drag]]
set = "line"
diameter = 0.03
cd = 1.2
air_density = 0.0023769
wind = [3.0, -1.0, 20.0]
[solver]
dt = 1e-3
t_end = 1e-3
)"));
  StructuralSystem sys(spec.model, spec.solver.search);
  const double err = chute::testing::assembledJacobianError(
      sys, chute::testing::movingState(spec.model, 1.02, 0.05, 5.0, 1.0));
  std::printf(
      "membranes, pressure (uniform, per element), drag (lines, membrane edge), cables: "
      "assembled J vs FD relative error %.2e "
      "(%d equations, symmetric=%d)\n",
      err, sys.numEquations(), sys.symmetric());
  EXPECT_LE(err, 1e-6);
  EXPECT_FALSE(sys.symmetric());
}

TEST(CanopySystem, GatheredStartOverAFlatReferenceIsStressFree) {
  // The fabric is gathered to 60 % of its flat cutting pattern in its plane (a packed start):
  // with wrinkling the internal force is exactly zero; without it the fabric would push back.
  const std::string text = R"(
[materials.fabric]
kind = "membrane"
E = 4.32e6
nu = 0.3
thickness = 5e-4
[[membranes]]
name = "canopy"
material = "fabric"
mesh = "disk"
radius = 7.0
rings = 6
)";
  for (bool wrinkling : {true, false}) {
    auto spec = readCase(writeCase("gathered", text + (wrinkling ? "" : "wrinkling = false\n") +
                                                   "[solver]\ntype = \"static\"\n"));
    auto& m = spec.model;
    for (int i = 0; i < m.numNodes(); ++i) {
      m.u0[i] = -0.4 * m.X[i];                 // gathered towards the centre
      m.u0[i].z() += 0.3 * std::sin(3.0 * i);  // and crumpled out of plane, much less than gathered
    }
    StructuralSystem sys(m, spec.solver.search);
    Eigen::VectorXd x(3 * m.numNodes()), zero = Eigen::VectorXd::Zero(3 * m.numNodes());
    for (int i = 0; i < m.numNodes(); ++i) x.segment<3>(3 * i) = m.X[i] + m.u0[i];
    sys.assemble(EvalPoint::statics(x, zero, 0.0, 1.0), false);
    const double f = sys.residual().norm();
    std::printf(
        "gathered canopy (60 %% of the flat pattern), wrinkling %s: |internal force| %.3e\n",
        wrinkling ? "on" : "off", f);
    if (wrinkling)
      EXPECT_EQ(f, 0.0);
    else
      EXPECT_GT(f, 1.0);
  }
}

TEST(CanopySystem, FreeFlyingPatchConservesEnergyWithoutNumericalDamping) {
  // A prestretched free patch released: it vibrates in its plane. rho_inf = 1, no loads.
  // Newmark's trapezoidal rule conserves energy exactly only for linear systems; for this
  // geometrically nonlinear one the drift over 1000 steps falls with the step, and at a step
  // resolving the highest mode (omega_max dt ~ 0.04) it is below 1e-6.
  const std::string file = writeCase("free_patch", R"(
[materials.fabric]
kind = "membrane"
E = 4.32e6
nu = 0.3
thickness = 5e-4
density = 1.6
[[membranes]]
name = "patch"
material = "fabric"
mesh = "rectangle"
size = [1.0, 0.6, 0.0]
divisions = [4, 3]
element = "quad"
wrinkling = false
prestrain = 1e-3
[solver]
dt = 2e-5
t_end = 2e-2
rho_inf = 1.0
[output]
every = 10
[[output.probes]]
name = "energy"
kind = "energy"
)");
  double drift = 0.0;
  for (double dt : {2e-5, 1e-5, 5e-6, 2.5e-6}) {
    auto num = [](double v) {
      std::ostringstream o;
      o << std::setprecision(17) << v;
      return o.str();
    };
    const auto spec = readCase(file, {"solver.dt=" + num(dt), "solver.t_end=" + num(1000 * dt)});
    const auto r = runCase(spec, RunOptions{});
    ASSERT_EQ(r.status, RunStatus::Completed);
    EXPECT_EQ(r.steps, 1000);
    const double scale = std::max(r.kineticMax, std::abs(r.energyInitial));
    drift = r.energyMaxDrift / scale;
    std::printf("free patch, 1000 steps of %.1e s at rho_inf = 1: relative energy drift %.2e\n", dt,
                drift);
  }
  EXPECT_LE(drift, 1e-6);
}

TEST(CanopySystem, PressureOnAClosedSurfaceConservesMomentum) {
  // An irregular tetrahedron of fabric inflated from rest: the pressure forces sum to zero, so
  // the total momentum stays zero while the surface moves.
  const auto spec = readCase(writeCase("closed_tet", R"(
[nodes]
a = [0.0, 0.0, 0.0]
b = [1.0, 0.1, 0.0]
c = [0.2, 0.8, 0.1]
d = [0.3, 0.2, 0.9]
[materials.fabric]
kind = "membrane"
E = 1e5
nu = 0.3
thickness = 1e-3
density = 10.0
[[membranes]]
name = "tet"
material = "fabric"
mesh = "elements"
triangles = [["a", "c", "b"], ["a", "b", "d"], ["b", "c", "d"], ["c", "a", "d"]]
[loads]
[[loads.pressure]]
membranes = "tet"
pressure = 50.0
[solver]
dt = 1e-3
t_end = 0.2
[output]
every = 20
[[output.probes]]
name = "a"
kind = "node_velocity"
[[output.probes]]
name = "b"
kind = "node_velocity"
[[output.probes]]
name = "c"
kind = "node_velocity"
[[output.probes]]
name = "d"
kind = "node_velocity"
)"));
  const auto r = runCase(spec, RunOptions{});
  ASSERT_EQ(r.status, RunStatus::Completed) << r.reason;
  // Lumped node masses: a third of each adjacent face's mass.
  const auto& m = spec.model;
  std::vector<double> mass(m.numNodes(), 0.0);
  for (const auto& e : m.membranes) {
    const double area =
        0.5 * (m.X[e.nodes[1]] - m.X[e.nodes[0]]).cross(m.X[e.nodes[2]] - m.X[e.nodes[0]]).norm();
    for (int i = 0; i < 3; ++i) mass[e.nodes[i]] += 10.0 * 1e-3 * area / 3.0;
  }
  double worst = 0.0, speed = 0.0;
  for (const auto& row : r.rows) {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (int i = 0; i < 4; ++i) {
      const Eigen::Vector3d vi(row[3 * i], row[3 * i + 1], row[3 * i + 2]);
      p += mass[i] * vi;
      speed = std::max(speed, mass[i] * vi.norm());
    }
    worst = std::max(worst, p.norm());
  }
  std::printf(
      "closed surface under pressure: max |total momentum| %.2e against node momenta up "
      "to %.2e\n",
      worst, speed);
  EXPECT_GT(speed, 0.0);
  EXPECT_LE(worst, 1e-10 * speed);
}

TEST(Airbag, InflatesToRestWithWrinklingAndFewNewtonIterations) {
  // The shipped airbag (16 x 16 quads) and a coarser mesh: at rest at the end, Newton <= 8
  // iterations in every step with wrinkling on, the centre displacement settled under refinement.
  double w[2];
  int k = 0;
  for (const char* div : {"8", "16"}) {
    const std::string text = [&] {
      std::ifstream in(CHUTE_SOURCE_DIR "/cases/airbag.toml");
      std::stringstream ss;
      ss << in.rdbuf();
      std::string s = ss.str();
      const std::string from = "divisions = [16, 16]";
      s.replace(s.find(from), from.size(), std::string("divisions = [") + div + ", " + div + "]");
      return s;
    }();
    const auto spec = readCase(writeCase(std::string("airbag_") + div, text));
    const auto r = runCase(spec, RunOptions{});
    ASSERT_EQ(r.status, RunStatus::Completed) << r.reason;
    const auto& last = r.rows.back();
    // columns: energy (4), centre (3), fabric (3), centre_stress (2)
    const double kinetic = last[0], wz = last[6], taut = last[7], wrinkled = last[8];
    w[k++] = wz;
    std::printf(
        "airbag %s x %s quads: centre displacement %.5f m, centre S1 %.3f MPa, fabric "
        "taut %.0f %% wrinkled %.0f %% slack %.0f %%, kinetic energy at the end %.1e, "
        "Newton max %d avg %.2f\n",
        div, div, wz, last[10] / 1e6, 100 * taut, 100 * wrinkled, 100 * last[9], kinetic,
        r.maxNewtonInStep, r.newtonPerStep());
    EXPECT_LE(r.maxNewtonInStep, 8);
    EXPECT_LE(kinetic, 1e-6);
    EXPECT_GT(wrinkled, 0.5);  // wrinkles everywhere but the centre
  }
  std::printf("  centre displacement change 8 -> 16: %.3f %%\n", 100 * (w[1] - w[0]) / w[1]);
  EXPECT_LE(std::abs(w[1] - w[0]) / w[1], 5e-3);
}
