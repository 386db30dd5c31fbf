// The membranes as a term on the explicit path (docs/formulation.md M3, M4; EX2): the triangles
// four at a time (kernels/MembraneTriangleBatch.hpp, with a last batch of fewer than four) and
// the quads after them give the residual the general element path gives at zero acceleration,
// weight included, to round-off of the sums' order; with the pressure and face drag of the
// triangles taken into that pass (P2), the residual and the loads of the separate terms; made in
// two halves (the assembly's two parts), the whole pass's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "assembly/SystemAssembler.hpp"
#include "solver/StructuralSystem.hpp"
#include "support/CupModel.hpp"
#include "support/FusedAgainstApart.hpp"
#include "terms/MembraneTerm.hpp"

using namespace chute;

namespace {

// A cup of 13 roof triangles fanned from the top and 13 wall quads, element by element in turn
// (triangle, quad, ...), on free nodes, with gravity.
Model cup() {
  Model m = chute::testing::openCup(13, 1.0, 0.8, {1e6, 0.3, 1e-4, 500.0});
  m.gravity = Vec3(0, 0, -9.81);
  return m;
}

// The cup's positions stretched by 5 % and jittered by up to 0.08 per coordinate.
Eigen::VectorXd jittered(const Model& m, std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-0.08, 0.08);
  Eigen::VectorXd x(3 * m.numNodes());
  for (int n = 0; n < m.numNodes(); ++n)
    x.segment<3>(3 * n) = 1.05 * m.X[n] + Vec3(jitter(rng), jitter(rng), jitter(rng));
  return x;
}

}  // namespace

TEST(MembraneTerm, ExplicitResidualIsTheElementPathsAtZeroAcceleration) {
  const Model m = cup();
  const DofMap dofs(m);
  std::mt19937 rng(5);
  double worst = 0.0;
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::VectorXd x = jittered(m, rng);
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(x.size());
    MembraneTerm explicitTerm(m), elementTerm(m);
    explicitTerm.prepareFor(IntegrationTraits{true, false});
    SystemAssembler a(dofs), b(dofs);
    std::vector<std::vector<int>> cliques;
    elementTerm.addCouplings(cliques);
    a.buildPattern({});  // sizes the residual
    b.buildPattern(cliques);
    a.begin(false);
    explicitTerm.assemble(EvalPoint::explicitForces(x, zero, zero, 0.0, 1e-4), a);
    b.begin(true);
    elementTerm.assemble(EvalPoint::implicitStep(x, zero, zero, 0.0, {1.0, 0.0, 0.0}, 1e-4), b);
    const double scale = b.residual().cwiseAbs().maxCoeff();
    const double diff = (a.residual() - b.residual()).cwiseAbs().maxCoeff();
    worst = std::max(worst, diff / scale);
    EXPECT_LE(diff, 1e-13 * scale) << "trial " << trial;
  }
  std::printf(
      "membranes, explicit against element path: largest difference %.3g of the largest "
      "entry (bound 1e-13; 13 triangles in batches of 4, 4, 4, 1 and 13 quads)\n",
      worst);
}

// P2: an explicit step's evaluation with the roof triangles' pressure and face drag in the
// membranes' pass gives the residual of every term evaluated on its own (the membranes' element
// path, the pressure and face-drag terms over every face), and the loads the energy balance keeps
// are those terms' loads: the quads' loads from the pressure and face-drag terms, the triangles'
// from the membranes' pass.
TEST(MembraneTerm, TakenFaceLoadsAreThePressureAndFaceDragTermsOnTheExplicitStep) {
  Model m = cup();
  PressureLoadDef pressure;
  pressure.set = 0, pressure.pressure = 800.0, pressure.rampTime = 0.5;
  for (size_t k = 0; k < m.membranes.size(); ++k)
    pressure.elementFactor.push_back(0.8 + 0.03 * static_cast<double>(k % 7));
  m.pressures.push_back(pressure);
  FaceDragLoadDef drag;
  drag.set = 0, drag.coefficient = 0.5 * 1.2 * 1.3, drag.wind = Vec3(1.0, -2.0, 12.0);
  drag.steadySubtracted = true;
  m.faceDrags.push_back(drag);
  StructuralSystem sys(m, TermOptions{});
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> jitter(-0.08, 0.08), speed(-3.0, 3.0);
  double worstResidual = 0.0, worstLoads = 0.0;
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::VectorXd x(3 * m.numNodes()), v(3 * m.numNodes());
    for (int n = 0; n < m.numNodes(); ++n) {
      x.segment<3>(3 * n) = 1.05 * m.X[n] + Vec3(jitter(rng), jitter(rng), jitter(rng));
      v.segment<3>(3 * n) = Vec3(speed(rng), speed(rng), speed(rng));
    }
    const double t = 0.05 * trial;  // through the pressure's ramp
    const auto g = chute::testing::fusedAgainstApart(sys, x, v, t);
    // Every face counted once, wherever its loads were evaluated (no pressure at the ramp's
    // start: none counted, as PressureTerm counts).
    EXPECT_EQ(g.fused.pressure - g.before.pressure, t > 0.0 ? 26 : 0);
    EXPECT_EQ(g.fused.faceDrag - g.before.faceDrag, 26);
    worstResidual = std::max(worstResidual, g.residual);
    worstLoads = std::max(worstLoads, g.loads);
    EXPECT_LE(g.residual, 1e-13) << "trial " << trial;
    EXPECT_LE(g.loads, 1e-13) << "trial " << trial;
  }
  std::printf(
      "explicit step with the triangles' loads in the membranes' pass against the terms apart: "
      "residual %.3g, loads %.3g of their largest entries (bound 1e-13; 13 triangles taken, 13 "
      "quads left to the load terms)\n",
      worstResidual, worstLoads);
}

TEST(MembraneTerm, TwoHalvesAreTheWholePass) {
  // Term::assembleHalf: half 0 then half 1 into one assembler add every triangle and quad once,
  // in the whole pass's order (the same bits); into two assemblers added after, the whole pass's
  // to round-off. Explicit evaluations are halved; any other is made whole by half 0.
  const Model m = cup();
  const DofMap dofs(m);
  std::mt19937 rng(8);
  double worst = 0.0;
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::VectorXd x = jittered(m, rng);
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(x.size());
    MembraneTerm term(m);
    term.prepareFor(IntegrationTraits{true, false});
    SystemAssembler whole(dofs), one(dofs), first(dofs), second(dofs);
    for (SystemAssembler* a : {&whole, &one, &first, &second}) {
      a->buildPattern({});
      a->begin(false);
    }
    const EvalPoint p = EvalPoint::explicitForces(x, zero, zero, 0.0, 1e-4);
    term.assemble(p, whole);
    term.assembleHalf(p, one, 0);
    term.assembleHalf(p, one, 1);
    term.afterHalves(p);
    term.assembleHalf(p, first, 0);
    term.assembleHalf(p, second, 1);
    term.afterHalves(p);
    EXPECT_EQ(whole.residual(), one.residual()) << "trial " << trial;
    EXPECT_GT((first.residual() - whole.residual()).cwiseAbs().maxCoeff(), 0.0);  // both halves
    EXPECT_GT(second.residual().cwiseAbs().maxCoeff(), 0.0);                      // did work
    const Eigen::VectorXd sum = first.residual() + second.residual();
    const double d =
        (sum - whole.residual()).cwiseAbs().maxCoeff() / whole.residual().cwiseAbs().maxCoeff();
    worst = std::max(worst, d);
    EXPECT_LE(d, 1e-14) << "trial " << trial;
  }
  std::printf(
      "membranes in two halves against the whole pass: the same bits into one assembler; into "
      "two, %.3g of the largest entry (bound 1e-14; 13 triangles, 13 quads)\n",
      worst);
}
