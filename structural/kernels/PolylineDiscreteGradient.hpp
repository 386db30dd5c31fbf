#pragma once
// Energy-momentum (discrete-gradient) internal force of a uniform-strain polyline (EM12,
// docs/formulation.md section 10): the condensed massless chain of a sliding group, path nodes in
// order (end, sliders along the chain, end). EM11 for any number of parts: the energy
// W = c(E) E^2 / 2 depends on x only through l = sum_k |d_k|, d_k = x_{k+1} - x_k; each part's
// length has the exact discrete gradient g_k = (d_k,n + d_k,n+1) / (|d_k,n| + |d_k,n+1|), so
// l_{n+1} - l_n = D_alg . (x_{n+1} - x_n) with D_alg the sum over parts of -g_k at node k and +g_k
// at node k + 1, and f_alg = S_alg (l_n + l_{n+1}) / (2 L^2) D_alg. Forces along midpoint chords:
// linear and angular momentum kept (EM6).
#include <Eigen/Core>
#include <vector>

#include "kernels/LineElementTypes.hpp"
#include "kernels/UniformStrainPolyline.hpp"

namespace chute::kernels {

struct PolylineDiscreteGradientResult {
  double strain0 = 0.0, strain1 = 0.0;
  double energy0 = 0.0, energy1 = 0.0;
  Eigen::VectorXd force;   // 3 N, path order
  Eigen::MatrixXd dForce;  // d force / d x_{n+1} (withTangent)
};

// x0, x1: the path nodes at the step's start and end; L: the chain's reference length; chi:
// EM8's parameter.
PolylineDiscreteGradientResult polylineDiscreteGradient(const std::vector<Vec3>& x0,
                                                        const std::vector<Vec3>& x1, double L,
                                                        const LineMaterial& mat, double chi,
                                                        bool withTangent);

// The point at the fraction phi of the arc length of the polyline P (uniform strain: a chain
// node of material coordinate S is at phi = S / L), and its derivative with respect to the path
// nodes' coordinates (3 x 3N) when dX is given.
Vec3 polylinePoint(const std::vector<Vec3>& P, double phi, Eigen::MatrixXd* dX);

}  // namespace chute::kernels
