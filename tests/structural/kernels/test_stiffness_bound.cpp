// The membranes' stable-step estimate (docs/formulation.md EX6m) against the highest frequency of
// the element it estimates, computed: the generalised eigenvalues of the constant-strain
// triangle's stiffness (membraneForce's tangent at the unstrained reference) with its lumped mass
// (membraneMass). EX6m is an estimate, not a bound; the documented ratios are checked here.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <vector>

#include "kernels/MembraneKernel.hpp"
#include "kernels/StiffnessBound.hpp"

using namespace chute::kernels;

namespace {

const MembraneMaterial kFabric{4.32e6, 0.3, 5e-4, 1.6};

// omega_max^2 of the free triangle X with lumped mass, over EX6m's S_i / m_i.
double highestOverEstimate(const std::array<Vec3, 3>& X) {
  const auto ref = triangleReference(X, kFabric.thickness);
  const auto K = membraneForce<3>(X, ref, kFabric, false, true, false).stiffness;
  const Eigen::Matrix3d M = membraneMass<3>(ref, kFabric.density, true);
  Eigen::Matrix<double, 9, 9> A;
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j) A(i, j) = K(i, j) / std::sqrt(M(i / 3, i / 3) * M(j / 3, j / 3));
  const double highest =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 9, 9>>(A).eigenvalues().maxCoeff();
  const MembraneBoundReference b =
      membraneBoundReference({X[0], X[1], X[2], Vec3::Zero()}, 3, kFabric);
  return highest / (b.perNode / M(0, 0));
}

}  // namespace

TEST(StiffnessBound, MembraneEstimateAgainstTheTrianglesHighestFrequency) {
  const double h = std::sqrt(3.0) / 2.0;
  const struct {
    const char* name;
    std::array<Vec3, 3> X;
    double documented;
  } cases[] = {
      {"equilateral", {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, h, 0)}, 1.46},
      {"right-angled", {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, 1.17},
      {"skinny", {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0.2, 0)}, 1.13},
  };
  for (const auto& c : cases) {
    const double ratio = highestOverEstimate(c.X);
    std::printf("%s triangle: highest omega^2 / EX6m's S/m = %.4f (documented %.2f)\n", c.name,
                ratio, c.documented);
    EXPECT_NEAR(ratio, c.documented, 0.01) << c.name;
    EXPECT_GT(ratio, 1.0) << c.name;  // exceeded: an estimate, not a bound
  }
}

// A free patch of 72 equilateral triangles (7 x 7 nodes), assembled: the highest omega^2 of the
// patch over the largest S_i / m_i of EX6m, with S_i and m_i summed over each node's triangles.
// Inside the default safety factor's 1 / 0.81.
TEST(StiffnessBound, MembraneEstimateAgainstAPatchsHighestFrequency) {
  const int n = 7;
  const double h = std::sqrt(3.0) / 2.0;
  std::vector<Vec3> X;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) X.emplace_back(i + 0.5 * j, h * j, 0.0);
  const int nodes = n * n;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3 * nodes, 3 * nodes);
  Eigen::VectorXd m = Eigen::VectorXd::Zero(nodes), S = Eigen::VectorXd::Zero(nodes);
  auto add = [&](int a, int b, int c) {
    const std::array<Vec3, 3> x{X[a], X[b], X[c]};
    const std::array<int, 3> id{a, b, c};
    const auto ref = triangleReference(x, kFabric.thickness);
    const auto Ke = membraneForce<3>(x, ref, kFabric, false, true, false).stiffness;
    const Eigen::Matrix3d Me = membraneMass<3>(ref, kFabric.density, true);
    const double perNode =
        membraneBoundReference({x[0], x[1], x[2], Vec3::Zero()}, 3, kFabric).perNode;
    for (int p = 0; p < 3; ++p) {
      m[id[p]] += Me(p, p);
      S[id[p]] += perNode;
      for (int q = 0; q < 3; ++q)
        K.block<3, 3>(3 * id[p], 3 * id[q]) += Ke.block<3, 3>(3 * p, 3 * q);
    }
  };
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      add(j * n + i, j * n + i + 1, (j + 1) * n + i);
      add(j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i);
    }
  Eigen::MatrixXd A(3 * nodes, 3 * nodes);
  for (int r = 0; r < 3 * nodes; ++r)
    for (int c = 0; c < 3 * nodes; ++c) A(r, c) = K(r, c) / std::sqrt(m[r / 3] * m[c / 3]);
  const double highest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A).eigenvalues().maxCoeff();
  const double estimate = (S.array() / m.array()).maxCoeff();
  std::printf(
      "patch of %d triangles: highest omega^2 / EX6m's largest S/m = %.4f (documented 1.075)\n",
      2 * (n - 1) * (n - 1), highest / estimate);
  EXPECT_NEAR(highest / estimate, 1.075, 0.01);
  EXPECT_LT(highest / estimate, 1.0 / (0.9 * 0.9));
}
