#include "kernels/MembraneKernels.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace chute::kernels {

// ---- material: relaxed plane-stress St Venant-Kirchhoff -------------------------------------
PlaneStress planeStressSVK(const Vec3& e, double E, double nu, bool wrinkling) {
  PlaneStress out;
  const double c = E / (1.0 - nu * nu);
  Mat3 D;
  D << c, c * nu, 0, c * nu, c, 0, 0, 0, c * (1.0 - nu) / 2.0;
  const double a = e[0], d = e[1], w = 0.5 * e[2], u = 0.5 * (a - d);
  const double R = std::sqrt(u * u + w * w);
  const double l1 = 0.5 * (a + d) + R, l2 = 0.5 * (a + d) - R;
  if (!wrinkling || l2 + nu * l1 > 0.0) {
    out.state = WrinkleState::Taut;
    out.stress = D * e;
    out.energy = 0.5 * e.dot(out.stress);
    out.tangent = D;
    return out;
  }
  if (l1 <= 0.0) {
    out.state = WrinkleState::Slack;
    out.stress.setZero();
    out.tangent.setZero();
    out.energy = 0.0;
    return out;
  }
  // Wrinkled: psi = E l1^2 / 2, l1 = (a + d)/2 + R(u, w), u = (a - d)/2, w = gamma/2. R > 0 here
  // because l2 <= -nu l1 < l1.
  out.state = WrinkleState::Wrinkled;
  const Vec3 g(0.5 + 0.5 * u / R, 0.5 - 0.5 * u / R, 0.5 * w / R);  // d l1 / de
  Eigen::Matrix<double, 2, 3> J;
  J << 0.5, -0.5, 0.0, 0.0, 0.0, 0.5;  // d(u, w)/de
  Eigen::Matrix2d H;                   // d2 R / d(u, w)^2
  H << w * w, -u * w, -u * w, u * u;
  H /= R * R * R;
  out.energy = 0.5 * E * l1 * l1;
  out.stress = E * l1 * g;
  out.tangent = E * (g * g.transpose() + l1 * J.transpose() * H * J);
  return out;
}

// ---- reference geometry ------------------------------------------------------------------------
namespace {
// Natural-coordinate shape functions and integration rules.
struct Rule3 {
  static constexpr int n = 1;
  static Eigen::Matrix<double, 3, 2> dNdXi(int) {
    Eigen::Matrix<double, 3, 2> d;
    d << -1, -1, 1, 0, 0, 1;
    return d;
  }
  static Eigen::Matrix<double, 3, 1> N(int) { return Eigen::Vector3d::Constant(1.0 / 3.0); }
  static double weight(int) { return 0.5; }
};
struct Rule4 {
  static constexpr int n = 4;
  static constexpr double g = 0.57735026918962576451;  // 1/sqrt(3)
  static Eigen::Vector2d point(int k) {
    const double xi[4] = {-g, g, g, -g}, eta[4] = {-g, -g, g, g};
    return {xi[k], eta[k]};
  }
  static Eigen::Matrix<double, 4, 2> dNdXi(int k) {
    const Eigen::Vector2d p = point(k);
    const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    Eigen::Matrix<double, 4, 2> d;
    for (int i = 0; i < 4; ++i) {
      d(i, 0) = 0.25 * sx[i] * (1 + sy[i] * p.y());
      d(i, 1) = 0.25 * sy[i] * (1 + sx[i] * p.x());
    }
    return d;
  }
  static Eigen::Matrix<double, 4, 1> N(int k) {
    const Eigen::Vector2d p = point(k);
    const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    Eigen::Matrix<double, 4, 1> n;
    for (int i = 0; i < 4; ++i) n[i] = 0.25 * (1 + sx[i] * p.x()) * (1 + sy[i] * p.y());
    return n;
  }
  static double weight(int) { return 1.0; }
};

template <int NumNodes, class Rule>
MembraneReference<NumNodes> buildReference(const std::array<Eigen::Vector2d, NumNodes>& X2,
                                           double thickness) {
  MembraneReference<NumNodes> ref;
  for (int k = 0; k < Rule::n; ++k) {
    const auto dNdXi = Rule::dNdXi(k);
    Eigen::Matrix2d J = Eigen::Matrix2d::Zero();  // J(alpha, beta) = dX_alpha / dxi_beta
    for (int i = 0; i < NumNodes; ++i) J += X2[i] * dNdXi.row(i);
    const double det = J.determinant();
    ref.dN[k] = dNdXi * J.inverse();
    ref.N[k] = Rule::N(k);
    ref.weight[k] = Rule::weight(k) * det * thickness;
    ref.area += Rule::weight(k) * det;
  }
  return ref;
}

// In-plane coordinates of the reference nodes in a frame with normal n.
template <int NumNodes>
std::array<Eigen::Vector2d, NumNodes> localCoordinates(const std::array<Vec3, NumNodes>& X,
                                                       const Vec3& n, double prestrain) {
  Vec3 e1 = X[1] - X[0];
  e1 -= e1.dot(n) * n;
  e1.normalize();
  const Vec3 e2 = n.cross(e1);
  std::array<Eigen::Vector2d, NumNodes> out;
  for (int i = 0; i < NumNodes; ++i) {
    const Vec3 r = X[i] - X[0];
    out[i] = Eigen::Vector2d(r.dot(e1), r.dot(e2)) / (1.0 + prestrain);
  }
  return out;
}
}  // namespace

MembraneReference<3> triangleReference(const std::array<Vec3, 3>& X, double thickness,
                                       double prestrain) {
  const Vec3 n = (X[1] - X[0]).cross(X[2] - X[0]).normalized();
  return buildReference<3, Rule3>(localCoordinates<3>(X, n, prestrain), thickness);
}

MembraneReference<4> quadReference(const std::array<Vec3, 4>& X, double thickness,
                                   double prestrain) {
  const Vec3 n = (X[2] - X[0]).cross(X[3] - X[1]).normalized();
  return buildReference<4, Rule4>(localCoordinates<4>(X, n, prestrain), thickness);
}

// ---- internal force and tangent (total Lagrangian) -----------------------------------------
template <int NumNodes>
MembraneResult<NumNodes> membraneForce(const std::array<Vec3, NumNodes>& x,
                                       const MembraneReference<NumNodes>& ref,
                                       const MembraneMaterial& mat, bool wrinkling,
                                       bool withTangent) {
  constexpr int kDofs = 3 * NumNodes;
  MembraneResult<NumNodes> r;
  r.force.setZero();
  r.stiffness.setZero();
  int worst = 0;
  for (int k = 0; k < MembraneReference<NumNodes>::kGauss; ++k) {
    const auto& dN = ref.dN[k];
    Eigen::Matrix<double, 3, 2> F = Eigen::Matrix<double, 3, 2>::Zero();  // dx / dX
    for (int i = 0; i < NumNodes; ++i) F += x[i] * dN.row(i);
    const Eigen::Matrix2d C = F.transpose() * F;
    const Vec3 e(0.5 * (C(0, 0) - 1.0), 0.5 * (C(1, 1) - 1.0), C(0, 1));  // (E11, E22, 2E12)
    const PlaneStress ps = planeStressSVK(e, mat.E, mat.nu, wrinkling);
    worst = std::max(worst, static_cast<int>(ps.state));
    // B: de = B dx; node i: (dN_i1 F1, dN_i2 F2, dN_i2 F1 + dN_i1 F2).
    Eigen::Matrix<double, 3, kDofs> B;
    for (int i = 0; i < NumNodes; ++i) {
      B.template block<1, 3>(0, 3 * i) = dN(i, 0) * F.col(0).transpose();
      B.template block<1, 3>(1, 3 * i) = dN(i, 1) * F.col(1).transpose();
      B.template block<1, 3>(2, 3 * i) =
          dN(i, 1) * F.col(0).transpose() + dN(i, 0) * F.col(1).transpose();
    }
    const double w = ref.weight[k];
    r.energy += w * ps.energy;
    r.force.noalias() += w * B.transpose() * ps.stress;
    if (withTangent) {
      r.stiffness.noalias() += w * B.transpose() * ps.tangent * B;
      Eigen::Matrix2d S;
      S << ps.stress[0], ps.stress[2], ps.stress[2], ps.stress[1];
      const Eigen::Matrix<double, NumNodes, NumNodes> G = dN * S * dN.transpose();
      for (int i = 0; i < NumNodes; ++i)
        for (int j = 0; j < NumNodes; ++j)
          r.stiffness.template block<3, 3>(3 * i, 3 * j).diagonal().array() += w * G(i, j);
    }
    Eigen::Matrix2d S;
    S << ps.stress[0], ps.stress[2], ps.stress[2], ps.stress[1];
    Eigen::Matrix2d Et;
    Et << e[0], 0.5 * e[2], 0.5 * e[2], e[1];
    const Eigen::Vector2d sv = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(S).eigenvalues();
    const Eigen::Vector2d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(Et).eigenvalues();
    r.principalStress += Eigen::Vector2d(sv[1], sv[0]) / MembraneReference<NumNodes>::kGauss;
    r.principalStrain += Eigen::Vector2d(ev[1], ev[0]) / MembraneReference<NumNodes>::kGauss;
  }
  r.state = static_cast<WrinkleState>(worst);
  return r;
}

template <int NumNodes>
Eigen::Matrix<double, NumNodes, NumNodes> membraneMass(const MembraneReference<NumNodes>& ref,
                                                       double density, bool lumped) {
  Eigen::Matrix<double, NumNodes, NumNodes> M = Eigen::Matrix<double, NumNodes, NumNodes>::Zero();
  if constexpr (NumNodes == 3) {
    // Exact for linear shape functions: rho t A / 12 (1 + delta_ij).
    const double m = density * ref.weight[0];
    M.setConstant(m / 12.0);
    M.diagonal().array() = m / 6.0;
  } else {
    for (int k = 0; k < MembraneReference<NumNodes>::kGauss; ++k)
      M += density * ref.weight[k] * ref.N[k] * ref.N[k].transpose();
  }
  if (lumped) {
    const Eigen::Matrix<double, NumNodes, 1> rows = M.rowwise().sum();
    M.setZero();
    M.diagonal() = rows;
  }
  return M;
}

// ---- follower pressure ---------------------------------------------------------------------
namespace {
Mat3 skew(const Vec3& v) {
  Mat3 s;
  s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return s;
}

// Three-point rule at the edge midpoints of the reference triangle (exact for quadratics): the
// product of a shape function and a linearly interpolated pressure.
struct Rule3Edges {
  static constexpr int n = 3;
  static Eigen::Matrix<double, 3, 2> dNdXi(int) { return Rule3::dNdXi(0); }
  static Eigen::Matrix<double, 3, 1> N(int k) {
    const double xi[3] = {0.5, 0.5, 0.0}, eta[3] = {0.0, 0.5, 0.5};
    return {1.0 - xi[k] - eta[k], xi[k], eta[k]};
  }
  static double weight(int) { return 1.0 / 6.0; }
};

// f_i = sum_k w_k p_k N_i(k) (x_,xi x x_,eta)(k) and its derivative; pressureAt(N) is the
// pressure at an integration point with shape-function values N.
template <int NumNodes, class Rule, class PressureAt>
PressureLoad<NumNodes> integratePressure(const std::array<Vec3, NumNodes>& x,
                                         PressureAt&& pressureAt, bool withTangent) {
  PressureLoad<NumNodes> out;
  out.force.setZero();
  out.dForce.setZero();
  for (int k = 0; k < Rule::n; ++k) {
    const auto dNdXi = Rule::dNdXi(k);
    const auto N = Rule::N(k);
    Vec3 a = Vec3::Zero(), b = Vec3::Zero();  // x_,xi and x_,eta
    for (int i = 0; i < NumNodes; ++i) a += x[i] * dNdXi(i, 0), b += x[i] * dNdXi(i, 1);
    const double w = Rule::weight(k) * pressureAt(N);
    const Vec3 n = a.cross(b);
    for (int i = 0; i < NumNodes; ++i) out.force.template segment<3>(3 * i) += w * N[i] * n;
    if (!withTangent) continue;
    // d(a x b) = -[b]x da + [a]x db, da = dN_k,xi dx_k, db = dN_k,eta dx_k.
    const Mat3 sa = skew(a), sb = skew(b);
    for (int kk = 0; kk < NumNodes; ++kk) {
      const Mat3 dn = -sb * dNdXi(kk, 0) + sa * dNdXi(kk, 1);
      for (int i = 0; i < NumNodes; ++i)
        out.dForce.template block<3, 3>(3 * i, 3 * kk) += w * N[i] * dn;
    }
  }
  return out;
}
}  // namespace

template <int NumNodes>
PressureLoad<NumNodes> pressureLoad(const std::array<Vec3, NumNodes>& x, double p,
                                    bool withTangent) {
  using Rule = std::conditional_t<NumNodes == 3, Rule3, Rule4>;
  return integratePressure<NumNodes, Rule>(
      x, [p](const Eigen::Matrix<double, NumNodes, 1>&) { return p; }, withTangent);
}

template <int NumNodes>
PressureLoad<NumNodes> pressureLoadNodal(const std::array<Vec3, NumNodes>& x,
                                         const Eigen::Matrix<double, NumNodes, 1>& p,
                                         bool withTangent) {
  using Rule = std::conditional_t<NumNodes == 3, Rule3Edges, Rule4>;
  return integratePressure<NumNodes, Rule>(
      x, [&p](const Eigen::Matrix<double, NumNodes, 1>& N) { return N.dot(p); }, withTangent);
}

template <int NumNodes>
Vec3 areaVector(const std::array<Vec3, NumNodes>& x) {
  if constexpr (NumNodes == 3) {
    return 0.5 * (x[1] - x[0]).cross(x[2] - x[0]);
  } else {
    return 0.5 * (x[2] - x[0]).cross(x[3] - x[1]);
  }
}

template <int NumNodes>
Eigen::Matrix<double, 3, 3 * NumNodes> areaVectorJacobian(const std::array<Vec3, NumNodes>& x) {
  // d(u x w) = -[w]x du + [u]x dw.
  Eigen::Matrix<double, 3, 3 * NumNodes> J;
  if constexpr (NumNodes == 3) {
    const Mat3 sa = skew(x[1] - x[0]), sb = skew(x[2] - x[0]);
    J << 0.5 * (sb - sa), -0.5 * sb, 0.5 * sa;
  } else {
    const Mat3 s1 = skew(x[2] - x[0]), s2 = skew(x[3] - x[1]);
    J << 0.5 * s2, -0.5 * s1, -0.5 * s2, 0.5 * s1;
  }
  return J;
}

// ---- line drag ---------------------------------------------------------------------------------
LineDrag lineDrag(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb, const Vec3& wind,
                  double coefficient, bool withTangent) {
  LineDrag out;
  out.residual.setZero();
  out.dPosition.setZero();
  out.dVelocity.setZero();
  const Vec3 d = xb - xa;
  const double l = d.norm();
  if (l == 0.0 || coefficient == 0.0) return out;
  const Vec3 e = d / l;
  const Mat3 P = Mat3::Identity() - e * e.transpose();
  const Vec3 v = 0.5 * (va + vb) - wind;
  const Vec3 u = P * v;  // normal relative velocity
  const double s = u.norm();
  // Residual (minus the drag force) on each node: (c l / 2) |u| u.
  const Vec3 r = 0.5 * coefficient * l * s * u;
  out.residual << r, r;
  if (!withTangent || s == 0.0) return out;
  const Mat3 dQdu = s * Mat3::Identity() + u * u.transpose() / s;  // d(|u| u)/du
  const Mat3 dv = 0.5 * coefficient * l * dQdu * P * 0.5;          // per node velocity
  const Mat3 dxb =
      0.5 * coefficient *
      (s * u * e.transpose() - dQdu * (e * v.transpose() + v.dot(e) * Mat3::Identity()) * P);
  for (int i = 0; i < 2; ++i) {
    out.dVelocity.block<3, 3>(3 * i, 0) = dv;
    out.dVelocity.block<3, 3>(3 * i, 3) = dv;
    out.dPosition.block<3, 3>(3 * i, 0) = -dxb;
    out.dPosition.block<3, 3>(3 * i, 3) = dxb;
  }
  return out;
}

template MembraneResult<3> membraneForce<3>(const std::array<Vec3, 3>&, const MembraneReference<3>&,
                                            const MembraneMaterial&, bool, bool);
template MembraneResult<4> membraneForce<4>(const std::array<Vec3, 4>&, const MembraneReference<4>&,
                                            const MembraneMaterial&, bool, bool);
template Eigen::Matrix<double, 3, 3> membraneMass<3>(const MembraneReference<3>&, double, bool);
template Eigen::Matrix<double, 4, 4> membraneMass<4>(const MembraneReference<4>&, double, bool);
template PressureLoad<3> pressureLoad<3>(const std::array<Vec3, 3>&, double, bool);
template PressureLoad<4> pressureLoad<4>(const std::array<Vec3, 4>&, double, bool);
template PressureLoad<3> pressureLoadNodal<3>(const std::array<Vec3, 3>&,
                                              const Eigen::Matrix<double, 3, 1>&, bool);
template PressureLoad<4> pressureLoadNodal<4>(const std::array<Vec3, 4>&,
                                              const Eigen::Matrix<double, 4, 1>&, bool);
template Vec3 areaVector<3>(const std::array<Vec3, 3>&);
template Vec3 areaVector<4>(const std::array<Vec3, 4>&);
template Eigen::Matrix<double, 3, 9> areaVectorJacobian<3>(const std::array<Vec3, 3>&);
template Eigen::Matrix<double, 3, 12> areaVectorJacobian<4>(const std::array<Vec3, 4>&);

}  // namespace chute::kernels
