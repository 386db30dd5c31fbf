#include "PeerProblem.hpp"

#include <cmath>
#include <map>
#include <stdexcept>

#include "StructuredMeshes.hpp"

namespace chute::bench {

namespace {
// O-grid disk of quadrilaterals in the plane z = 0, normals +z: the central square
// [-s, s]^2 (s = R / 2) of n x n cells and, on each of its sides, a block of n (around) x m
// (radial) cells whose radial lines run straight from the square's edge to the circle. Node
// "canopy.center" when n is even; node sets "canopy" and "canopy.rim" (counter-clockwise).
void addQuadDisk(Model& m, int set, int material, double R, int n, int layers) {
  const double s = 0.5 * R;
  std::map<std::pair<long, long>, int> byPosition;  // shared block edges made once
  auto& all = m.nodeSets["canopy"];
  auto node = [&](double x, double y) {
    const std::pair<long, long> key{std::lround(x * 1e9 / R), std::lround(y * 1e9 / R)};
    auto it = byPosition.find(key);
    if (it != byPosition.end()) return it->second;
    const int id = m.addNode(Vec3(x, y, 0.0), "canopy." + std::to_string(m.numNodes()));
    byPosition[key] = id;
    all.push_back(id);
    return id;
  };
  auto quad = [&](int a, int b, int c, int d) {
    MembraneElement e;
    e.nodes = {a, b, c, d};
    e.numNodes = 4;
    e.set = set;
    e.material = material;
    m.membranes.push_back(e);
  };
  std::vector<int> sq((n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      sq[j * (n + 1) + i] = node(s * (-1.0 + 2.0 * i / n), s * (-1.0 + 2.0 * j / n));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      quad(sq[j * (n + 1) + i], sq[j * (n + 1) + i + 1], sq[(j + 1) * (n + 1) + i + 1],
           sq[(j + 1) * (n + 1) + i]);
  std::vector<int>& rim = m.nodeSets["canopy.rim"];
  for (int b = 0; b < 4; ++b) {  // block on the side at angle b pi / 2 (b = 0: x = +s)
    const double c = std::cos(b * M_PI / 2), sn = std::sin(b * M_PI / 2);
    std::vector<int> g((n + 1) * (layers + 1));
    for (int j = 0; j <= n; ++j) {
      const double th = -M_PI / 4 + M_PI / 2 * j / n;
      const double xi = s, yi = s * (-1.0 + 2.0 * j / n);  // on the square's side
      const double xo = R * std::cos(th), yo = R * std::sin(th);
      for (int k = 0; k <= layers; ++k) {
        const double x = xi + (xo - xi) * k / layers, y = yi + (yo - yi) * k / layers;
        g[j * (layers + 1) + k] = node(c * x - sn * y, sn * x + c * y);
      }
      if (j < n) rim.push_back(g[j * (layers + 1) + layers]);
    }
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < layers; ++k)
        quad(g[j * (layers + 1) + k], g[j * (layers + 1) + k + 1],
             g[(j + 1) * (layers + 1) + k + 1], g[(j + 1) * (layers + 1) + k]);
  }
  const int centre = sq[(n / 2) * (n + 1) + n / 2];
  m.nodeByName.erase(m.nodeName[centre]);
  m.nodeName[centre] = "canopy.center";
  m.nodeByName["canopy.center"] = centre;
}
}  // namespace

PeerProblem buildPeerProblem(const PeerParams& p) {
  if (p.rings < 1 || (p.quads && (p.square < 2 || p.square % 2 != 0)) || p.lineStride < 0 ||
      p.lineElements < 2 || p.lineElements % 2 != 0 || p.steps < 1 || p.dt <= 0.0)
    throw std::invalid_argument(
        "peer problem: rings >= 1, stride >= 1, even line elements >= 2, "
        "steps >= 1 and dt > 0 required");
  PeerProblem out;
  CaseSpec& s = out.spec;
  s.name = "peer_canopy";
  s.units = "m, kg, s, N";
  Model& m = s.model;

  m.membraneMaterialName.push_back("fabric");
  m.membraneMaterials.push_back({p.fabricE, p.fabricNu, p.fabricThickness, p.fabricDensity});
  MembraneSet set;
  set.name = "canopy";
  set.wrinkling = false;  // CalculiX membranes carry compression: compare like with like
  m.membraneSets.push_back(set);
  if (p.quads)
    addQuadDisk(m, 0, 0, p.radius, p.square, p.rings);
  else
    mesh::addDisk(m, "canopy", 0, 0, Vec3::Zero(), p.radius, p.rings);
  // Stress-free shallow cap as the reference geometry.
  for (int n : m.nodeSets.at("canopy")) {
    const double r2 = m.X[n].head<2>().squaredNorm() / (p.radius * p.radius);
    m.X[n].z() = p.bulge * (1.0 - r2);
  }

  kernels::LineMaterial line;
  line.E = p.lineE;
  line.area = p.lineArea;
  line.density = p.lumpedLineMass ? 0.0 : p.lineDensity;
  line.tensionOnly = false;  // truss: CalculiX T3D2 carries compression too
  m.materialName.push_back("line");
  m.materials.push_back(line);
  m.lineSets.push_back({"lines", false});
  out.confluence = m.addNode(Vec3(0.0, 0.0, -p.confluenceDepth), "confluence");
  m.constraint[out.confluence].fixed = {true, true, true};

  const auto& rim = m.nodeSets.at("canopy.rim");
  if (p.lineStride == 0)  // membrane only: the rim held, the confluence left unconnected
    for (int n : rim) m.constraint[n].fixed = {true, true, true};
  for (size_t i = 0; p.lineStride > 0 && i < rim.size(); i += static_cast<size_t>(p.lineStride)) {
    const Vec3 a = m.X[rim[i]], b = m.X[out.confluence];
    int prev = rim[i];
    for (int k = 1; k <= p.lineElements; ++k) {
      const int next = k == p.lineElements
                           ? out.confluence
                           : m.addNode(a + (b - a) * double(k) / p.lineElements,
                                       "line" + std::to_string(i) + "." + std::to_string(k));
      const double L = (m.X[next] - m.X[prev]).norm();
      m.cables.push_back({prev, next, L, 0, 0});
      if (p.lumpedLineMass) {
        m.pointMass[prev] += 0.5 * p.lineDensity * p.lineArea * L;
        m.pointMass[next] += 0.5 * p.lineDensity * p.lineArea * L;
      }
      if (i == 0 && k == p.lineElements / 2) out.probes.lineMid = next;
      prev = next;
    }
  }
  out.probes.apex = m.nodeId("canopy.center");
  out.probes.rim = rim[0];
  if (out.probes.lineMid < 0) out.probes.lineMid = m.nodeSets.at("canopy")[1];  // no lines

  PressureLoadDef pl;
  pl.set = 0;
  pl.pressure = p.pressure;
  pl.rampTime = p.rampTime;
  m.pressures.push_back(pl);
  m.massKind = kernels::MassKind::Consistent;  // CalculiX's implicit dynamics: consistent mass

  s.solver.type = AnalysisType::Dynamic;
  s.solver.dt = p.dt;
  s.solver.tEnd = p.dt * p.steps;
  s.solver.rhoInf = p.rhoInf;
  s.solver.integrator = *integratorFromName(p.integrator);
  s.output.everySteps = 1;
  for (auto [name, node] : {std::pair<const char*, int>{"apex", out.probes.apex},
                            {"rim", out.probes.rim},
                            {"line_mid", out.probes.lineMid}}) {
    ProbeSpec pr;
    pr.name = name;
    pr.kind = ProbeKind::NodePosition;
    pr.node = node;
    s.output.probes.push_back(pr);
  }
  return out;
}

}  // namespace chute::bench
