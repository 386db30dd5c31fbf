#pragma once
// The stable step of explicit central differences from the elements' current sizes and wave
// speeds (docs/formulation.md EX4-EX6). A pure function of the model, the sliding groups' active
// elements, the positions and the lumped nodal masses.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "model/Model.hpp"
#include "model/SlidingGroupState.hpp"

namespace chute {

// Per node, the Gershgorin row sum S_i of the stiffness that bounds its frequency:
// omega_max^2 <= max_i S_i / m_i (EX5). Lines: 2 E A / l per end (axial, on the current length
// l); a sliding element's uniform-strain stiffness E A / (l1 + l2) times the gradient norms of
// its length (EX6); membranes: 4 E t A0 / (n (1 - nu^2) h^2) per node with h the smallest
// current altitude (plane-stress dilatational wave, EX5). Nodes whose dofs are all prescribed
// are left out of the sums (they are not part of the free system).
std::vector<double> nodalStiffnessBound(const Model& m,
                                        const std::vector<const SlidingGroupState*>& groups,
                                        const Eigen::VectorXd& x, double t);

// What the membranes' part of the bound takes from the reference geometry alone, computed once
// per model: per element the bound at unit stretch, 4 E t A0 / (n (1 - nu^2) h0^2) (EX6m), and
// its reference edge lengths.
struct MembraneBoundData {
  std::vector<double> perNode;            // per element
  std::vector<std::array<double, 4>> l0;  // per element, edge i from node i to node i + 1
};
MembraneBoundData membraneBoundData(const Model& m);
// The same bound with the membranes' reference part given (the explicit path's every-4-steps
// evaluation).
std::vector<double> nodalStiffnessBound(const Model& m, const MembraneBoundData& membranes,
                                        const std::vector<const SlidingGroupState*>& groups,
                                        const Eigen::VectorXd& x, double t);

struct StableStepEstimate {
  double dt = 0.0;  // 2 / omega_max (no safety factor, no damping)
  int node = -1;    // the node that limits it
};

// nodalMass: per node (least mass over its free dofs; <= 0 nodes are skipped: the integrator
// refuses them before). free: whether the node has a free dof.
StableStepEstimate stableStep(const std::vector<double>& stiffness,
                              const std::vector<double>& nodalMass, const std::vector<char>& free);

// Largest stable step of central differences with stiffness-proportional damping beta (EX7):
// dt <= (2 / omega) (sqrt(1 + xi^2) - xi), xi = beta omega / 2.
double dampedStableStep(double undampedStep, double beta);

}  // namespace chute
