// The cables as a term on the explicit path (docs/formulation.md CB1): four at a time (with AVX2;
// one at a time without), with the drag of their line sets taken into that pass, the residual and
// the energy balance's loads of the cable and line-drag terms each evaluated on its own, to
// round-off of the sums' order: a set with one drag load (taken), one with two (left to the
// line-drag term), one without drag, one cut while the others carry on, a fixed node, gravity.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "case/CaseSpec.hpp"
#include "solver/StructuralSystem.hpp"
#include "support/FusedAgainstApart.hpp"
#include "support/LineGeometry.hpp"

using namespace chute;

namespace {

// Four chains of five cables each, one line set per chain, hanging from node 0 (fixed).
Model chains() {
  Model m;
  m.materialName.push_back("rope");
  m.materials.push_back(chute::testing::rope());
  const int top = m.addNode(Vec3::Zero(), "top");
  m.constraint[top].fixed = {true, true, true};
  for (int s = 0; s < 4; ++s) {
    LineSet set;
    set.name = "chain" + std::to_string(s);
    if (s == 3) set.cutAt = 0.3;
    m.lineSets.push_back(set);
    int prev = top;
    for (int k = 1; k <= 5; ++k) {
      const int n = m.addNode(Vec3(0.1 * s, 0.05 * k, -0.5 * k));
      CableElement c;
      c.a = prev, c.b = n, c.material = 0, c.set = s;
      c.L = 0.45;
      m.cables.push_back(c);
      prev = n;
    }
  }
  auto drag = [&](int set, double coefficient, const Vec3& wind) {
    DragLoadDef d;
    d.lineSet = set, d.coefficient = coefficient, d.wind = wind;
    m.drags.push_back(d);
  };
  drag(0, 0.02, Vec3(1.0, 0.0, 8.0));
  drag(1, 0.015, Vec3(0.0, 2.0, 6.0));
  drag(1, 0.01, Vec3(-1.0, 0.0, 3.0));
  drag(3, 0.02, Vec3(0.5, 0.5, 9.0));
  m.gravity = Vec3(0.0, 0.0, -9.81);
  return m;
}

}  // namespace

TEST(CableTerm, TakenLineDragIsTheCableAndDragTermsOnTheExplicitStep) {
  const Model m = chains();
  StructuralSystem sys(m, TermOptions{});
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> jitter(-0.08, 0.08), speed(-3.0, 3.0);
  double worstResidual = 0.0, worstLoads = 0.0;
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::VectorXd x(3 * m.numNodes()), v(3 * m.numNodes());
    for (int n = 0; n < m.numNodes(); ++n) {
      const double stretch = n == 0 ? 1.0 : 1.0 + 0.04 * (trial % 4) - 0.03;  // some slack
      x.segment<3>(3 * n) =
          stretch * m.X[n] + (n == 0 ? Vec3::Zero() : Vec3(jitter(rng), jitter(rng), jitter(rng)));
      v.segment<3>(3 * n) = n == 0 ? Vec3::Zero() : Vec3(speed(rng), speed(rng), speed(rng));
    }
    const double t = 0.05 * trial;  // chain 3 cut from t > 0.3
    const auto g = chute::testing::fusedAgainstApart(sys, x, v, t);
    // Every element and every drag counted once, wherever evaluated.
    const int carried = t > 0.3 ? 15 : 20;
    EXPECT_EQ(g.fused.lineElastic - g.before.lineElastic, carried);
    EXPECT_EQ(g.fused.lineMass - g.before.lineMass, carried);
    EXPECT_EQ(g.fused.drag - g.before.drag, 5 + 10 + 5);
    worstResidual = std::max(worstResidual, g.residual);
    worstLoads = std::max(worstLoads, g.loads);
    EXPECT_LE(g.residual, 1e-13) << "trial " << trial;
    EXPECT_LE(g.loads, 1e-13) << "trial " << trial;
  }
  std::printf(
      "explicit step with the cables' drag in the cables' pass against the terms apart: residual "
      "%.3g, loads %.3g of their largest entries (bound 1e-13; 20 cables, 10 with their drag "
      "taken, 5 with two drag loads left to the drag term, 5 cut from t = 0.3)\n",
      worstResidual, worstLoads);
}

TEST(CableTerm, TakenLineDragOfTheC9IsTheTermsApartOnTheExplicitStep) {
  const CaseSpec spec = readCase(CHUTE_SOURCE_DIR "/cases/c9_slider.toml", {});
  const Model& m = spec.model;
  StructuralSystem sys(m, spec.solver.search);
  StructuralState s = sys.initialState();
  double worstResidual = 0.0, worstLoads = 0.0;
  for (int trial = 0; trial < 5; ++trial) {
    // The folded start, moved and stretched a little, with some motion (drag not zero).
    Eigen::VectorXd x = s.x, v = s.v;
    for (long d = 0; d < x.size(); ++d) {
      x[d] *= 1.0 + 0.01 * trial;
      x[d] += 0.002 * std::sin(0.37 * static_cast<double>(d) + trial);
      v[d] = 2.0 * std::cos(0.21 * static_cast<double>(d) - trial);
    }
    sys.updateState(x);
    const auto g = chute::testing::fusedAgainstApart(sys, x, v, 0.1);
    // Every segment counted once, either way.
    EXPECT_EQ(g.apart.drag - g.fused.drag, g.fused.drag - g.before.drag);
    worstResidual = std::max(worstResidual, g.residual);
    worstLoads = std::max(worstLoads, g.loads);
    EXPECT_LE(g.residual, 1e-13) << "trial " << trial;
    EXPECT_LE(g.loads, 1e-13) << "trial " << trial;
  }
  std::printf(
      "C-9 with slider, explicit step with the lines' drag in the cables' and groups' passes "
      "against the terms apart: residual %.3g, loads %.3g of their largest entries (bound "
      "1e-13)\n",
      worstResidual, worstLoads);
}
