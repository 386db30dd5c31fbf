#include "kernels/UniformStrainPolyline.hpp"

#include <algorithm>
#include <cmath>

namespace chute::kernels {

template <int NumNodes>
PolylineResult<NumNodes> uniformStrainPolyline(const std::array<Vec3, NumNodes>& x, double L,
                                               const LineMaterial& mat, bool withTangent) {
  constexpr int kSeg = NumNodes - 1;
  PolylineResult<NumNodes> r;
  auto& e = r.segmentDirection;
  const double lMin = kMinSegmentFraction * L;

  r.length = 0.0;
  for (int k = 0; k < kSeg; ++k) {
    const Vec3 d = x[k + 1] - x[k];
    r.segmentLength[k] = d.norm();
    r.length += r.segmentLength[k];
    e[k] = r.segmentLength[k] > lMin ? Vec3(d / r.segmentLength[k]) : Vec3::Zero();
  }
  // Analytic limit l_k -> 0 (slider on an end node): the vanishing segment continues the cable
  // straight through, so it takes the direction of its longest neighbour. The combined force on
  // the coincident node pair is then exact; only the split between the two is a convention.
  for (int k = 0; k < kSeg; ++k) {
    if (r.segmentLength[k] > lMin) continue;
    int best = -1;
    for (int j : {k - 1, k + 1})
      if (j >= 0 && j < kSeg && r.segmentLength[j] > lMin &&
          (best < 0 || r.segmentLength[j] > r.segmentLength[best]))
        best = j;
    if (best >= 0) e[k] = e[best];
  }

  r.dLength.setZero();
  for (int k = 0; k < kSeg; ++k) {
    r.dLength.template segment<3>(3 * k) -= e[k];
    r.dLength.template segment<3>(3 * (k + 1)) += e[k];
  }

  const double L2 = L * L;
  r.strain = (r.length * r.length - L2) / (2.0 * L2);  // F1 / F6
  double Eeff = mat.E;
  if (r.strain < 0.0 && mat.tensionOnly) Eeff = mat.E * mat.compressionStiffnessRatio;
  // A cable at exactly zero strain is taken as slack: it carries nothing and has no stiffness.
  if (r.strain == 0.0 && mat.tensionOnly) Eeff = 0.0;

  const double EAoverL = Eeff * mat.area / L;
  r.axialForce = EAoverL * r.strain * r.length;  // F2: N = E A0 eps l / L
  r.energy = 0.5 * Eeff * mat.area * L * r.strain * r.strain;
  r.force = r.axialForce * r.dLength;  // F2 / F8: f = N D

  r.stiffness.setZero();
  if (!withTangent || Eeff == 0.0) return r;
  // F3 / F9: K = (E A0/L) [(eps + l^2/L^2) D D^T + eps l G]; G = sum_k h_k [I -I; -I I],
  // h_k = (I - e_k e_k^T) / l_k. eps l (E A0 / L) = N, so the geometric part is N G.
  r.stiffness.noalias() =
      EAoverL * (r.strain + r.length * r.length / L2) * (r.dLength * r.dLength.transpose());
  for (int k = 0; k < kSeg; ++k) {
    const double lk = std::max(r.segmentLength[k], lMin);
    const Mat3 h = r.axialForce * (Mat3::Identity() - e[k] * e[k].transpose()) / lk;
    r.stiffness.template block<3, 3>(3 * k, 3 * k) += h;
    r.stiffness.template block<3, 3>(3 * (k + 1), 3 * (k + 1)) += h;
    r.stiffness.template block<3, 3>(3 * k, 3 * (k + 1)) -= h;
    r.stiffness.template block<3, 3>(3 * (k + 1), 3 * k) -= h;
  }
  return r;
}

template PolylineResult<2> uniformStrainPolyline<2>(const std::array<Vec3, 2>&, double,
                                                    const LineMaterial&, bool);
template PolylineResult<3> uniformStrainPolyline<3>(const std::array<Vec3, 3>&, double,
                                                    const LineMaterial&, bool);

}  // namespace chute::kernels
