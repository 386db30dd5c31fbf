#include "solver/StableStep.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace chute {

namespace {

Vec3 at(const Eigen::VectorXd& x, int n) {
  return x.segment<3>(3 * n);
}

// Smallest altitude of triangle (a, b, c): twice its area over its longest edge.
double smallestAltitude(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double twiceArea = (b - a).cross(c - a).norm();
  const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  return longest > 0.0 ? twiceArea / longest : 0.0;
}

// Axial stiffness of a line part of reference length L: E A / L (engineering strain, F1). The
// tension's geometric stiffness N / l is left out: it is E A / L times the strain, covered by
// the safety factor, and a step that followed it would vary with the line's axial vibration,
// which pumps energy into that vibration (EX6).
double lineStiffness(const kernels::LineMaterial& mat, double L, double /*l*/) {
  return mat.E * mat.area / L;
}

}  // namespace

std::vector<double> nodalStiffnessBound(const Model& m,
                                        const std::vector<const SlidingGroupState*>& groups,
                                        const Eigen::VectorXd& x, double t) {
  return nodalStiffnessBound(m, membraneBoundData(m), groups, x, t);
}

MembraneBoundData membraneBoundData(const Model& m) {
  MembraneBoundData d;
  d.perNode.reserve(m.membranes.size());
  d.l0.reserve(m.membranes.size());
  for (const auto& e : m.membranes) {
    const auto& mat = m.membraneMaterials[e.material];
    const double shrink = 1.0 / (1.0 + m.membraneSets[e.set].prestrain);
    const int nn = e.numNodes;
    auto X = [&](int i) { return Vec3(shrink * m.X[e.nodes[i]]); };
    // Reference area and smallest reference altitude (a quad: its four corner triangles).
    double area0 = 0.0, h0 = std::numeric_limits<double>::infinity();
    if (nn == 3) {
      area0 = 0.5 * (X(1) - X(0)).cross(X(2) - X(0)).norm();
      h0 = smallestAltitude(X(0), X(1), X(2));
    } else {
      area0 = 0.5 * (X(2) - X(0)).cross(X(3) - X(1)).norm();
      for (int i = 0; i < 4; ++i)
        h0 = std::min(h0, smallestAltitude(X(i), X((i + 1) % 4), X((i + 2) % 4)));
    }
    d.perNode.push_back(h0 > 0.0 ? 4.0 * mat.E * mat.thickness * area0 /
                                       (nn * (1.0 - mat.nu * mat.nu) * h0 * h0)
                                 : 0.0);
    std::array<double, 4> l0{};
    for (int i = 0; i < nn; ++i) l0[i] = (X((i + 1) % nn) - X(i)).norm();
    d.l0.push_back(l0);
  }
  return d;
}

std::vector<double> nodalStiffnessBound(const Model& m, const MembraneBoundData& membranes,
                                        const std::vector<const SlidingGroupState*>& groups,
                                        const Eigen::VectorXd& x, double t) {
  const int n = m.numNodes();
  std::vector<double> S(n, 0.0);
  std::vector<char> free(n, 0);
  for (int i = 0; i < n; ++i) {
    const auto& c = m.constraint[i];
    free[i] = !(c.fixed[0] && c.fixed[1] && c.fixed[2]);
  }
  // A two-node line: K = k [1 -1; -1 1] (x) n n^T; the row sum over free nodes is k per node
  // touched (EX5).
  auto addLine = [&](int a, int b, double k) {
    const double rowSum = k * ((free[a] ? 1.0 : 0.0) + (free[b] ? 1.0 : 0.0));
    S[a] += rowSum;
    S[b] += rowSum;
  };
  for (const auto& c : m.cables) {
    if (m.lineSets[c.set].cutBy(t)) continue;
    addLine(c.a, c.b,
            lineStiffness(m.materials[c.material], c.L, (at(x, c.b) - at(x, c.a)).norm()));
  }
  for (const auto* st : groups) {
    const auto& g = st->def();
    const auto& mat = m.materials[g.material];
    for (int k = 0; k < g.numElements(); ++k) {
      const int n1 = g.chain[k], n2 = g.chain[k + 1];
      const double L = st->refLength(k);
      const int s = st->sliderOfElement(k);
      if (s < 0) {
        addLine(n1, n2, lineStiffness(mat, L, (at(x, n2) - at(x, n1)).norm()));
        continue;
      }
      // Uniform strain over the whole element (F9): K = k g g^T with g the gradient of
      // l1 + l2, |g| = 1 at the end nodes and |t1 - t2| <= 2 at the slider. The stiffness is
      // that of the whole reference length L however close the slider is to a node: a slider
      // approaching a node does not shrink the step (EX6).
      const int n3 = g.sliders[s];
      if (g.frictionOf(s)) {
        // Capstan friction: each part has its own strain over its own reference length (FR2);
        // a sticking slider next to a node makes a short, stiff part, and the step shrinks
        // with it (EX6).
        const double s1 = std::clamp(st->splitStart(s), 1e-9 * L, L * (1.0 - 1e-9));
        addLine(n1, n3, mat.E * mat.area / s1);
        addLine(n3, n2, mat.E * mat.area / (L - s1));
        continue;
      }
      const Vec3 d1 = at(x, n3) - at(x, n1), d2 = at(x, n2) - at(x, n3);
      const double l1 = d1.norm(), l2 = d2.norm();
      const double gs = (l1 > 0.0 && l2 > 0.0) ? (d1 / l1 - d2 / l2).norm() : 2.0;
      const double kk = lineStiffness(mat, L, l1 + l2);
      const double g1 = free[n1] ? 1.0 : 0.0, g2 = free[n2] ? 1.0 : 0.0, g3 = free[n3] ? gs : 0.0;
      const double sum = g1 + g2 + g3;
      S[n1] += kk * 1.0 * sum;
      S[n2] += kk * 1.0 * sum;
      S[n3] += kk * gs * sum;
    }
  }
  for (size_t k = 0; k < m.membranes.size(); ++k) {
    const auto& e = m.membranes[k];
    const double base = membranes.perNode[k];
    if (!(base > 0.0)) continue;
    // Total-Lagrangian St. Venant-Kirchhoff: the stiffness grows with the square of the largest
    // stretch; compressed (folded, wrinkled) fabric is bounded by its reference stiffness.
    const int nn = e.numNodes;
    double stretch = 1.0;
    for (int i = 0; i < nn; ++i) {
      const double l0 = membranes.l0[k][i];
      if (l0 > 0.0)
        stretch = std::max(stretch, (at(x, e.nodes[(i + 1) % nn]) - at(x, e.nodes[i])).norm() / l0);
    }
    const double perNode = base * stretch * stretch;
    for (int i = 0; i < nn; ++i) S[e.nodes[i]] += perNode;
  }
  return S;
}

StableStepEstimate stableStep(const std::vector<double>& stiffness,
                              const std::vector<double>& nodalMass, const std::vector<char>& free) {
  StableStepEstimate out;
  double omega2 = 0.0;
  for (size_t i = 0; i < stiffness.size(); ++i) {
    if (!free[i] || !(nodalMass[i] > 0.0)) continue;
    const double w2 = stiffness[i] / nodalMass[i];
    if (w2 > omega2) omega2 = w2, out.node = static_cast<int>(i);
  }
  out.dt = omega2 > 0.0 ? 2.0 / std::sqrt(omega2) : std::numeric_limits<double>::infinity();
  return out;
}

double dampedStableStep(double undampedStep, double beta) {
  if (!(beta > 0.0) || !std::isfinite(undampedStep)) return undampedStep;
  const double omega = 2.0 / undampedStep;
  const double xi = 0.5 * beta * omega;
  return undampedStep * (std::sqrt(1.0 + xi * xi) - xi);
}

}  // namespace chute
