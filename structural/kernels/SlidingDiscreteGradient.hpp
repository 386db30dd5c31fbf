#pragma once
// Energy-momentum (discrete-gradient) internal force of an active sliding element without
// friction (docs/formulation.md EM11): node order (1, 2, 3), cable ends 1 and 2, slider 3, at the
// step's start and end. The energy W = c(E) E^2 / 2 depends on x only through the total length
// l = |d_1| + |d_2|, d_i = x_3 - x_i. Each part's length has the exact discrete gradient
//   |d_i,n+1| - |d_i,n| = g_i . (d_i,n+1 - d_i,n),  g_i = (d_i,n + d_i,n+1) / (|d_i,n| +
//   |d_i,n+1|),
// so l_{n+1} - l_n = D_alg . (x_{n+1} - x_n) with D_alg = [-g_1; -g_2; g_1 + g_2], and
//   f_alg = S_alg(E_n, E_{n+1}) (l_n + l_{n+1}) / (2 L^2) D_alg
// (S_alg of EM4, E_{n+1} - E_n = (l_n + l_{n+1}) (l_{n+1} - l_n) / (2 L^2)) gives
// W_{n+1} - W_n = f_alg . (x_{n+1} - x_n). Each g_i lies along its part's midpoint chord: the
// forces conserve linear and angular momentum (EM6). The apex rounding RG1 is not used (a part
// of zero length at both ends has g_i = 0).
#include "kernels/LineElementTypes.hpp"
#include "kernels/UniformStrainPolyline.hpp"

namespace chute::kernels {

struct SlidingDiscreteGradientResult {
  double strain0 = 0.0, strain1 = 0.0;
  double energy0 = 0.0, energy1 = 0.0;
  Vec9 force;   // EM11
  Mat9 dForce;  // d f_alg / d x_{n+1}
};

// x0: nodes (1, 2, 3) at the step's start, x1 at its end; chi: EM8's parameter.
SlidingDiscreteGradientResult slidingDiscreteGradient(const std::array<Vec3, 3>& x0,
                                                      const std::array<Vec3, 3>& x1, double L,
                                                      const LineMaterial& mat, double chi,
                                                      bool withTangent);

}  // namespace chute::kernels
