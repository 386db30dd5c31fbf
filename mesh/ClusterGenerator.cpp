#include "ClusterGenerator.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "MeshWriter.hpp"

namespace chute::mesh {

namespace {
// "_<i>" (appended, not concatenated: GCC 12 warns falsely on "_" + to_string).
std::string suffix(int i) {
  std::string s = "_";
  s += std::to_string(i);
  return s;
}
}  // namespace

void ClusterSpec::validate() const {
  auto bad = [](const std::string& option, const std::string& why) {
    throw std::invalid_argument(option + ": " + why);
  };
  if (canopies != 2 && canopies != 3) bad("--canopies", "expected 2 or 3");
  for (const auto& [option, x] : {std::pair<const char*, double>{"--spacing", spacing},
                                  {"--riser-length", riserLength},
                                  {"--payload-mass", payloadMass}})
    if (!std::isfinite(x) || x < 0.0 || x > 1e6) bad(option, "must be in [0, 1e6]");
  if (riserElements < 1 || riserElements > 10000) bad("--riser-elements", "must be in [1, 10000]");
  if (parachute.payloadMass > 0.0 || parachute.hasBox())
    bad("--payload-box", "a cluster carries a point payload (--payload-mass) on its risers");
  // The risers checked as a parachute's (ParachuteSpec::validate: 0, the default of a third of
  // the lines, or at least D/1000, in elements at least a tenth of the canopy's): 1e-9 gave a
  // case whose step no run can take.
  ParachuteSpec withRisers = parachute;
  withRisers.riserLength = riserLength;
  withRisers.riserElements = riserElements;
  withRisers.validate();
  if (spacing > 0.0 && spacing < 0.1 * parachute.diameter)
    bad("--spacing",
        "less than a tenth of the diameter: the canopies would start inside each other");
}

GeneratedCluster generateCluster(const ClusterSpec& spec, const std::string& msh) {
  spec.validate();
  GeneratedCluster out;
  out.single = generateParachute(spec.parachute, "");
  const GmshMesh& one = out.single.mesh;
  const ParachuteSpec& p = spec.parachute;
  const int n = spec.canopies;
  const double R = p.diameter / 2, H = std::sqrt(p.lineLength * p.lineLength - R * R);
  out.spacing = spec.spacing > 0.0 ? spec.spacing : 0.7 * p.diameter;
  out.riserLength = spec.riserLength > 0.0 ? spec.riserLength : p.lineLength / 3;
  // Canopy centres on a circle of radius d about the vertical: neighbours `spacing` apart; the
  // centre is (riser + H) along the tilted axis, so sin(beta) = d / (riser + H).
  const double d = out.spacing / (2.0 * std::sin(std::numbers::pi / n));
  const double reach = out.riserLength + H;
  if (d >= reach) throw std::invalid_argument("--spacing: too wide for the risers and lines");
  out.tilt = std::asin(d / reach);

  std::size_t maxTag = 0;
  for (std::size_t t : one.nodeTags) maxTag = std::max(maxTag, t);
  const std::size_t stride = maxTag + 1;
  const auto& u0 = one.views.count("initial_displacement") ? one.views.at("initial_displacement")
                                                           : NodeVectors{};
  GmshMesh& m = out.mesh;
  const std::size_t confluence = one.group("confluence", 0)->nodes()[0];
  std::vector<std::size_t> confluences;
  for (int i = 0; i < n; ++i) {
    const double phi = 2.0 * std::numbers::pi * i / n;
    // Tilt about the horizontal axis normal to the azimuth, then turn to the azimuth.
    const Eigen::Matrix3d rot =
        (Eigen::AngleAxisd(phi, Vec3::UnitZ()) * Eigen::AngleAxisd(out.tilt, Vec3::UnitY()))
            .toRotationMatrix();
    const Vec3 shift = out.riserLength * (rot * Vec3::UnitZ());  // the confluence
    const std::size_t offset = stride * i;
    // The parachute's start moved rigidly so that its confluence stays at its reference point:
    // the riser starts straight at its length.
    const Vec3 uConfluence = u0.count(confluence) ? u0.at(confluence) : Vec3::Zero();
    const std::string tail = suffix(i + 1);
    for (size_t k = 0; k < one.nodeTags.size(); ++k) {
      const std::size_t tag = one.nodeTags[k] + offset;
      m.nodeTags.push_back(tag);
      m.coords.push_back(rot * one.coords[k] + shift);
      const auto it = u0.find(one.nodeTags[k]);
      m.views["initial_displacement"][tag] =
          rot * ((it != u0.end() ? it->second : Vec3::Zero()) - uConfluence);
    }
    for (const auto& g : one.groups) {
      MeshGroup copy = g;
      copy.name += tail;
      for (auto& e : copy.elements)
        for (auto& t : e) t += offset;
      m.groups.push_back(std::move(copy));
    }
    confluences.push_back(confluence + offset);
  }
  // The payload at the origin, a straight riser of riserElements elements to each confluence.
  std::size_t next = stride * n;
  const std::size_t payload = next++;
  m.nodeTags.push_back(payload);
  m.coords.push_back(Vec3::Zero());
  m.views["initial_displacement"][payload] = Vec3::Zero();
  MeshGroup all{"risers", 1, 0, {}};
  for (int i = 0; i < n; ++i) {
    m.buildIndex();
    const Vec3 top = m.at(confluences[i]);
    MeshGroup riser{"riser" + suffix(i + 1), 1, 0, {}};
    std::size_t prev = payload;
    for (int e = 1; e <= spec.riserElements; ++e) {
      std::size_t node = confluences[i];
      if (e < spec.riserElements) {
        node = next++;
        const double f = double(e) / spec.riserElements;
        m.nodeTags.push_back(node);
        m.coords.push_back(f * top);
        m.views["initial_displacement"][node] = Vec3::Zero();
      }
      riser.elements.push_back({prev, node});
      prev = node;
    }
    all.elements.insert(all.elements.end(), riser.elements.begin(), riser.elements.end());
    m.groups.push_back(riser);
  }
  m.groups.push_back(all);
  m.groups.push_back({"payload", 0, 0, {{payload}}});
  m.buildIndex();
  if (!msh.empty()) writeMesh(m, msh);
  return out;
}

}  // namespace chute::mesh
