#include "kernels/SlidingDiscreteGradient.hpp"

#include <vector>

#include "kernels/PolylineDiscreteGradient.hpp"

namespace chute::kernels {

SlidingDiscreteGradientResult slidingDiscreteGradient(const std::array<Vec3, 3>& x0,
                                                      const std::array<Vec3, 3>& x1, double L,
                                                      const LineMaterial& mat, double chi,
                                                      bool withTangent) {
  // EM11 is EM12 on the path end 1 -> slider -> end 2: the part from the slider to end 2 is
  // traversed the other way, which negates its g and e exactly, so the force and tangent are
  // bit for bit those of the two parts written out. kPath: path position -> element node.
  constexpr int kPath[3] = {0, 2, 1};
  std::vector<Vec3> p0(3), p1(3);
  for (int i = 0; i < 3; ++i) p0[i] = x0[kPath[i]], p1[i] = x1[kPath[i]];
  const PolylineDiscreteGradientResult p =
      polylineDiscreteGradient(p0, p1, L, mat, chi, withTangent);
  SlidingDiscreteGradientResult r;
  r.strain0 = p.strain0, r.strain1 = p.strain1;
  r.energy0 = p.energy0, r.energy1 = p.energy1;
  for (int i = 0; i < 3; ++i) r.force.segment<3>(3 * kPath[i]) = p.force.segment<3>(3 * i);
  r.dForce.setZero();
  if (!withTangent) return r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      r.dForce.block<3, 3>(3 * kPath[i], 3 * kPath[j]) = p.dForce.block<3, 3>(3 * i, 3 * j);
  return r;
}

}  // namespace chute::kernels
