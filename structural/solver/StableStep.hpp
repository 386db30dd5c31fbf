#pragma once
// The stable step of explicit central differences (docs/formulation.md EX4-EX7) from the nodal
// stiffness bounds the terms give (Term::addStiffnessBound, kernels/StiffnessBound.hpp) and the
// lumped nodal masses: omega_max^2 <= max_i S_i / m_i (EX5).
#include <vector>

namespace chute {

struct StableStepEstimate {
  double dt = 0.0;  // 2 / omega_max (no safety factor, no damping)
  int node = -1;    // the node that limits it
};

// stiffness: per node, the row sum S_i of the stiffness (StructuralSystem::stiffnessBound).
// nodalMass: per node (least mass over its free dofs; <= 0 nodes are skipped: the integrator
// refuses them before). free: whether the node has a free dof.
StableStepEstimate stableStep(const std::vector<double>& stiffness,
                              const std::vector<double>& nodalMass, const std::vector<char>& free);

// Largest stable step of central differences with stiffness-proportional damping beta (EX7):
// dt <= (2 / omega) (sqrt(1 + xi^2) - xi), xi = beta omega / 2.
double dampedStableStep(double undampedStep, double beta);

}  // namespace chute
