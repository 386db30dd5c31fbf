// The airflow's loads on a canopy as a term (docs/flight.md FL1-FL12), on a rigid polygonal cup
// (every node held): the enclosed volume against its closed form, the captured air's steady
// pressure against the flow's stagnation pressure (impermeable) and against the balance of mouth
// inflow and cloth outflow solved independently (porous), nothing at all in still air, and the
// term's one pass over the faces against the face law (kernels/CanopyFlow) face by face, and the
// explicit step's loads made in the membranes' pass (FL13) against the term's own.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>

#include "solver/CentralDifference.hpp"
#include "solver/TimeStepper.hpp"
#include "support/CupModel.hpp"
#include "terms/CanopyFlowTerm.hpp"

using namespace chute;

namespace {

constexpr int kSides = 12;
constexpr double kRadius = 1.0, kHeight = 0.8;

// A cup open at the bottom (support/CupModel.hpp), every node held: the flow's loads act on a
// rigid shape, and the captured air settles.
Model rigidCup(double windSpeed, double permeability) {
  Model m = chute::testing::openCup(kSides, kRadius, kHeight, {1e6, 0.3, 1e-4, 500.0});
  for (auto& c : m.constraint) c.fixed = {true, true, true};
  m.air.given = true;
  m.air.density = 1.225;
  m.air.pressure = 101325.0;
  m.air.wind = Vec3(0, 0, windSpeed);  // up, into the mouth
  CanopyFlowDef d;
  d.set = 0;
  d.baseCoefficient = -0.8;
  if (permeability > 0.0) d.cloth = kernels::ClothPermeability::fromTest(permeability, 124.5, 0.0);
  m.canopyFlows.push_back(d);
  return m;
}

// The captured air's gauge pressure after `time` of the explicit steps' air updates.
double settledPressure(const Model& m, double time) {
  StructuralSystem sys(m, SliderSearch::MaterialCoordinate);
  CentralDifference cd(sys, ExplicitSettings{}, 1e-4);
  TimeStepper stepper(sys, cd, 1e-4);
  StructuralState s = stepper.start();
  stepper.advanceTo(
      s, time, [](double) { return 1e300; }, [](const StructuralState&, int) { return true; });
  return sys.termList().canopyFlows().front()->figuresAt(s.x, s.v).insideGauge;
}

}  // namespace

TEST(CanopyFlowTerm, EnclosedVolumeIsTheCupsClosedForm) {
  const Model m = rigidCup(0.0, 0.0);
  const CanopyFlowTerm term(m, 0);
  Eigen::VectorXd x(3 * m.numNodes()), v = Eigen::VectorXd::Zero(3 * m.numNodes());
  for (int n = 0; n < m.numNodes(); ++n) x.segment<3>(3 * n) = m.X[n];
  const double polygon = 0.5 * kSides * kRadius * kRadius * std::sin(2 * std::numbers::pi / kSides);
  const auto f = term.figuresAt(x, v);
  // Moved and turned rigidly: the same volume.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 0.5).normalized()).toRotationMatrix();
  Eigen::VectorXd y(x.size());
  for (int n = 0; n < m.numNodes(); ++n) y.segment<3>(3 * n) = R * m.X[n] + Vec3(3, -1, 2);
  const auto g = term.figuresAt(y, v);
  std::printf("cup volume %.12g, closed form %.12g; moved and turned %.12g; mouth %.12g (%.12g)\n",
              f.volume, polygon * kHeight, g.volume, f.mouthArea, polygon);
  EXPECT_NEAR(f.volume, polygon * kHeight, 1e-12);
  EXPECT_NEAR(g.volume, polygon * kHeight, 1e-12);
  EXPECT_NEAR(f.mouthArea, polygon, 1e-12);
  EXPECT_NEAR(term.nominalDiameter(), 2 * kRadius, 1e-12);
}

TEST(CanopyFlowTerm, ImpermeableCupCapturesTheStagnationPressure) {
  // FL4: no way out, so the inflow stops where the inside pressure is the flow's ram pressure q.
  const double V = 10.0, q = 0.5 * 1.225 * V * V;
  const double p = settledPressure(rigidCup(V, 0.0), 0.2);
  std::printf("impermeable cup in a %g m/s wind: inside %.6g Pa, q = %.6g Pa (%.2e)\n", V, p, q,
              p / q - 1);
  EXPECT_NEAR(p / q, 1.0, 1e-3);
}

TEST(CanopyFlowTerm, PorousCupSettlesWhereInflowMatchesTheClothsOutflow) {
  // FL4, FL6, FL9 solved independently: the mouth's Bernoulli inflow
  // Cd A_m sqrt(2 (q - p) / rho) equals the cloth's Darcy outflow through the roof (outside at
  // the base pressure Cb q: it looks downstream) and the walls (along the flow: the attached
  // band, no suction), u = p_diff u_ref / 124.5.
  const double V = 10.0, rho = 1.225, q = 0.5 * rho * V * V, uRef = 0.5;
  const double polygon = 0.5 * kSides * kRadius * kRadius * std::sin(2 * std::numbers::pi / kSides);
  const double walls = kSides * 2 * kRadius * std::sin(std::numbers::pi / kSides) * kHeight;
  auto imbalance = [&](double p) {
    const double in = 0.61 * polygon * std::sqrt(2 * (q - p) / rho);
    const double out = polygon * (p + 0.8 * q) * uRef / 124.5 + walls * p * uRef / 124.5;
    return in - out;
  };
  double lo = -q, hi = q;
  for (int i = 0; i < 200; ++i) (imbalance(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
  const double expected = 0.5 * (lo + hi);
  const double p = settledPressure(rigidCup(V, uRef), 0.2);
  std::printf(
      "porous cup (u_ref %g m/s at 124.5 Pa) in a %g m/s wind: inside %.6g Pa, the "
      "balance's %.6g Pa (%.2e); q = %.6g Pa\n",
      uRef, V, p, expected, p / expected - 1, q);
  EXPECT_NEAR(p / expected, 1.0, 1e-3);
  EXPECT_LT(p, q);
}

TEST(CanopyFlowTerm, StillAirLoadsNothing) {
  const Model m = rigidCup(0.0, 0.5);
  StructuralSystem sys(m, SliderSearch::MaterialCoordinate);
  const StructuralState s = sys.initialState();
  const auto f = sys.termList().canopyFlows().front()->figuresAt(s.x, s.v);
  EXPECT_EQ(f.insideGauge, 0.0);  // ambient air captured at the start
  EXPECT_EQ(f.dynamicPressure, 0.0);
  EXPECT_EQ(f.inflow, 0.0);
  EXPECT_EQ(f.clothOutflow, 0.0);
}

TEST(CanopyFlowTerm, OnePassLoadsAreTheFaceLawAtTheStartsCanopyVelocity) {
  // FL1, FL8: the term's loads at a state, its faces' area vectors and velocities used as they
  // are made, against canopyFaceLoad face by face with the canopy-wide state made here: the
  // canopy's velocity the nodes' by their area shares at the start (the cup as built), the flow
  // direction and dynamic pressure from it, the inside pressure the term's own (FL3, checked
  // above). Free nodes, bent and moving: every face at its own attitude to the flow.
  Model m = rigidCup(12.0, 0.5);
  for (auto& c : m.constraint) c.fixed = {false, false, false};
  StructuralSystem sys(m, SliderSearch::MaterialCoordinate);
  const CanopyFlowTerm& term = *sys.termList().canopyFlows().front();
  std::vector<double> share(m.numNodes(), 0.0);
  double total = 0.0;
  for (const auto& e : m.membranes) {
    const Vec3 A =
        e.numNodes == 3
            ? Vec3(0.5 *
                   (m.X[e.nodes[1]] - m.X[e.nodes[0]]).cross(m.X[e.nodes[2]] - m.X[e.nodes[0]]))
            : Vec3(0.5 *
                   (m.X[e.nodes[2]] - m.X[e.nodes[0]]).cross(m.X[e.nodes[3]] - m.X[e.nodes[1]]));
    for (int i = 0; i < e.numNodes; ++i) share[e.nodes[i]] += A.norm() / e.numNodes;
    total += A.norm();
  }
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1), speed(-4.0, 4.0);
  double worst = 0.0;
  for (int trial = 0; trial < 10; ++trial) {
    Eigen::VectorXd x(3 * m.numNodes()), v(3 * m.numNodes());
    for (int n = 0; n < m.numNodes(); ++n) {
      x.segment<3>(3 * n) = m.X[n] + Vec3(jitter(rng), jitter(rng), jitter(rng));
      v.segment<3>(3 * n) = Vec3(speed(rng), speed(rng), speed(rng));
    }
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(x.size());
    const Eigen::VectorXd r = sys.residualOverAllDofs(EvalPoint::state(x, v, zero, 0.0), false);
    kernels::CanopyFlowState s;
    for (int n = 0; n < m.numNodes(); ++n)
      s.canopyVelocity += share[n] / total * v.segment<3>(3 * n);
    const Vec3 U = m.air.wind - s.canopyVelocity;
    s.flowDirection = U.normalized();
    s.dynamicPressure = 0.5 * m.air.density * U.squaredNorm();
    s.baseCoefficient = -0.8;
    s.normalDrag = 0.5 * m.air.density * 1.17;
    s.insideGauge = term.figuresAt(x, v).insideGauge;
    Eigen::VectorXd expected = Eigen::VectorXd::Zero(x.size());
    auto add = [&](const auto& e, auto nodesTag) {
      constexpr int N = decltype(nodesTag)::value;
      std::array<Vec3, N> xf, vf;
      for (int i = 0; i < N; ++i)
        xf[i] = x.segment<3>(3 * e.nodes[i]), vf[i] = v.segment<3>(3 * e.nodes[i]);
      const auto f = kernels::canopyFaceLoad<N>(xf, vf, s, false);
      for (int i = 0; i < N; ++i)
        expected.segment<3>(3 * e.nodes[i]) += f.residual.template segment<3>(3 * i);
    };
    for (const auto& e : m.membranes)
      e.numNodes == 3 ? add(e, std::integral_constant<int, 3>{})
                      : add(e, std::integral_constant<int, 4>{});
    const double d = (r - expected).cwiseAbs().maxCoeff() / expected.cwiseAbs().maxCoeff();
    worst = std::max(worst, d);
    EXPECT_LE(d, 1e-13) << "trial " << trial;
  }
  std::printf(
      "one pass over the faces against the face law face by face: %.3g of the largest load "
      "(bound 1e-13; 10 bent, moving cups of 12 triangles and 12 quads)\n",
      worst);
}

namespace {

// The cup of triangles only (each wall quad halved), free, its fabric stiff enough to keep its
// shape over a few steps: what the membranes' pass takes the airflow's loads of (FL13).
Model triangleCup(double windSpeed, double permeability) {
  Model m = rigidCup(windSpeed, permeability);
  for (auto& c : m.constraint) c.fixed = {false, false, false};
  std::vector<MembraneElement> triangles;
  for (const auto& e : m.membranes) {
    if (e.numNodes == 3) {
      triangles.push_back(e);
      continue;
    }
    MembraneElement a = e, b = e;
    a.numNodes = b.numNodes = 3;
    a.nodes = {e.nodes[0], e.nodes[1], e.nodes[2], -1};
    b.nodes = {e.nodes[0], e.nodes[2], e.nodes[3], -1};
    triangles.push_back(a), triangles.push_back(b);
  }
  m.membranes = triangles;
  return m;
}

}  // namespace

TEST(CanopyFlowTerm, MembranesPassLoadsAreTheTermsOwnOnTheExplicitStep) {
  // FL13: the explicit step's residual and the loads the energy balance keeps, with the airflow's
  // loads made in the membranes' pass, against the same system with each term its own; with and
  // without stiffness damping's shifted positions (EX7), permeable cloth of either law; and the
  // loads of an evaluation the membranes' pass does not take, the same with it taken or not.
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05), speed(-3.0, 3.0);
  double worstResidual = 0.0, worstLoads = 0.0;
  int taken = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const Model m = triangleCup(15.0, trial % 3 == 0 ? 0.0 : 0.4);
    TermOptions apart;
    apart.takeCanopyFlow = false;
    StructuralSystem fused(m, TermOptions{}), reference(m, apart);
    Eigen::VectorXd x(3 * m.numNodes()), v(3 * m.numNodes());
    for (int n = 0; n < m.numNodes(); ++n) {
      x.segment<3>(3 * n) = m.X[n] + Vec3(jitter(rng), jitter(rng), jitter(rng));
      v.segment<3>(3 * n) = Vec3(speed(rng), speed(rng), speed(rng));
    }
    const double beta = trial % 2 == 0 ? 0.0 : 1e-4;
    const Eigen::VectorXd xEval = x + beta * v, zero = Eigen::VectorXd::Zero(x.size());
    const double t = 1e-3 * (trial + 1);
    const EvalPoint p =
        EvalPoint::explicitForces(xEval, v, zero, t, 1e-5, beta > 0.0 ? &x : nullptr, beta);
    Eigen::VectorXd residual[2], loads[2];
    StructuralSystem* systems[2] = {&fused, &reference};
    for (int k = 0; k < 2; ++k) {
      systems[k]->captureStepLoads(true);
      systems[k]->assemble(p, false);
      systems[k]->captureStepLoads(false);
      residual[k] = systems[k]->residual();
      ASSERT_NE(systems[k]->stepLoadsAt(t), nullptr);
      loads[k] = *systems[k]->stepLoadsAt(t);
    }
    taken += fused.termList().canopyFlows().front()->assemblyCost() == 0.0;
    // Every other evaluation (here the loads at a state, as output and the energy balance ask
    // them) is the airflow's term's own, taken or not: the same bits.
    const EvalPoint state = EvalPoint::state(x, v, zero, t);
    EXPECT_EQ(fused.residualOverAllDofs(state, false), reference.residualOverAllDofs(state, false))
        << "trial " << trial;
    const double dr =
        (residual[0] - residual[1]).cwiseAbs().maxCoeff() / residual[1].cwiseAbs().maxCoeff();
    const double dl = (loads[0] - loads[1]).cwiseAbs().maxCoeff() / loads[1].cwiseAbs().maxCoeff();
    worstResidual = std::max(worstResidual, dr);
    worstLoads = std::max(worstLoads, dl);
    EXPECT_LE(dr, 1e-12) << "trial " << trial;
    EXPECT_LE(dl, 1e-12) << "trial " << trial;
  }
  EXPECT_EQ(taken, 12);  // every cup's loads were the membranes' pass's
  std::printf(
      "explicit step with the airflow's loads in the membranes' pass against the terms apart: "
      "residual %.3g, kept loads %.3g of their largest entries (bound 1e-12; 12 cups of 36 "
      "triangles, half at EX7's shifted positions)\n",
      worstResidual, worstLoads);
}
