#include "PeerProblem.hpp"

#include <stdexcept>

#include "StructuredMeshes.hpp"

namespace chute::bench {

PeerProblem buildPeerProblem(const PeerParams& p) {
  if (p.rings < 1 || p.lineStride < 1 || p.lineElements < 2 || p.lineElements % 2 != 0 ||
      p.steps < 1 || p.dt <= 0.0)
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
  mesh::addDisk(m, "canopy", 0, 0, Vec3::Zero(), p.radius, p.rings);
  // Stress-free shallow cap as the reference geometry.
  for (int n : m.nodeSets.at("canopy")) {
    const double r2 = m.X[n].head<2>().squaredNorm() / (p.radius * p.radius);
    m.X[n].z() = p.bulge * (1.0 - r2);
  }

  kernels::LineMaterial line;
  line.E = p.lineE;
  line.area = p.lineArea;
  line.density = p.lineDensity;
  line.tensionOnly = false;  // truss: CalculiX T3D2 carries compression too
  m.materialName.push_back("line");
  m.materials.push_back(line);
  m.lineSets.push_back({"lines", false});
  out.confluence = m.addNode(Vec3(0.0, 0.0, -p.confluenceDepth), "confluence");
  m.constraint[out.confluence].fixed = {true, true, true};

  const auto& rim = m.nodeSets.at("canopy.rim");
  for (size_t i = 0; i < rim.size(); i += static_cast<size_t>(p.lineStride)) {
    const Vec3 a = m.X[rim[i]], b = m.X[out.confluence];
    int prev = rim[i];
    for (int k = 1; k <= p.lineElements; ++k) {
      const int next = k == p.lineElements
                           ? out.confluence
                           : m.addNode(a + (b - a) * double(k) / p.lineElements,
                                       "line" + std::to_string(i) + "." + std::to_string(k));
      m.cables.push_back({prev, next, (m.X[next] - m.X[prev]).norm(), 0, 0});
      if (i == 0 && k == p.lineElements / 2) out.probes.lineMid = next;
      prev = next;
    }
  }
  out.probes.apex = m.nodeId("canopy.center");
  out.probes.rim = rim[0];

  PressureLoadDef pl;
  pl.set = 0;
  pl.pressure = p.pressure;
  pl.rampTime = p.rampTime;
  m.pressures.push_back(pl);
  m.massKind = kernels::MassKind::Consistent;  // CalculiX's implicit dynamics: consistent mass

  s.solver.type = "dynamic";
  s.solver.dt = p.dt;
  s.solver.tEnd = p.dt * p.steps;
  s.solver.rhoInf = p.rhoInf;
  s.solver.integrator = p.integrator;
  s.output.everySteps = 1;
  for (auto [name, node] : {std::pair<const char*, int>{"apex", out.probes.apex},
                            {"rim", out.probes.rim},
                            {"line_mid", out.probes.lineMid}}) {
    ProbeSpec pr;
    pr.name = name;
    pr.kind = "node_position";
    pr.node = node;
    s.output.probes.push_back(pr);
  }
  return out;
}

}  // namespace chute::bench
