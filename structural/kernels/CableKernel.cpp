#include "kernels/CableKernel.hpp"

#include <algorithm>
#include <cmath>

namespace chute::kernels {

PolylineResult<2> cableForce(const Vec3& xa, const Vec3& xb, double L, const LineMaterial& mat,
                             bool withTangent) {
  return uniformStrainPolyline<2>({xa, xb}, L, mat, withTangent);
}

Mat6 cableMass(double L, const LineMaterial& mat, MassKind kind) {
  const double m = mat.density * mat.area * L;
  Mat6 M = Mat6::Zero();
  const Mat3 I = Mat3::Identity();
  if (kind == MassKind::Lumped) {  // F4, lumped: (rho A0 L / 2) diag(I, I)
    M.block<3, 3>(0, 0) = 0.5 * m * I;
    M.block<3, 3>(3, 3) = 0.5 * m * I;
  } else {  // F4, consistent: (rho A0 L / 6) [2I I; I 2I]
    M.block<3, 3>(0, 0) = (m / 3.0) * I;
    M.block<3, 3>(3, 3) = (m / 3.0) * I;
    M.block<3, 3>(0, 3) = (m / 6.0) * I;
    M.block<3, 3>(3, 0) = (m / 6.0) * I;
  }
  return M;
}

Vec6 cableGravity(double L, const LineMaterial& mat, const Vec3& g) {
  Vec6 f;
  const double half = 0.5 * mat.density * mat.area * L;
  f << half * g, half * g;
  return f;
}

double slackTautCrossing(const Vec3& d, const Vec3& delta, double L) {
  // q(f) = |d + f delta|^2 - L^2 = A f^2 + 2 B f + C is convex in f: with opposite signs at
  // f = 0 and f = 1 it has exactly one root in between.
  const double band = kSlackTautBand * L;
  const double l0 = d.norm(), l1 = (d + delta).norm();
  if (std::abs(l0 - L) <= band || std::abs(l1 - L) <= band || (l0 < L) == (l1 < L)) return 1.0;
  const double A = delta.squaredNorm(), B = d.dot(delta), C = (l0 - L) * (l0 + L);
  const double s = std::sqrt(std::max(0.0, B * B - A * C));
  // Cancellation-free forms of the larger root (slack -> taut, C < 0) and the smaller one
  // (taut -> slack, C > 0).
  const double f = C < 0.0 ? -C / (B + s) : C / (s - B);
  return std::clamp(f, 0.0, 1.0);
}

}  // namespace chute::kernels
