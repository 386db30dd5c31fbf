#include "PackedStart.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace chute::mesh {

namespace {

using P2 = std::array<double, 2>;

double pointSegment(const P2& p, const P2& a, const P2& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
}

// Distance between two disjoint segments of a plane: an endpoint is nearest.
double segmentSegment(const P2& a, const P2& b, const P2& c, const P2& d) {
  return std::min(
      {pointSegment(a, c, d), pointSegment(b, c, d), pointSegment(c, a, b), pointSegment(d, a, b)});
}

constexpr double kRunFactor = 0.98;     // runs: cloth compressed 2 % along the run
constexpr double kCrossingSlack = 0.9;  // crossings: at least 1 / 0.9 the outer layer's path
constexpr double kInnerRadius = 0.4;    // inner seams of the star at 0.4 of the outer radius

}  // namespace

PackLayout packLayout(const ParachuteSpec& spec) {
  auto bad = [](const std::string& option, const std::string& why) {
    throw std::invalid_argument(option + ": " + why);
  };
  PackLayout l;
  const int n = l.gores = spec.gores;
  l.R = spec.diameter / 2;
  l.ventRadius = spec.ventDiameter / 2;
  l.H = std::sqrt(spec.lineLength * spec.lineLength - l.R * l.R);
  l.length = spec.packLength > 0 ? spec.packLength : spec.diameter / 12;
  l.diameter = spec.packDiameter > 0 ? spec.packDiameter : spec.diameter / 25;
  l.gap = spec.packGap > 0 ? spec.packGap : spec.diameter / 8500;
  const double W = l.diameter / std::sqrt(2.0);  // the square inscribed in the bag's section
  l.halfWidth = W / 2;
  const double cloth = l.R - l.ventRadius;  // pattern length of a meridian, skirt to vent
  const double h = spec.elementSize;

  // The fewest runs whose length fits the bag: U = (pitch - gap) / 2, crossings of at least one
  // element of cloth (well-shaped triangles), the first run longer by U + gap (the bottom
  // crossings clear the bag's mouth).
  for (int m = 1;; ++m) {
    if (m > 200) bad("--pack-length", "the canopy needs more than 200 runs: give a longer pack");
    l.runs = m;
    l.pitch = W / m;
    l.halfThickness = (l.pitch - l.gap) / 2;
    if (!(l.halfThickness > 0))
      bad("--pack-diameter", "too small: " + std::to_string(m) +
                                 " runs of the canopy side by side leave no room "
                                 "for their layers (give a larger --pack-diameter, a longer "
                                 "--pack-length or a smaller "
                                 "--pack-gap)");
    l.crossingCloth = m > 1 ? std::max(h, (l.pitch + 2 * l.halfThickness) / kCrossingSlack) : 0.0;
    l.firstRunExtra = m > 1 ? l.halfThickness + l.gap : 0.0;
    l.runCloth = (cloth - (m - 1) * l.crossingCloth - l.firstRunExtra / kRunFactor) / m;
    if (!(l.runCloth > 0))
      bad("--pack-length", "too short: the crossings between runs take up the whole canopy");
    const double top = l.firstRunExtra + kRunFactor * l.runCloth + (m > 1 ? l.halfThickness : 0);
    if (top <= l.length) break;
  }
  double s = 0.0;
  for (int i = 0; i + 1 < l.runs; ++i) {
    s += l.runCloth + (i == 0 ? l.firstRunExtra / kRunFactor : 0.0);
    l.foldRadii.push_back(l.R - s);
    s += l.crossingCloth;
    l.foldRadii.push_back(l.R - s);
  }

  // The star: seam k at angle 2 pi k / n, outer and inner seams alternately, flattened to the
  // half-thickness U (through the pack, the direction of the S-folds) and half-width V.
  for (int k = 0; k < n; ++k) {
    const double phi = 2.0 * std::numbers::pi * k / n, r = k % 2 == 0 ? 1.0 : kInnerRadius;
    l.polygon.push_back({l.halfThickness * r * std::sin(phi), l.halfWidth * r * std::cos(phi)});
  }
  l.minSeparation = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const P2 &a = l.polygon[i], &b = l.polygon[(i + 1) % n];
    l.maxEdge = std::max(l.maxEdge, std::hypot(b[0] - a[0], b[1] - a[1]));
    for (int j = i + 2; j < n; ++j) {
      if ((j + 1) % n == i) continue;  // adjacent through seam i
      l.minSeparation =
          std::min(l.minSeparation, segmentSegment(a, b, l.polygon[j], l.polygon[(j + 1) % n]));
    }
  }
  // The layers near the vent (the smallest hoop, where the star may be scaled down) stay `gap`
  // apart; without a vent they meet at the apex, as they must.
  const double dTheta = 2.0 * std::numbers::pi / n;
  const double ventScale =
      l.ventRadius > 0 ? std::min(1.0, l.hoopFactor * l.ventRadius * dTheta / l.maxEdge) : 1.0;
  if (l.minSeparation * ventScale < l.gap)
    bad("--pack-diameter",
        "the pleats of " + std::to_string(n) + " gores in " + std::to_string(l.runs) +
            " runs would be " + std::to_string(l.minSeparation * ventScale) +
            " apart, less than the gap " + std::to_string(l.gap) +
            " (give a larger --pack-diameter, a longer --pack-length or a smaller --pack-gap)");
  return l;
}

Vec3 packedPoint(const PackLayout& l, const Vec3& X, double c) {
  const int n = l.gores;
  const double dTheta = 2.0 * std::numbers::pi / n;
  const double rho = std::hypot(X.x(), X.y());
  double theta = std::atan2(X.y(), X.x());
  if (theta < 0) theta += 2.0 * std::numbers::pi;
  // The cross-section: the point's place on its gore's edge of the star, scaled down where the
  // hoop is shorter than the star's longest edge would allow.
  const int k = std::clamp(static_cast<int>(std::floor(theta / dTheta)), 0, n - 1);
  const double psi = theta / dTheta - k;
  const auto& a = l.polygon[k];
  const auto& b = l.polygon[(k + 1) % n];
  const double scale = std::min(1.0, l.hoopFactor * rho * dTheta / l.maxEdge);
  const double u = scale * ((1 - psi) * a[0] + psi * b[0]);
  const double v = scale * ((1 - psi) * a[1] + psi * b[1]);

  // The centreline: runs up and down (tangent +-z) joined by crossings (+x); normal n = y x t.
  const double s = std::clamp(l.R - rho, 0.0, l.R - l.ventRadius);
  const Vec3 ex = Vec3::UnitX(), ey = Vec3::UnitY(), ez = Vec3::UnitZ();
  auto normal = [&](const Vec3& t) { return Vec3(t.z(), 0.0, -t.x()); };
  Vec3 start(-(l.runs - 1) * l.pitch / 2, 0.0, l.H);
  double cloth0 = 0.0;
  const int segments = 2 * l.runs - 1;
  for (int i = 0; i < segments; ++i) {
    const bool run = i % 2 == 0;
    const int r = i / 2;
    const Vec3 t = run ? (r % 2 == 0 ? ez : Vec3(-ez)) : ex;
    const double cloth =
        run ? l.runCloth + (r == 0 ? l.firstRunExtra / kRunFactor : 0.0) : l.crossingCloth;
    // The first run's extra stretch (below the bottom crossings) keeps its length whatever c:
    // the crossings stay clear of the bag's mouth.
    const double length = run ? c * l.runCloth + (r == 0 ? l.firstRunExtra : 0.0) : l.pitch;
    const Vec3 end = start + length * t;
    if (s <= cloth0 + cloth || i == segments - 1) {
      const Vec3 tPrev = i == 0 ? t : (run ? ex : (r % 2 == 0 ? ez : Vec3(-ez)));
      const Vec3 tNext = i == segments - 1 ? t : (run ? ex : ((r + 1) % 2 == 0 ? ez : Vec3(-ez)));
      // Mitred ends: the layer at offset u turns at u (n_in + n_out) (90-degree creases).
      const Vec3 nStart = i == 0 ? normal(t) : Vec3(normal(tPrev) + normal(t));
      const Vec3 nEnd = i == segments - 1 ? normal(t) : Vec3(normal(t) + normal(tNext));
      const double f = std::clamp((s - cloth0) / cloth, 0.0, 1.0);
      return (1 - f) * (start + u * nStart) + f * (end + u * nEnd) + v * ey;
    }
    cloth0 += cloth;
    start = end;
  }
  return start;  // not reached
}

}  // namespace chute::mesh
