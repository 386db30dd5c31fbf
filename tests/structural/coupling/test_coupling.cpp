// The coupling interface for an external flow solver: its kernels and load terms against finite
// differences, implicit coupling against the monolithic solution of the same flow law, window
// checkpoints bit for bit (with a slider handed over inside the window), Aitken against constant
// under-relaxation, and the case-file pressure path unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>

#include "app/RunCase.hpp"
#include "case/CaseSpec.hpp"
#include "coupling/CouplingDriver.hpp"
#include "coupling/CouplingInterface.hpp"
#include "coupling/QuasiSteadyFlow.hpp"
#include "kernels/PressureKernel.hpp"
#include "solver/GeneralizedAlpha.hpp"
#include "support/AssembledJacobian.hpp"
#include "support/FiniteDifference.hpp"
#include "support/Scenes.hpp"
#include "terms/sliding/SlidingGroupTerm.hpp"

using namespace chute;
using namespace chute::coupling;
using chute::testing::writeCase;

namespace {
template <int N>
std::array<Vec3, N> unstack(const Eigen::VectorXd& v) {
  std::array<Vec3, N> out;
  for (int i = 0; i < N; ++i) out[i] = v.segment<3>(3 * i);
  return out;
}
template <int N>
Eigen::VectorXd skewedFace() {  // a non-planar, stretched face
  Eigen::VectorXd y(3 * N);
  const double q[12] = {0.0, 0.0, 0.1, 1.1, -0.1, 0.0, 1.2, 0.9, 0.2, -0.1, 1.0, -0.15};
  const double t[9] = {0.0, 0.0, 0.1, 1.1, -0.1, 0.0, 0.3, 0.9, 0.2};
  for (int k = 0; k < 3 * N; ++k) y[k] = N == 4 ? q[k] : t[k];
  return y;
}
// The demo canopy, small: 3 rings, 10 windows.
CaseSpec smallCanopy(std::vector<std::string> extra = {}) {
  std::vector<std::string> o = {"membranes.0.rings=3", "solver.t_end=0.005", "solver.dt=5e-4"};
  o.insert(o.end(), extra.begin(), extra.end());
  return readCase(CHUTE_SOURCE_DIR "/cases/canopy_coupled.toml", o);
}
QuasiSteadyFlowLaw demoLaw() {
  QuasiSteadyFlowLaw law;
  law.stagnationPressure = 60.0, law.rampTime = 0.002, law.airDensity = 1.2;
  law.normalDragCoefficient = 1.0, law.addedMassLength = 0.03;
  return law;
}
}  // namespace

TEST(CouplingKernels, NodalPressureTangentMatchesFDAndUniformValuesGiveTheFacePressure) {
  double worstTangent = 0.0, worstUniform = 0.0, worstArea = 0.0;
  auto check = [&](auto tag) {
    constexpr int N = decltype(tag)::value;
    const Eigen::VectorXd y0 = skewedFace<N>();
    Eigen::Matrix<double, N, 1> pv;
    for (int i = 0; i < N; ++i) pv[i] = 2.0 + 1.5 * i;
    const auto l = kernels::pressureLoadNodal<N>(unstack<N>(y0), pv, true);
    const Eigen::MatrixXd fd = chute::testing::fdJacobian(
        [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
          return kernels::pressureLoadNodal<N>(unstack<N>(y), pv, false).force;
        },
        y0, 1e-6);
    worstTangent = std::max(worstTangent, chute::testing::relativeError(l.dForce, fd));
    // Uniform nodal values: the face-pressure kernel's force (exact integration of both).
    const auto u = kernels::pressureLoadNodal<N>(unstack<N>(y0),
                                                 Eigen::Matrix<double, N, 1>::Constant(3.0), false);
    const auto s = kernels::pressureLoad<N>(unstack<N>(y0), 3.0, false);
    worstUniform = std::max(worstUniform, chute::testing::relativeError(u.force, s.force));
    // The area vector is the total of a unit pressure's force; its Jacobian against FD.
    Vec3 total = Vec3::Zero();
    const auto unit = kernels::pressureLoad<N>(unstack<N>(y0), 1.0, false);
    for (int i = 0; i < N; ++i) total += unit.force.template segment<3>(3 * i);
    const Vec3 A = kernels::areaVector<N>(unstack<N>(y0));
    worstArea = std::max(worstArea, (A - total).norm() / A.norm());
    const Eigen::MatrixXd dA = kernels::areaVectorJacobian<N>(unstack<N>(y0));
    const Eigen::MatrixXd dAfd = chute::testing::fdJacobian(
        [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
          return kernels::areaVector<N>(unstack<N>(y));
        },
        y0, 1e-6);
    worstTangent = std::max(worstTangent, chute::testing::relativeError(dA, dAfd));
  };
  check(std::integral_constant<int, 3>{});
  check(std::integral_constant<int, 4>{});
  std::printf(
      "nodal pressure and area-vector tangents vs FD: %.2e; uniform nodal vs face pressure: "
      "%.2e; area vector vs total unit-pressure force: %.2e\n",
      worstTangent, worstUniform, worstArea);
  EXPECT_LE(worstTangent, 1e-6);
  EXPECT_LE(worstUniform, 1e-14);
  EXPECT_LE(worstArea, 1e-14);
}

TEST(CouplingTerms, AssembledJacobiansOfExternalLoadsAndTheFlowLawMatchFD) {
  // Quads and triangles; every load kind the interface reads, plus the monolithic flow term.
  const auto spec = readCase(writeCase("coupling_fd", R"(
[materials.fabric]
kind = "membrane"
E = 1e6
nu = 0.3
thickness = 1e-4
density = 500.0
[[membranes]]
name = "quads"
material = "fabric"
mesh = "rectangle"
size = [1.0, 1.0, 0.0]
divisions = [2, 2]
element = "quad"
[[membranes]]
name = "tris"
material = "fabric"
mesh = "rectangle"
corner = [1.5, 0.0, 0.0]
size = [1.0, 1.0, 0.0]
divisions = [2, 1]
element = "triangle"
[solver]
dt = 1e-3
t_end = 1e-3
)"));
  const WetSurface w = WetSurface::fromModel(spec.model);
  auto ext = std::make_unique<ExternalLoadTerm>(w);
  Eigen::VectorXd pf(w.numFaces()), pv(w.numVertices()), fv(3 * w.numVertices());
  for (int k = 0; k < pf.size(); ++k) pf[k] = 3.0 + std::sin(1.0 + k);
  for (int k = 0; k < pv.size(); ++k) pv[k] = 2.0 * std::cos(0.3 * k);
  for (int k = 0; k < fv.size(); ++k) fv[k] = std::sin(0.7 * k);
  ext->setFacePressures(pf);
  ext->setVertexPressures(pv);
  ext->setVertexForces(fv);
  std::vector<std::unique_ptr<Term>> extra;
  extra.push_back(std::move(ext));
  QuasiSteadyFlowLaw law = demoLaw();
  law.wind = Vec3(0.5, -0.2, 1.0);
  extra.push_back(std::make_unique<QuasiSteadyPressureTerm>(w, law));
  StructuralSystem sys(spec.model, spec.solver.search, std::move(extra));
  const double err = chute::testing::assembledJacobianError(
      sys, chute::testing::movingState(spec.model, 1.02, 0.05, 3.0, 40.0));
  std::printf(
      "external face + vertex pressures, vertex forces, quasi-steady flow term (x, v, a): "
      "assembled J vs FD %.2e (%d equations)\n",
      err, sys.numEquations());
  EXPECT_LE(err, 1e-6);
}

TEST(CouplingTerms, FacePressuresEqualToTheCaseFileGiveTheSameResidualBitForBit) {
  // The case's pressure (per element factors) through PressureTerm, and the same values through
  // the coupling's ExternalLoadTerm: identical residuals and Jacobians.
  const std::string text = R"(
[materials.fabric]
kind = "membrane"
E = 1e6
nu = 0.3
thickness = 1e-4
[[membranes]]
name = "tris"
material = "fabric"
mesh = "rectangle"
size = [1.0, 1.0, 0.0]
divisions = [2, 1]
element = "triangle"
[[loads.pressure]]
membranes = "tris"
pressure = 2.5
element_factors = [1.0, 0.5, 2.0, -1.0]
[solver]
dt = 1e-3
t_end = 1e-3
)";
  const auto spec = readCase(writeCase("coupling_same", text));
  StructuralSystem caseSys(spec.model, spec.solver.search);
  Model bare = spec.model;
  bare.pressures.clear();
  const WetSurface w = WetSurface::fromModel(bare);
  auto ext = std::make_unique<ExternalLoadTerm>(w);
  ext->setFacePressures(Eigen::Vector4d(2.5, 1.25, 5.0, -2.5));
  std::vector<std::unique_ptr<Term>> extra;
  extra.push_back(std::move(ext));
  StructuralSystem coupledSys(bare, spec.solver.search, std::move(extra));
  const int n = 3 * bare.numNodes();
  Eigen::VectorXd x(n), zero = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < bare.numNodes(); ++i) x.segment<3>(3 * i) = bare.X[i];
  for (int k = 2; k < n; k += 3) x[k] = 0.1 * std::sin(2.0 * k);
  caseSys.assemble(EvalPoint::state(x, zero, zero, 0.0), true);
  coupledSys.assemble(EvalPoint::state(x, zero, zero, 0.0), true);
  const double dr = (caseSys.residual() - coupledSys.residual()).cwiseAbs().maxCoeff();
  const double dJ = (Eigen::MatrixXd(caseSys.matrix()) - Eigen::MatrixXd(coupledSys.matrix()))
                        .cwiseAbs()
                        .maxCoeff();
  std::printf(
      "case-file pressure vs the same face pressures supplied by coupling: max |dR| %.1e, "
      "max |dJ| %.1e\n",
      dr, dJ);
  EXPECT_EQ(dr, 0.0);
  EXPECT_EQ(dJ, 0.0);
}

namespace {
// The monolithic reference: the flow law as a structural term, stepped with the same dt.
Eigen::VectorXd monolithic(const CaseSpec& specIn, const QuasiSteadyFlowLaw& law, int steps,
                           double dt, long* newton) {
  CaseSpec spec = specIn;
  spec.model.pressures.clear();  // as the coupling interface does on the wet surface
  const WetSurface w = WetSurface::fromModel(spec.model);
  std::vector<std::unique_ptr<Term>> extra;
  extra.push_back(std::make_unique<QuasiSteadyPressureTerm>(w, law));
  StructuralSystem sys(spec.model, spec.solver.search, std::move(extra));
  NewtonSettings ns;
  ns.tolDisplacement = spec.solver.tolDisplacement;
  ns.maxIterations = 40;
  GeneralizedAlpha ga(sys, spec.solver.rhoInf, AlphaScheme::Bossak, ns, dt, 0.0);
  StructuralState s = sys.initialState();
  ga.computeAcceleration(s);
  sys.commit(CommitPoint{s.x, s.t, 0.0, s.t});
  for (int k = 0; k < steps; ++k) {
    const auto rep = ga.tryStep(s, dt);
    EXPECT_TRUE(rep.converged) << rep.failure;
    *newton += rep.iterations;
  }
  Eigen::VectorXd out(3 * s.x.size());
  out << s.x, s.v, s.a;
  return out;
}
}  // namespace

TEST(CoupledRun, ImplicitCouplingConvergesToTheMonolithicSolution) {
  // rho_inf = 1 (alpha_m = 0): the monolithic term's acceleration is the end-of-step one, the
  // one the flow participant reads. Window = step. Tight Newton and coupling tolerances.
  const auto spec = smallCanopy({"solver.rho_inf=1.0", "solver.newton_tolerance=1e-14"});
  const QuasiSteadyFlowLaw law = demoLaw();
  const int windows = 10;
  long newton = 0;
  const Eigen::VectorXd ref = monolithic(spec, law, windows, spec.solver.dt, &newton);
  CouplingInterface structure(spec);
  const QuasiSteadyFlow flow(structure.surface(), law);
  CouplingSettings cs;
  cs.tolerance = 1e-13;
  cs.maxIterations = 200;
  const auto rep = runCoupled(
      structure, [&](const InterfaceData& d) { return flow.facePressures(d); }, cs);
  ASSERT_TRUE(rep.converged) << rep.failure;
  ASSERT_EQ(static_cast<int>(rep.windows.size()), windows);
  const auto& s = structure.state();
  const int n = static_cast<int>(s.x.size());
  Eigen::VectorXd X(n);
  for (int i = 0; i < n / 3; ++i) X.segment<3>(3 * i) = spec.model.X[i];
  const double dx = (s.x - ref.head(n)).cwiseAbs().maxCoeff();
  const double ux = (ref.head(n) - X).cwiseAbs().maxCoeff();
  const double dv = (s.v - ref.segment(n, n)).cwiseAbs().maxCoeff();
  const double uv = ref.segment(n, n).cwiseAbs().maxCoeff();
  std::printf(
      "implicit (Aitken, tol 1e-13) vs monolithic after %d windows: max |dx| %.2e of max "
      "displacement %.4e (relative %.2e); max |dv| %.2e of %.4e (relative %.2e); %.1f "
      "sub-iterations per window; monolithic %.1f Newton iterations per step\n",
      windows, dx, ux, dx / ux, dv, uv, dv / uv, rep.iterationsPerWindow(),
      double(newton) / windows);
  EXPECT_LE(dx / ux, 1e-8);
  EXPECT_LE(dv / uv, 1e-8);
}

TEST(CoupledRun, AitkenNeedsFewerSubIterationsThanConstantRelaxation) {
  const auto spec = smallCanopy();
  const QuasiSteadyFlowLaw law = demoLaw();
  long total[2] = {0, 0};
  double last[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    CouplingInterface structure(spec);
    const QuasiSteadyFlow flow(structure.surface(), law);
    CouplingSettings cs;
    cs.relaxation = k == 0 ? Relaxation::Constant : Relaxation::Aitken;
    cs.omega = 0.5;
    cs.tolerance = 1e-10;
    const auto rep = runCoupled(
        structure, [&](const InterfaceData& d) { return flow.facePressures(d); }, cs);
    ASSERT_TRUE(rep.converged) << rep.failure;
    total[k] = rep.iterations();
    last[k] = structure.state().x.norm();
    std::printf(
        "%s relaxation (omega %.2f): %ld sub-iterations over %zu windows (%.2f per "
        "window), last window's residual %.2e\n",
        k == 0 ? "constant" : "Aitken", cs.omega, total[k], rep.windows.size(),
        rep.iterationsPerWindow(), rep.windows.back().residual);
  }
  EXPECT_LT(total[1], total[0]);
  EXPECT_NEAR(last[0], last[1], 1e-8 * last[0]);  // the same solution
}

TEST(CoupledRun, ExplicitCouplingIsStaggeredAndFirstOrderCloseToImplicit) {
  const auto spec = smallCanopy();
  const QuasiSteadyFlowLaw law = demoLaw();
  Eigen::VectorXd x[2];
  for (int k = 0; k < 2; ++k) {
    CouplingInterface structure(spec);
    const QuasiSteadyFlow flow(structure.surface(), law);
    CouplingSettings cs;
    cs.scheme = k == 0 ? CouplingScheme::Explicit : CouplingScheme::Implicit;
    const auto rep = runCoupled(
        structure, [&](const InterfaceData& d) { return flow.facePressures(d); }, cs);
    ASSERT_TRUE(rep.converged) << rep.failure;
    if (k == 0) {
      EXPECT_EQ(rep.iterations(), static_cast<long>(rep.windows.size()));
    }
    x[k] = structure.state().x;
  }
  const double d = (x[0] - x[1]).cwiseAbs().maxCoeff();
  std::printf("explicit vs implicit coupling after 10 windows: max |dx| %.3e\n", d);
  EXPECT_GT(d, 0.0);
  EXPECT_LT(d, 1e-2);
}

// A small pressurised membrane beside bead_5's rope: the wet surface of the window tests.
const std::string kFlap = R"(
[materials.fabric]
kind = "membrane"
E = 1e6
nu = 0.3
thickness = 1e-3
density = 100.0
[[membranes]]
name = "flap"
material = "fabric"
mesh = "rectangle"
corner = [0.0, 1.0, 0.0]
size = [1.0, 0.5, 0.0]
divisions = [2, 2]
element = "quad"
prestrain = 1e-4
[[boundary.constraints]]
set = "flap.xmin"
dofs = "xyz"
)";

TEST(WindowCheckpoint, RestoreReproducesAWindowBitForBitAcrossASliderHandOver) {
  // bead_5's bead on its sliding rope plus a small pressurised membrane: the window is repeated
  // after a different attempt, and the slider's hand-over inside the window is undone by
  // restoreCheckpoint and happens again identically.
  std::ifstream in(CHUTE_SOURCE_DIR "/cases/bead_5.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text += kFlap;
  const auto spec = readCase(writeCase("checkpoint_bead", text), {"solver.t_end=2.0"});
  CouplingInterface s(spec);
  const double window = 0.05;
  Eigen::VectorXd p1 = Eigen::VectorXd::Constant(s.numFaces(), 3.0);
  Eigen::VectorXd p2 = Eigen::VectorXd::Constant(s.numFaces(), -7.0);
  const auto& group = s.system().termList().slidingGroups().front()->state();
  int handoverWindows = 0, compared = 0;
  bool allEqual = true;
  while (s.time() < 1.0 && handoverWindows < 2) {
    s.saveCheckpoint();
    const int before = group.committedActiveElement(0);
    s.setFacePressures(p2);  // a first attempt with other loads
    s.advance(window);
    s.restoreCheckpoint();
    const bool reverted = group.committedActiveElement(0) == before;
    s.setFacePressures(p1);
    s.advance(window);
    const WindowCheckpoint a = s.snapshot();
    s.restoreCheckpoint();
    s.setFacePressures(p1);
    s.advance(window);
    const WindowCheckpoint b = s.snapshot();
    ++compared;
    // The whole snapshot: state, step control and every term's history, bit for bit.
    const bool equal = a.state.t == b.state.t && a.state.x == b.state.x && a.state.v == b.state.v &&
                       a.state.a == b.state.a && a.state.control.dt == b.state.control.dt &&
                       a.state.control.eventStep == b.state.control.eventStep &&
                       a.termNames == b.termNames && a.histories == b.histories && reverted;
    allEqual &= equal;
    if (group.committedActiveElement(0) != before) {
      ++handoverWindows;
      std::printf(
          "window ending t = %.3f: slider handed over %d -> %d inside it; repeated "
          "window identical: %s (attempt with other loads reverted: %s)\n",
          s.time(), before, group.committedActiveElement(0), equal ? "yes" : "NO",
          reverted ? "yes" : "NO");
    }
  }
  std::printf("%d windows repeated after restore, all bit for bit: %s; %d with a hand-over\n",
              compared, allEqual ? "yes" : "NO", handoverWindows);
  EXPECT_TRUE(allEqual);
  EXPECT_GE(handoverWindows, 1);
}

TEST(CouplingInterfaceApi, SizesGeometryErrorsAndDroppedCasePressure) {
  const auto spec = smallCanopy();
  CouplingInterface s(spec);
  EXPECT_TRUE(s.spec().model.pressures.empty());  // the flow owns the wet surface's pressure
  const Eigen::VectorXd A = s.faceAreas();
  const double total = A.sum(), disk = 3.14159265358979 * 1.0 * 1.0;
  std::printf(
      "wet surface: %d vertices, %d faces, area %.6f (polygon of the unit disk; pi = "
      "%.6f)\n",
      s.numVertices(), s.numFaces(), total, disk);
  EXPECT_LT(total, disk);
  EXPECT_GT(total, 0.9 * disk);
  EXPECT_NEAR(std::abs(s.faceNormals()[2]), 1.0, 1e-15);
  EXPECT_THROW(s.setFacePressures(Eigen::VectorXd::Zero(3)), std::invalid_argument);
  EXPECT_THROW(s.restoreCheckpoint(), NoCheckpointError);
  EXPECT_THROW(s.advance(-1.0), CouplingError);
  EXPECT_THROW(CouplingInterface(spec, {"nope"}), std::invalid_argument);
  const double taken = s.advance(1.5 * spec.solver.dt);  // sub-steps inside
  EXPECT_EQ(taken, 1.5 * spec.solver.dt);
  EXPECT_EQ(s.time(), 1.5 * spec.solver.dt);
  EXPECT_EQ(s.counters().steps, 2);
}

TEST(WindowCheckpoint, AWindowWithACutInsideIsRepeatedBitForBit) {
  // bead_5 with a line holding the bead up from above, cut at t = 0.2325, inside the window
  // [0.2, 0.25]: the coupling interface lands a step on the cut as `chute run` does
  // (TimeStepper), and the window repeated after restoreCheckpoint() is bit for bit.
  std::ifstream in(CHUTE_SOURCE_DIR "/cases/bead_5.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string holder = R"(
[materials.holder_line]
kind = "cable"
E = 1.0e8
area = 1.0e-4
density = 0.0
[[cables]]
name = "holder"
material = "holder_line"
path = ["hook", "bead"]
)";
  // [nodes] gets the hook above the bead; the cut is an event of the case.
  text.replace(text.find("[nodes]"), 7, "[nodes]\nhook = [0.5, 0.0, 0.5]");
  text += kFlap;
  const std::string fixed = "fixed = [\"left_anchor\", \"right_anchor\"";
  text.replace(text.find(fixed), fixed.size(), fixed + ", \"hook\"");
  const auto withCut = readCase(
      writeCase("cut_window", text + holder + "[[events]]\ncut = \"holder\"\nat = 0.2325\n"),
      {"solver.t_end=1.0"});
  const auto noCut = readCase(writeCase("nocut_window", text + holder), {"solver.t_end=1.0"});
  CouplingInterface s(withCut), ref(noCut);
  const double window = 0.05;
  for (int w = 0; w < 4; ++w) s.advance(window), ref.advance(window);  // to t = 0.2
  ASSERT_NEAR(s.time(), 0.2, 1e-12);
  EXPECT_TRUE(s.state().x == ref.state().x);  // nothing cut yet
  const long stepsBefore = s.counters().steps;
  s.saveCheckpoint();
  s.advance(window);
  const WindowCheckpoint a = s.snapshot();
  const long stepsInWindow = s.counters().steps - stepsBefore;
  s.restoreCheckpoint();
  s.advance(window);
  const WindowCheckpoint b = s.snapshot();
  ref.advance(window);
  const bool equal = a.state.t == b.state.t && a.state.x == b.state.x && a.state.v == b.state.v &&
                     a.state.a == b.state.a && a.histories == b.histories &&
                     a.state.control.dt == b.state.control.dt;
  const double moved = (a.state.x - ref.state().x).lpNorm<Eigen::Infinity>();
  std::printf(
      "window [0.2, 0.25] with a cut at 0.2325: %ld steps (dt 0.005: 10 without a stop), "
      "repeated bit for bit: %s; bead %.3e ft from the uncut run at its end\n",
      stepsInWindow, equal ? "yes" : "NO", moved);
  EXPECT_TRUE(equal);
  EXPECT_GE(stepsInWindow, 11);  // a step ends on the cut
  EXPECT_GT(moved, 1e-6);        // and the cut changed the motion
}

TEST(CouplingInterfaceApi, WindowsThatCannotMoveTimeOrWouldNeverEndAreRefusedAndChangeNothing) {
  // advance(5e-324) used to leave the handle failing until a restore, advance(1e300) never
  // returned, advance(1e-20) returned without moving time: each is refused at once now, the
  // state is untouched and the next ordinary window goes on.
  // At the start (t = 0, where 5e-324 is still a representable step that the stepper counts as
  // reached at once) and after a window.
  for (const bool atStart : {true, false}) {
    CouplingInterface s(smallCanopy());
    if (!atStart) s.advance(s.preferredTimeStep());
    const auto before = s.snapshot();
    int refused = 0;
    for (const double dt : {5e-324, 1e-20, 1e300, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
      try {
        s.advance(dt);
        ADD_FAILURE() << "advance(" << dt << ") accepted at t = " << s.time();
      } catch (const CouplingError& e) {
        ++refused;
        std::printf("t = %g: advance(%g): %s\n", before.state.t, dt, e.what());
      }
      const auto after = s.snapshot();
      EXPECT_TRUE(after.state.x == before.state.x && after.state.t == before.state.t &&
                  after.histories == before.histories);
    }
    EXPECT_EQ(refused, 5);
    const double t = s.time();
    s.advance(s.preferredTimeStep());
    EXPECT_GT(s.time(), t);
  }
}

TEST(CouplingInterfaceApi, StepsWithEveryIntegratorAsChuteRunDoes) {
  // One factory builds the integrator for `chute run` and for the coupling interface: the small
  // canopy under a constant 60 Pa, once with the case's own pressure (runCase) and once with the
  // same pressure set on the wet surface window by window (from t = 0: initializeWithLoads), give
  // the same steps for each integrator: the window is the case's dt, which the implicit schemes
  // take and which caps the explicit one's stable step here, and the wet surface's pressure goes
  // through the case pressure's kernel. So they agree to round-off.
  for (const auto kind : integratorKinds()) {
    const std::string name(integratorName(kind));
    const CaseSpec spec = smallCanopy({"solver.integrator=\"" + name + "\"",
                                       "loads.pressure.0.ramp_time=0", "output.interval=5e-4"});
    const RunResult run = runCase(spec, RunOptions{});
    ASSERT_EQ(run.status, RunStatus::Completed) << name << ": " << run.reason;
    CouplingInterface s(spec);
    const int apex = spec.model.nodeId("canopy.center");
    s.setFacePressures(Eigen::VectorXd::Constant(s.numFaces(), 60.0));
    s.initializeWithLoads();  // the pressure acts from t = 0, as the case's
    while (s.time() < spec.solver.tEnd - 1e-12) s.advance(spec.solver.dt);
    const double coupled = s.state().x[3 * apex + 2] - spec.model.X[apex].z();
    const int col = static_cast<int>(std::find(run.columns.begin(), run.columns.end(), "apex.z") -
                                     run.columns.begin());
    const double alone = run.rows.back()[col] - spec.model.X[apex].z();
    const double rel = std::abs(coupled - alone) / std::abs(alone);
    std::printf("%-20s apex rise at t = %g: chute run %.9e, coupled %.9e (relative %.2e)\n",
                name.c_str(), s.time(), alone, coupled, rel);
    EXPECT_GT(std::abs(alone), 1e-4);
    EXPECT_LT(rel, 1e-12) << name;
  }
}
