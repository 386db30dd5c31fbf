#include "ParachuteStart.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "PackedStart.hpp"

namespace chute::mesh {

namespace {

// Largest principal stretch of the triangle (X0, X1, X2) -> (x0, x1, x2): sqrt of the largest
// eigenvalue of C = F^T F, F = Ds Dm^-1 on the reference triangle's own plane.
double maxStretch(const Vec3& X0, const Vec3& X1, const Vec3& X2, const Vec3& x0, const Vec3& x1,
                  const Vec3& x2) {
  const Vec3 d1 = X1 - X0, d2 = X2 - X0;
  const Vec3 e1 = d1.normalized(), e2 = d1.cross(d2).cross(d1).normalized();
  Eigen::Matrix2d Dm;
  Dm << d1.dot(e1), d2.dot(e1), d1.dot(e2), d2.dot(e2);
  Eigen::Matrix<double, 3, 2> Ds;
  Ds << x1 - x0, x2 - x0;
  const Eigen::Matrix<double, 3, 2> F = Ds * Dm.inverse();
  const Eigen::Matrix2d C = F.transpose() * F;
  const double tr = C.trace(), det = C.determinant();
  return std::sqrt(0.5 * tr + std::sqrt(std::max(0.0, 0.25 * tr * tr - det)));
}

std::size_t onlyNode(const GmshMesh& m, const std::string& group) {
  const MeshGroup* g = m.group(group, 0);
  if (!g || g->nodes().size() != 1) throw std::logic_error("no single-node group " + group);
  return g->nodes()[0];
}

}  // namespace

StartConfiguration parachuteStart(const ParachuteSpec& spec, const GmshMesh& m) {
  StartConfiguration out;
  const int n = spec.gores;
  const double R = spec.diameter / 2, L = spec.lineLength, H = std::sqrt(L * L - R * R);
  const bool folded = spec.start == "folded";
  const bool inflated = spec.start == "inflated";
  const bool packed = spec.start == "packed";
  const PackLayout pack = packed ? packLayout(spec) : PackLayout{};
  const bool mapped = folded || inflated || packed;  // the canopy moves
  // Inflated: the pattern radius rho becomes arc length lambda rho along the meridians of a
  // spherical cap of radius Rs (Rs sin(R / Rs) = ratio R: the skirt at the projected radius),
  // the skirt at height H. Meridians keep (lambda = 1) or lose length, hoops shorten: the fabric
  // starts stress-free (wrinkled), the gores' excess width taken up when pressure bulges them.
  double Rs = R;
  if (inflated) {
    const double target = spec.inflatedRatio * R;
    double lo = 2.0 * R / M_PI, hi = 1e6 * R;  // Rs sin(R/Rs) rises from 2R/pi to R
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      (mid * std::sin(R / mid) < target ? lo : hi) = mid;
    }
    Rs = 0.5 * (lo + hi);
  }
  const double eps = (spec.bundleRadius > 0.0 ? spec.bundleRadius : spec.diameter / 40) / R;
  const double drop = spec.sliderDrop > 0.0 ? spec.sliderDrop : L / 20;
  auto& u = out.displacement;

  // Canopy: the folded cone map, its axial factor lowered until no element stretches (the
  // interpolated map of a triangle can stretch a little more than the smooth map).
  const MeshGroup& canopy = *m.group("canopy", 2);
  const auto canopyNodes = canopy.nodes();
  auto fold = [&](const Vec3& X, double c) -> Vec3 {
    if (inflated) {
      const double rho = std::hypot(X.x(), X.y()), theta = std::atan2(X.y(), X.x());
      const double phi = c * rho / Rs, phiR = c * R / Rs;
      return Vec3(Rs * std::sin(phi) * std::cos(theta), Rs * std::sin(phi) * std::sin(theta),
                  H + Rs * (std::cos(phi) - std::cos(phiR)));
    }
    if (packed) return packedPoint(pack, X, c);
    if (!folded) return X;
    const double rho = std::hypot(X.x(), X.y());
    return Vec3(eps * X.x(), eps * X.y(), H + c * (R - rho));
  };
  double c = inflated ? 1.0 : packed ? 0.98 : 0.999 * std::sqrt(1.0 - eps * eps);
  for (int attempt = 0;; ++attempt) {
    double worst = 0.0;
    auto tri = [&](std::size_t a, std::size_t b, std::size_t d) {
      const Vec3 &A = m.at(a), &B = m.at(b), &D = m.at(d);
      worst = std::max(worst, maxStretch(A, B, D, fold(A, c), fold(B, c), fold(D, c)));
    };
    for (const auto& e : canopy.elements) {
      tri(e[0], e[1], e[2]);
      if (e.size() == 4) tri(e[0], e[2], e[3]);
    }
    out.maxStretch = mapped ? worst : 1.0;  // flat: the identity (round-off about 1)
    if (worst <= 1.0 || !mapped) break;
    if (attempt > 200) throw std::runtime_error(spec.start + " start: could not shape the canopy");
    c *= 0.995;
  }
  out.axialFactor = mapped ? c : 1.0;
  for (std::size_t t : canopyNodes) u[t] = fold(m.at(t), c) - m.at(t);

  // Slider: a rigid drop to sliderDrop below the skirt (which stays at height H).
  std::vector<Vec3> grommet;
  if (spec.hasSlider()) {
    const MeshGroup& slider = *m.group("slider", 2);
    double zRef = 0.0;
    for (std::size_t t : slider.nodes()) zRef = m.at(t).z();
    const Vec3 shift(0.0, 0.0, H - drop - zRef);
    for (std::size_t t : slider.nodes()) u[t] = shift;
    for (int k = 0; k < 4; ++k) {
      const std::size_t g = onlyNode(m, "grommet_" + std::to_string(k));
      grommet.push_back(m.at(g) + shift);
    }
  }

  // Confluence: on the axis, as high as the longest line allows, less lineSlack.
  const std::size_t confluence = onlyNode(m, "confluence");
  std::vector<std::vector<std::size_t>> chains(n);
  std::vector<Vec3> skirt(n);
  double longest = 0.0, reach = 0.0;
  for (int j = 0; j < n; ++j) {
    auto& ch = chains[j] = orderedChain(*m.group("line_" + std::to_string(j), 1));
    if (ch.front() == confluence) std::reverse(ch.begin(), ch.end());
    skirt[j] = m.at(ch.front()) + u.at(ch.front());
    // Inflated: straight from the skirt (the line's own start); folded / flat: over the axis.
    const Vec3 via = spec.hasSlider() ? grommet[grommetOfLine(j, n)]
                     : inflated       ? skirt[j]
                                      : Vec3(0, 0, skirt[j].z());
    longest = std::max(longest, (via - skirt[j]).norm());
    reach = std::max(reach, std::hypot(via.x(), via.y()));
  }
  const double zVia = spec.hasSlider() ? H - drop : H;
  const double rest = (1.0 - spec.lineSlack) * L - longest;
  if (!(rest > reach))
    throw std::invalid_argument(
        "--slider-drop: the lines cannot reach the confluence through the grommets (make the "
        "slider smaller, the drop shorter or the lines longer)");
  const Vec3 c0(0.0, 0.0, zVia - std::sqrt(rest * rest - reach * reach));
  u[confluence] = c0 - m.at(confluence);

  // Lines: skirt -> (grommet ->) confluence, nodes at their reference arc length scaled by
  // lambda = path / length <= 1 (every element shortened alike); a node that would sit on the
  // grommet is moved 0.4 % of its element off it, so each slider starts inside its element.
  for (int j = 0; j < n; ++j) {
    const auto& ch = chains[j];
    std::vector<double> S(ch.size(), 0.0);
    for (size_t i = 1; i < ch.size(); ++i) S[i] = S[i - 1] + (m.at(ch[i]) - m.at(ch[i - 1])).norm();
    std::vector<Vec3> path = {skirt[j]};
    if (spec.hasSlider()) path.push_back(grommet[grommetOfLine(j, n)]);
    path.push_back(c0);
    std::vector<double> arc(path.size(), 0.0);
    for (size_t i = 1; i < path.size(); ++i) arc[i] = arc[i - 1] + (path[i] - path[i - 1]).norm();
    const double lambda = arc.back() / S.back();
    std::vector<double> s(ch.size());
    for (size_t i = 0; i < ch.size(); ++i) s[i] = lambda * S[i];
    if (spec.hasSlider()) {
      const double a = arc[1];
      for (size_t i = 1; i + 1 < ch.size(); ++i) {
        const double le = std::min(S[i] - S[i - 1], S[i + 1] - S[i]);
        const double d = std::min(0.004 * lambda, 0.5 * (1.0 - lambda)) * le;
        if (std::abs(s[i] - a) < d) s[i] = s[i] <= a ? a - d : a + d;
      }
    }
    for (size_t i = 1; i + 1 < ch.size(); ++i) {
      size_t seg = 1;
      while (seg + 1 < path.size() && arc[seg] < s[i]) ++seg;
      const double f = (s[i] - arc[seg - 1]) / (arc[seg] - arc[seg - 1]);
      u[ch[i]] = path[seg - 1] + f * (path[seg] - path[seg - 1]) - m.at(ch[i]);
    }
  }

  // Payload and risers follow the confluence rigidly.
  for (const char* name : {"risers", "payload_box", "payload"})
    for (int dim : {0, 1})
      if (const MeshGroup* g = m.group(name, dim); g && g->dim == dim)
        for (std::size_t t : g->nodes())
          if (t != confluence) u[t] = c0 - m.at(confluence);
  for (std::size_t t : m.nodeTags) u.try_emplace(t, Vec3::Zero());
  // Inflated: the whole start moved rigidly so that the confluence stays at its reference point
  // (the origin): a payload rigged below it in a case file's [nodes] starts where it is written.
  if (inflated) {
    const Vec3 shift = -u.at(confluence);
    for (auto& [tag, d] : u) d += shift;
  }
  return out;
}

}  // namespace chute::mesh
