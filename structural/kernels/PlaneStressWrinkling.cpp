#include "kernels/PlaneStressWrinkling.hpp"

#include <cmath>

namespace chute::kernels {

// ---- material: relaxed plane-stress St Venant-Kirchhoff -------------------------------------
PlaneStress planeStressSVK(const Vec3& e, double E, double nu, bool wrinkling, bool withTangent) {
  PlaneStress out;
  const double a = e[0], d = e[1], w = 0.5 * e[2], u = 0.5 * (a - d);
  const double R = std::sqrt(u * u + w * w);
  const double l1 = 0.5 * (a + d) + R, l2 = 0.5 * (a + d) - R;
  if (!wrinkling || l2 + nu * l1 > 0.0) {
    // The plane-stress matrix only here: its division is a good part of a wrinkled or slack
    // point's cost otherwise.
    const double c = E / (1.0 - nu * nu);
    Mat3 D;
    D << c, c * nu, 0, c * nu, c, 0, 0, 0, c * (1.0 - nu) / 2.0;
    out.state = WrinkleState::Taut;
    out.stress = D * e;
    out.energy = 0.5 * e.dot(out.stress);
    if (withTangent) out.tangent = D;
    return out;
  }
  if (l1 <= 0.0) {
    out.state = WrinkleState::Slack;
    out.stress.setZero();
    if (withTangent) out.tangent.setZero();
    out.energy = 0.0;
    return out;
  }
  // Wrinkled: psi = E l1^2 / 2, l1 = (a + d)/2 + R(u, w), u = (a - d)/2, w = gamma/2. R > 0 here
  // because l2 <= -nu l1 < l1.
  out.state = WrinkleState::Wrinkled;
  const Vec3 g(0.5 + 0.5 * u / R, 0.5 - 0.5 * u / R, 0.5 * w / R);  // d l1 / de
  out.energy = 0.5 * E * l1 * l1;
  out.stress = E * l1 * g;
  if (!withTangent) return out;
  Eigen::Matrix<double, 2, 3> J;
  J << 0.5, -0.5, 0.0, 0.0, 0.0, 0.5;  // d(u, w)/de
  Eigen::Matrix2d H;                   // d2 R / d(u, w)^2
  H << w * w, -u * w, -u * w, u * u;
  H /= R * R * R;
  out.tangent = E * (g * g.transpose() + l1 * J.transpose() * H * J);
  return out;
}

}  // namespace chute::kernels
