#include "ElementShape.hpp"

#include <Eigen/Geometry>
#include <algorithm>

namespace chute::mesh {

std::string ShapeProblem::text(const std::string& nodeName) const {
  std::string out = why;
  if (const auto at = out.find('%'); at != std::string::npos) out.replace(at, 1, nodeName);
  return out;
}

ShapeProblem elementShapeProblem(const Vec3* x, const std::size_t* ids, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (ids[i] == ids[j]) return {"node % appears twice", j};
  double edge2 = 0.0;
  for (int i = 0; i < n; ++i) edge2 = std::max(edge2, (x[(i + 1) % n] - x[i]).squaredNorm());
  if (edge2 == 0.0) return {"zero size (its nodes are at one point)", -1};
  if (n == 2) return {};
  const double tol = 1e-12 * edge2;
  auto X = [&](int i) { return x[(i + n) % n]; };
  if (n == 3) {
    if ((X(1) - X(0)).cross(X(2) - X(0)).norm() <= tol)
      return {"zero area (its nodes are collinear)", -1};
    return {};
  }
  const Vec3 normal = (X(2) - X(0)).cross(X(3) - X(1));
  if (normal.norm() <= tol) return {"zero area (its diagonals are parallel)", -1};
  const Vec3 unit = normal.normalized();
  for (int i = 0; i < 4; ++i) {
    const double turn = (X(i + 1) - X(i)).cross(X(i - 1) - X(i)).dot(unit);
    if (turn <= tol)
      return {turn >= -tol ? "not convex at node % (a straight corner: three nodes collinear)"
                           : "not convex at node % (nodes must go round the element, "
                             "counter-clockwise about its normal: a bow-tie or a reflex corner)",
              i};
  }
  return {};
}

}  // namespace chute::mesh
