#include "kernels/SlidingCableKernel.hpp"

namespace chute::kernels {

namespace {
// Element dof order (1, 2, 3) <-> kernel path order (1, 3, 2): node of the element at path k.
constexpr int kPathNode[3] = {0, 2, 1};
}  // namespace

PolylineResult<3> slidingForce(const Vec3& x1, const Vec3& x2, const Vec3& x3, double L,
                               const LineMaterial& mat, bool withTangent) {
  const auto p = uniformStrainPolyline<3>({x1, x3, x2}, L, mat, withTangent);
  PolylineResult<3> r = p;  // scalars and segment data stay in path order (l1 = segment 0)
  for (int i = 0; i < 3; ++i) {
    const int ei = kPathNode[i];
    r.dLength.segment<3>(3 * ei) = p.dLength.segment<3>(3 * i);
    r.force.segment<3>(3 * ei) = p.force.segment<3>(3 * i);
    if (!withTangent) continue;  // the stiffness is set only withTangent
    for (int j = 0; j < 3; ++j)
      r.stiffness.block<3, 3>(3 * ei, 3 * kPathNode[j]) = p.stiffness.block<3, 3>(3 * i, 3 * j);
  }
  return r;
}

namespace {
// Split ratios r_i = l_i / l of the active element and their gradients in element dof order.
struct SplitRatios {
  double r1, r2;
  Vec9 dr1, dr2;
};

// The split ratios alone (the lumped mass needs no gradients): the same values as splitRatios,
// from the parts' lengths as uniformStrainPolyline<3> makes them on the path (1, slider, 2)
// (partLength: the exact length, or RG1's quadratic at the apex; l = 0 + l_1 + l_2), without
// the rest of the kernel (the explicit step's lumped M(x) 1 asks for them for every active
// sliding element at every step, where the whole kernel and its result's copies had been made).
void splitRatioValues(const Vec3& x1, const Vec3& x2, const Vec3& x3, double L, double& r1,
                      double& r2) {
  const double apex = kApexFraction * L;
  const double l1 = partLengthOnly(x3 - x1, apex), l2 = partLengthOnly(x2 - x3, apex);
  double length = 0.0;
  length += l1;
  length += l2;
  r1 = l1 / length;
  r2 = l2 / length;
}

SplitRatios splitRatios(const Vec3& x1, const Vec3& x2, const Vec3& x3, double L) {
  // Reuse the kernel's limit-safe geometry; material is irrelevant for lengths.
  const auto p = slidingForce(x1, x2, x3, L, LineMaterial{}, false);
  const double l1 = p.segmentLength[0], l2 = p.segmentLength[1], l = p.length;
  // Path segment 0 runs node 1 -> slider, segment 1 slider -> node 2 (element dofs 1, 2, 3).
  Vec9 dl1 = Vec9::Zero(), dl2 = Vec9::Zero();
  dl1.segment<3>(0) = -p.segmentGradient[0];
  dl1.segment<3>(6) = p.segmentGradient[0];
  dl2.segment<3>(3) = p.segmentGradient[1];
  dl2.segment<3>(6) = -p.segmentGradient[1];
  SplitRatios s;
  s.r1 = l1 / l;
  s.r2 = l2 / l;
  s.dr1 = (dl1 * l - l1 * p.dLength) / (l * l);
  s.dr2 = (dl2 * l - l2 * p.dLength) / (l * l);
  return s;
}
}  // namespace

SlidingInertia slidingInertia(const Vec3& x1, const Vec3& x2, const Vec3& x3, const Vec9& a,
                              double L, const LineMaterial& mat, MassKind kind) {
  const SplitRatios s = splitRatios(x1, x2, x3, L);
  const double m = mat.density * mat.area * L;  // total element mass, invariant
  const Mat3 I = Mat3::Identity();
  SlidingInertia out;
  out.mass.setZero();
  out.dForce.setZero();
  if (kind == MassKind::Lumped) {
    // F10 lumped: node 1 m r1/2, node 2 m r2/2, slider m/2.
    out.mass.block<3, 3>(0, 0) = 0.5 * m * s.r1 * I;
    out.mass.block<3, 3>(3, 3) = 0.5 * m * s.r2 * I;
    out.mass.block<3, 3>(6, 6) = 0.5 * m * I;
    out.force = out.mass * a;
    out.dForce.block<3, 9>(0, 0) = 0.5 * m * a.segment<3>(0) * s.dr1.transpose();
    out.dForce.block<3, 9>(3, 0) = 0.5 * m * a.segment<3>(3) * s.dr2.transpose();
  } else {
    // F10 consistent: (m/6) { r1 [2I 0 I; 0 0 0; I 0 2I] + r2 [0 0 0; 0 2I I; 0 I 2I] }.
    Mat9 B1 = Mat9::Zero(), B2 = Mat9::Zero();
    B1.block<3, 3>(0, 0) = 2 * I;
    B1.block<3, 3>(0, 6) = I;
    B1.block<3, 3>(6, 0) = I;
    B1.block<3, 3>(6, 6) = 2 * I;
    B2.block<3, 3>(3, 3) = 2 * I;
    B2.block<3, 3>(3, 6) = I;
    B2.block<3, 3>(6, 3) = I;
    B2.block<3, 3>(6, 6) = 2 * I;
    out.mass = (m / 6.0) * (s.r1 * B1 + s.r2 * B2);
    out.force = out.mass * a;
    out.dForce = (m / 6.0) * ((B1 * a) * s.dr1.transpose() + (B2 * a) * s.dr2.transpose());
  }
  return out;
}

Vec9 slidingInertiaForce(const Vec3& x1, const Vec3& x2, const Vec3& x3, const Vec9& a, double L,
                         const LineMaterial& mat, MassKind kind) {
  if (kind != MassKind::Lumped) return slidingInertia(x1, x2, x3, a, L, mat, kind).force;
  double r1 = 0.0, r2 = 0.0;
  splitRatioValues(x1, x2, x3, L, r1, r2);
  const double m = mat.density * mat.area * L;
  // The diagonal of slidingInertia's lumped M(x) (0.5 m r_i I), each row's one nonzero.
  const double d[3] = {0.5 * m * r1, 0.5 * m * r2, 0.5 * m};
  Vec9 f;
  for (int i = 0; i < 9; ++i) f[i] = d[i / 3] * a[i];
  return f;
}

SlidingGravity slidingGravity(const Vec3& x1, const Vec3& x2, const Vec3& x3, double L,
                              const LineMaterial& mat, const Vec3& g) {
  const SplitRatios s = splitRatios(x1, x2, x3, L);
  const double half = 0.5 * mat.density * mat.area * L;
  SlidingGravity out;
  // F11: node i gets rho A0 (L/l) l_i g / 2 = half r_i g; the slider half g.
  out.force << half * s.r1 * g, half * s.r2 * g, half * g;
  out.dForce.setZero();
  out.dForce.block<3, 9>(0, 0) = half * g * s.dr1.transpose();
  out.dForce.block<3, 9>(3, 0) = half * g * s.dr2.transpose();
  return out;
}

double sliderReferenceOffset(const Vec3& x1, const Vec3& x2, const Vec3& x3, double L) {
  const double l1 = (x3 - x1).norm(), l2 = (x3 - x2).norm();
  const double l = l1 + l2;
  return l > 0.0 ? L * l1 / l : 0.5 * L;
}

}  // namespace chute::kernels
