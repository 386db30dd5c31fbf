#include "kernels/ContactPotential.hpp"

#include <Eigen/Geometry>
#include <cmath>

namespace chute::kernels {

namespace {

// A unit vector along v, or zero.
Vec3 unit(const Vec3& v) {
  const double n = v.norm();
  return n > 0.0 ? Vec3(v / n) : Vec3::Zero();
}

// The direction a pair at d = 0 is pushed: the triangle's normal, or the normal of both edges.
Vec3 fallbackNormal(ContactPairKind kind, const std::array<Vec3, 4>& x) {
  if (kind == ContactPairKind::PointTriangle) return unit((x[2] - x[1]).cross(x[3] - x[1]));
  return unit((x[1] - x[0]).cross(x[3] - x[2]));
}

}  // namespace

double mollifierThreshold(const Vec3& e1Reference, const Vec3& e2Reference) {
  return 1e-3 * e1Reference.squaredNorm() * e2Reference.squaredNorm();
}

// CT5. c = |e1|^2 |e2|^2 - (e1 . e2)^2 = |e1 x e2|^2, its derivatives with respect to the edge
// vectors, then to the nodes (e1 = a1 - a0, e2 = b1 - b0).
Mollifier edgeEdgeMollifier(const std::array<Vec3, 4>& x, double epsX, bool withHessian) {
  Mollifier out;
  const Vec3 e1 = x[1] - x[0], e2 = x[3] - x[2];
  const double c = e1.cross(e2).squaredNorm();
  if (!(c < epsX)) return out;
  const double q = c / epsX;
  out.value = (2.0 - q) * q;
  const double dm = (2.0 - 2.0 * q) / epsX;  // dm / dc
  const double e11 = e1.squaredNorm(), e22 = e2.squaredNorm(), e12 = e1.dot(e2);
  const Vec3 g1 = 2.0 * e22 * e1 - 2.0 * e12 * e2;  // dc / de1
  const Vec3 g2 = 2.0 * e11 * e2 - 2.0 * e12 * e1;  // dc / de2
  Vec12 gc;
  gc << -g1, g1, -g2, g2;
  out.gradient = dm * gc;
  if (!withHessian) return out;
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  Eigen::Matrix<double, 6, 6> he;  // d2c / d(e1, e2)^2
  he.block<3, 3>(0, 0) = 2.0 * e22 * I - 2.0 * e2 * e2.transpose();
  he.block<3, 3>(3, 3) = 2.0 * e11 * I - 2.0 * e1 * e1.transpose();
  he.block<3, 3>(0, 3) = 4.0 * e1 * e2.transpose() - 2.0 * e12 * I - 2.0 * e2 * e1.transpose();
  he.block<3, 3>(3, 0) = he.block<3, 3>(0, 3).transpose();
  Eigen::Matrix<double, 6, 12> S = Eigen::Matrix<double, 6, 12>::Zero();  // (e1, e2) = S x
  S.block<3, 3>(0, 0) = -I, S.block<3, 3>(0, 3) = I;
  S.block<3, 3>(3, 6) = -I, S.block<3, 3>(3, 9) = I;
  const double ddm = -2.0 / (epsX * epsX);
  out.hessian = ddm * gc * gc.transpose() + dm * S.transpose() * he * S;
  return out;
}

Distance pairDistance(ContactPairKind kind, const std::array<Vec3, 4>& x, bool withHessian) {
  const SquaredDistance s = kind == ContactPairKind::PointTriangle
                                ? pointTriangleDistance(x[0], x[1], x[2], x[3], withHessian)
                                : edgeEdgeDistance(x[0], x[1], x[2], x[3], withHessian);
  return unsignedDistance(s, s.value > 0.0 ? Vec3::Zero() : fallbackNormal(kind, x), withHessian);
}

double pairSquaredDistance(ContactPairKind kind, const std::array<Vec3, 4>& x) {
  return kind == ContactPairKind::PointTriangle
             ? pointTriangleSquaredDistance(x[0], x[1], x[2], x[3])
             : edgeEdgeSquaredDistance(x[0], x[1], x[2], x[3]);
}

PairResponse contactPair(ContactPairKind kind, const std::array<Vec3, 4>& x,
                         const std::array<Vec3, 4>& v, const ContactLaw& law, double epsX,
                         bool withTangent) {
  PairResponse out;
  const SquaredDistance s = kind == ContactPairKind::PointTriangle
                                ? pointTriangleDistance(x[0], x[1], x[2], x[3], withTangent)
                                : edgeEdgeDistance(x[0], x[1], x[2], x[3], withTangent);
  if (!(s.value < law.thickness * law.thickness)) return out;
  out.distance =
      unsignedDistance(s, s.value > 0.0 ? Vec3::Zero() : fallbackNormal(kind, x), withTangent);
  const Distance& d = out.distance;
  const double delta = law.thickness - d.value;  // > 0
  out.active = true;
  // CT4: P = 1/2 k delta^2, dP/dx = -k delta grad d, d2P/dx2 = k grad d grad d^T - k delta Hess d.
  const double k = law.stiffness;
  const double P = 0.5 * k * delta * delta;
  const Vec12 gradP = -k * delta * d.gradient;
  // CT6: r_d = g grad d with g = c (delta / dHat) min(ddot, 0).
  Vec12 vel;
  for (int i = 0; i < 4; ++i) vel.segment<3>(3 * i) = v[i];
  const double ddot = d.gradient.dot(vel);
  const bool damped = law.damping > 0.0 && ddot < 0.0;
  const double cd = damped ? law.damping / law.thickness : 0.0;
  const double g = cd * delta * ddot;
  Vec12 r = gradP + g * d.gradient;
  Mat12 rx, rv;
  if (withTangent) {
    rx = k * d.gradient * d.gradient.transpose() - k * delta * d.hessian;
    rv.setZero();
    if (damped) {
      // d g / dx = cd (-ddot grad d + delta Hess d v), d g / dv = cd delta grad d.
      const Vec12 gx = cd * (-ddot * d.gradient + delta * (d.hessian * vel));
      rx += d.gradient * gx.transpose() + g * d.hessian;
      rv = cd * delta * d.gradient * d.gradient.transpose();
    }
  }
  double m = 1.0;
  if (kind == ContactPairKind::EdgeEdge) {
    const Mollifier mo = edgeEdgeMollifier(x, epsX, withTangent);
    m = mo.value;
    if (withTangent) {
      // (m P)'' = m P'' + P' m'^T + m' P'^T + P m''; (m r_d)' = m r_d' + r_d m'^T.
      const Vec12 rd = g * d.gradient;
      rx = m * rx + gradP * mo.gradient.transpose() + mo.gradient * gradP.transpose() +
           P * mo.hessian + rd * mo.gradient.transpose();
      rv *= m;
    }
    r = m * r + P * mo.gradient;
  }
  out.energy = m * P;
  out.normalForce = m * k * delta;
  out.residual = r;
  if (withTangent) out.dPosition = rx, out.dVelocity = rv;
  return out;
}

}  // namespace chute::kernels
