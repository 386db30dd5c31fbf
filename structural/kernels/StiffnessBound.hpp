#pragma once
// Per-node bounds of the stiffness that set the stable step of explicit central differences
// (docs/formulation.md EX5-EX6): the Gershgorin row sum S_i of each element's stiffness, so that
// omega_max^2 <= max_i S_i / m_i (lines; the membranes' S_i is an estimate, EX6m, below). Pure
// functions of an element's geometry and material; the terms add them up over their elements
// (Term::addStiffnessBound).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <limits>
#include <vector>

#include "kernels/MembraneKernel.hpp"
#include "kernels/UniformStrainPolyline.hpp"

namespace chute::kernels {

// Axial stiffness of a line part of reference length L: E A / L (engineering strain, F1). The
// tension's geometric stiffness N / l is left out: it is E A / L times the strain, covered by
// the safety factor, and a step that followed it would vary with the line's axial vibration,
// which pumps energy into that vibration (EX6).
inline double lineStiffness(const LineMaterial& mat, double L) {
  return mat.E * mat.area / L;
}

// A two-node line of stiffness k: K = k [1 -1; -1 1] (x) n n^T, whose row sum over the free nodes
// is k per free node touched, at both ends (EX5); each end's times its factor (EX6l: a
// tension-only line's nodes that no membrane touches take kHangingLineBound).
inline void addLineBound(int a, int b, double k, const std::vector<char>& free,
                         std::vector<double>& S, double factorA = 1.0, double factorB = 1.0) {
  const double rowSum = k * ((free[a] ? 1.0 : 0.0) + (free[b] ? 1.0 : 0.0));
  S[a] += factorA * rowSum;
  S[b] += factorB * rowSum;
}

// EX6l: the bound at a tension-only line's node that hangs free of the fabric, times 1 / 0.85^2,
// so that such a line's highest axial mode runs at 0.85 of the step the chain allows. A
// suspension line flapping in the flow gained energy in that mode at the chain's step (with the
// safety factor and the step's band, 0.81 of L / c): a generated 15 m canopy whose lines set the
// step diverged in 3 of 16 runs that differ by round-off; at 0.72 of L / c none of 16 did
// (docs/explicit.md, "Lines that set the step").
inline constexpr double kHangingLineBound = 1.0 / (0.85 * 0.85);

// Smallest altitude of triangle (a, b, c): twice its area over its longest edge.
inline double smallestAltitude(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               const Eigen::Vector3d& c) {
  const double twiceArea = (b - a).cross(c - a).norm();
  const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  return longest > 0.0 ? twiceArea / longest : 0.0;
}

// What a membrane element's bound takes from its reference geometry alone (EX6m): the bound at
// unit stretch, 4 E t A0 / (n (1 - nu^2) h0^2) per node (plane-stress dilatational wave over the
// smallest reference altitude h0; a quad: the least of its four corner triangles'), and its
// reference edge lengths (edge i from node i to node i + 1). An estimate rather than a row sum:
// a lone triangle's highest frequency squared is up to 1.46 times it, a mesh's about 1.075 times
// (test_stiffness_bound), inside the safety factor's 0.81.
struct MembraneBoundReference {
  double perNode = 0.0;
  std::array<double, 4> l0{};
};
inline MembraneBoundReference membraneBoundReference(const std::array<Eigen::Vector3d, 4>& X,
                                                     int numNodes, const MembraneMaterial& mat) {
  double area0 = 0.0, h0 = std::numeric_limits<double>::infinity();
  if (numNodes == 3) {
    area0 = 0.5 * (X[1] - X[0]).cross(X[2] - X[0]).norm();
    h0 = smallestAltitude(X[0], X[1], X[2]);
  } else {
    area0 = 0.5 * (X[2] - X[0]).cross(X[3] - X[1]).norm();
    for (int i = 0; i < 4; ++i)
      h0 = std::min(h0, smallestAltitude(X[i], X[(i + 1) % 4], X[(i + 2) % 4]));
  }
  MembraneBoundReference r;
  r.perNode = h0 > 0.0 ? 4.0 * mat.E * mat.thickness * area0 /
                             (numNodes * (1.0 - mat.nu * mat.nu) * h0 * h0)
                       : 0.0;
  for (int i = 0; i < numNodes; ++i) r.l0[i] = (X[(i + 1) % numNodes] - X[i]).norm();
  return r;
}

// The bound per node of a membrane element at current positions x (EX6m): total-Lagrangian St.
// Venant-Kirchhoff stiffness grows with the square of the largest edge stretch; compressed
// (folded, wrinkled) fabric is bounded by its reference stiffness. The number of nodes a template
// argument: the edge loop unrolled, without a division per edge for its end node (every element
// at every estimate of the explicit step).
template <int NumNodes>
double membraneNodeBound(const MembraneBoundReference& ref,
                         const std::array<Eigen::Vector3d, NumNodes>& x) {
  double stretch = 1.0;
  for (int i = 0; i < NumNodes; ++i) {
    const double l0 = ref.l0[i];
    if (l0 > 0.0) stretch = std::max(stretch, (x[(i + 1) % NumNodes] - x[i]).norm() / l0);
  }
  return ref.perNode * stretch * stretch;
}

}  // namespace chute::kernels
