// The membranes as a term on the explicit path (docs/formulation.md M3, M4; EX2): the triangles
// four at a time (kernels/MembraneTriangleBatch.hpp, with a last batch of fewer than four) and
// the quads after them give the residual the general element path gives at zero acceleration,
// weight included, to round-off of the sums' order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "assembly/SystemAssembler.hpp"
#include "support/CupModel.hpp"
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

}  // namespace

TEST(MembraneTerm, ExplicitResidualIsTheElementPathsAtZeroAcceleration) {
  const Model m = cup();
  const DofMap dofs(m);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.08, 0.08);
  double worst = 0.0;
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::VectorXd x(3 * m.numNodes());
    for (int n = 0; n < m.numNodes(); ++n)
      x.segment<3>(3 * n) = 1.05 * m.X[n] + Vec3(jitter(rng), jitter(rng), jitter(rng));
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
