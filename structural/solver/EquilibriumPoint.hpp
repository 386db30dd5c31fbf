#pragma once
// Where the equations of a converged step hold (docs/formulation.md, eq. TI5): the
// configuration whose internal forces balance the inertia and the loads. Forces, stresses,
// strains and energies are reported there (docs/output.md), the motion (positions,
// velocities) at the step's end. For Bossak, statics and a start it is the state itself; for
// Chung-Hulbert it is the alpha-point x_{n+1-alpha_f} = (1 - alpha_f) x_{n+1} + alpha_f x_n,
// where a stiff member is stretched by its force / stiffness while the end-of-step positions
// stretch it by a further O((v dt)^2 / L) that no force balances.
#include <Eigen/Core>
#include <cmath>

namespace chute {

struct EquilibriumPoint {
  const Eigen::VectorXd& x;
  const Eigen::VectorXd& v;
  const Eigen::VectorXd& a;
  double t = 0.0;
};

// The equilibrium point that an integrator kept of its last converged step (an integrator other
// than the generalized-alpha family fills one too): the point if it belongs to the state that
// step ended in, the state itself otherwise.
struct KeptEquilibrium {
  Eigen::VectorXd x, v, a;
  double t = 0.0;
  double tEnd = -1.0;  // the end time of the step it belongs to (< 0: none kept)
  bool atEnd = true;   // the integrator's equilibrium is the end of its steps (nothing kept)

  template <class State>
  EquilibriumPoint of(const State& s) const {
    // The stepping may round a step's end onto an output time: a millionth of the distance
    // between the two points is a match.
    if (atEnd || tEnd < 0.0 || std::abs(s.t - tEnd) > 1e-6 * (tEnd - t))
      return EquilibriumPoint{s.x, s.v, s.a, s.t};
    return EquilibriumPoint{x, v, a, t};
  }
};

}  // namespace chute
