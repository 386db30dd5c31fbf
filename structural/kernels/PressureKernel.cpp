#include "kernels/PressureKernel.hpp"

#include <Eigen/Geometry>
#include <type_traits>

#include "kernels/MembraneShapeRules.hpp"

namespace chute::kernels {

using shape_rules::Rule3;
using shape_rules::Rule4;

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
  if (withTangent) out.dForce.setZero();  // residual-only evaluations never read it
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

template PressureLoad<3> pressureLoad<3>(const std::array<Vec3, 3>&, double, bool);
template PressureLoad<4> pressureLoad<4>(const std::array<Vec3, 4>&, double, bool);
template PressureLoad<3> pressureLoadNodal<3>(const std::array<Vec3, 3>&,
                                              const Eigen::Matrix<double, 3, 1>&, bool);
template PressureLoad<4> pressureLoadNodal<4>(const std::array<Vec3, 4>&,
                                              const Eigen::Matrix<double, 4, 1>&, bool);
template Eigen::Matrix<double, 3, 9> areaVectorJacobian<3>(const std::array<Vec3, 3>&);
template Eigen::Matrix<double, 3, 12> areaVectorJacobian<4>(const std::array<Vec3, 4>&);

}  // namespace chute::kernels
