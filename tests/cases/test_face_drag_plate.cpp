// Face drag through the whole stack: a flat membrane plate falling flat in still air reaches the
// analytic terminal velocity v_t = sqrt(2 m g / (rho_air Cd A)) (quads and triangles), and the
// assembled Jacobian with face drag matches finite differences of the residual.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "app/RunCase.hpp"
#include "case/CaseSpec.hpp"
#include "solver/StructuralSystem.hpp"
#include "support/AssembledJacobian.hpp"
#include "support/FiniteDifference.hpp"
#include "support/Scenes.hpp"

using namespace chute;
using chute::testing::writeCase;

namespace {

std::string plateCase(const std::string& element) {
  return R"(
[materials.fabric]
kind = "membrane"
E = 4.32e6
nu = 0.3
thickness = 4.0e-4
density = 0.6
[[membranes]]
name = "plate"
material = "fabric"
mesh = "rectangle"
size = [2.0, 2.0, 0.0]
divisions = [3, 3]
element = ")" +
         element + R"("
[loads]
gravity = [0.0, 0.0, -32.2]
[[loads.face_drag]]
membranes = "plate"
cd = 1.2
air_density = 0.0023769
[solver]
dt = 2e-3
t_end = 1.0
[output]
interval = 0.05
[[output.probes]]
name = "energy"
kind = "energy"
)";
}
}  // namespace

TEST(FaceDragPlate, FallingPlateReachesAnalyticTerminalVelocity) {
  const double rhoAir = 0.0023769, cd = 1.2, g = 32.2, area = 4.0, mass = 0.6 * 4.0e-4 * area;
  const double vt = std::sqrt(2 * mass * g / (rhoAir * cd * area));
  for (const char* element : {"quad", "triangle"}) {
    const auto spec = readCase(writeCase(std::string("plate_") + element, plateCase(element)));
    const auto r = runCase(spec, RunOptions{});
    ASSERT_EQ(r.status, RunStatus::Completed) << r.reason;
    int ke = -1;
    for (size_t c = 0; c < r.columns.size(); ++c)
      if (r.columns[c] == "energy.kinetic") ke = static_cast<int>(c);
    ASSERT_GE(ke, 0);
    // The plate moves as a rigid body (uniform lumped mass and drag per area): |v| from 1/2 m v^2.
    const double v = std::sqrt(2 * r.rows.back()[ke] / mass);
    const double err = std::abs(v - vt) / vt;
    std::printf(
        "plate (%s): speed at t = %.2f s %.8f ft/s, analytic terminal %.8f ft/s "
        "(time constant v_t/g = %.4f s): relative error %.2e, Newton/step %.2f\n",
        element, r.finalTime, v, vt, vt / g, err, r.newtonPerStep());
    EXPECT_LE(err, 1e-6);
  }
}

TEST(FaceDragPlate, AssembledJacobianWithFaceDragMatchesFiniteDifferences) {
  auto text = plateCase("quad");
  text.replace(text.find("air_density = 0.0023769\n"), 24,
               "air_density = 0.0023769\nwind = [1.0, -2.0, 9.0]\nsubtract_steady = true\n");
  const auto spec = readCase(writeCase("plate_fd", text));
  StructuralSystem sys(spec.model, spec.solver.search);
  const double err = chute::testing::assembledJacobianError(
      sys, chute::testing::movingState(spec.model, 1.01, 0.1, 5.0, 1.0));
  std::printf(
      "membranes + gravity + face drag (steady subtracted): assembled J vs FD relative "
      "error %.2e (%d equations, symmetric=%d)\n",
      err, sys.numEquations(), sys.symmetric());
  EXPECT_LE(err, 1e-6);
  EXPECT_FALSE(sys.symmetric());
}
