#include "CalculixInp.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

namespace chute::bench {

void writeCalculixInp(std::ostream& os, const PeerProblem& problem, const PeerParams& params,
                      const CalculixOptions& options) {
  if (options.alpha < -1.0 / 3.0 - 1e-12 || options.alpha > 0.0)
    throw std::invalid_argument("CalculiX HHT alpha must lie in [-1/3, 0]");
  const Model& m = problem.spec.model;
  const SolverSpec& sv = problem.spec.solver;
  auto id = [](int node) { return node + 1; };
  fmt::print(os, "*HEADING\nchute peer problem: canopy {} rings, {} lines x {} trusses\n",
             params.rings, m.cables.size() / params.lineElements, params.lineElements);
  // ccx reads at most 20 characters per number: 14 significant digits, round-off zeros as 0.
  double size = 0.0;
  for (const auto& x : m.X) size = std::max(size, x.cwiseAbs().maxCoeff());
  auto coord = [&](double v) { return std::abs(v) < 1e-14 * size ? 0.0 : v; };
  os << "*NODE, NSET=NALL\n";
  for (int n = 0; n < m.numNodes(); ++n)
    fmt::print(os, "{}, {:.14g}, {:.14g}, {:.14g}\n", id(n), coord(m.X[n].x()), coord(m.X[n].y()),
               coord(m.X[n].z()));
  int element = 0;
  // One element type for the canopy: M3D3 (CalculiX integrates its mass at one point, see
  // bench/peer/README.md) or M3D4 (2 x 2 points, chute's consistent quad mass exactly).
  const int nn = m.membranes.empty() ? 3 : m.membranes.front().numNodes;
  fmt::print(os, "*ELEMENT, TYPE={}, ELSET=CANOPY\n", nn == 3 ? "M3D3" : "M3D4");
  for (const auto& e : m.membranes) {
    if (e.numNodes != nn) throw std::invalid_argument("the peer writer takes one element type");
    fmt::print(os, "{}", ++element);
    for (int k = 0; k < nn; ++k) fmt::print(os, ", {}", id(e.nodes[k]));
    os << "\n";
  }
  if (!m.cables.empty()) {
    os << "*ELEMENT, TYPE=T3D2, ELSET=LINES\n";
    for (const auto& c : m.cables) fmt::print(os, "{}, {}, {}\n", ++element, id(c.a), id(c.b));
  }
  // Point masses (the lines' mass lumped at their nodes): one MASS element per node, one
  // element set per distinct mass.
  std::map<double, std::vector<int>> byMass;
  for (int n = 0; n < m.numNodes(); ++n)
    if (m.pointMass[n] > 0.0 && !m.constraint[n].fixed[0]) byMass[m.pointMass[n]].push_back(n);
  int massSet = 0;
  for (const auto& [mass, nodes] : byMass) {
    fmt::print(os, "*ELEMENT, TYPE=MASS, ELSET=PM{}\n", ++massSet);
    for (int n : nodes) fmt::print(os, "{}, {}\n", ++element, id(n));
  }
  fmt::print(os, "*NSET, NSET=PROBES\n{}, {}, {}\n", id(problem.probes.apex),
             id(problem.probes.rim), id(problem.probes.lineMid));
  os << "*NSET, NSET=FIXED\n";
  for (int n = 0; n < m.numNodes(); ++n)
    if (m.constraint[n].fixed[0]) fmt::print(os, "{}\n", id(n));

  const auto& fab = m.membraneMaterials.at(0);
  const auto& line = m.materials.at(0);
  fmt::print(os, "*MATERIAL, NAME=FABRIC\n*ELASTIC\n{:.14g}, {:.14g}\n*DENSITY\n{:.14g}\n", fab.E,
             fab.nu, fab.density);
  // nu = 0: a truss is uniaxial St Venant-Kirchhoff with a constant reference area, as in chute.
  fmt::print(os, "*MATERIAL, NAME=LINE\n*ELASTIC\n{:.14g}, 0.0\n*DENSITY\n{:.14g}\n", line.E,
             line.density);
  fmt::print(os, "*MEMBRANE SECTION, ELSET=CANOPY, MATERIAL=FABRIC\n{:.14g}\n", fab.thickness);
  if (!m.cables.empty())
    fmt::print(os, "*SOLID SECTION, ELSET=LINES, MATERIAL=LINE\n{:.14g}\n", line.area);
  massSet = 0;
  for (const auto& entry : byMass)
    fmt::print(os, "*MASS, ELSET=PM{}\n{:.14g}\n", ++massSet, entry.first);
  os << "*BOUNDARY\nFIXED, 1, 3\n";

  const auto& pl = m.pressures.at(0);
  const double tEnd = sv.tEnd;
  os << "*AMPLITUDE, NAME=RAMP\n";
  if (pl.rampTime > 0.0)
    fmt::print(os, "0.0, 0.0, {:.14g}, 1.0, {:.14g}, 1.0\n", pl.rampTime,
               std::max(2.0 * tEnd, 2.0 * pl.rampTime));
  else
    fmt::print(os, "0.0, 1.0, {:.14g}, 1.0\n", 2.0 * tEnd);
  const long increments = std::lround(tEnd / sv.dt);
  fmt::print(os, "*STEP, NLGEOM, INC={}\n*DYNAMIC, DIRECT, ALPHA={:.14g}\n{:.14g}, {:.14g}\n",
             increments + 10, options.alpha, sv.dt, tEnd);
  if (options.residualTolerance > 0.0 || options.correctionTolerance > 0.0) {
    // R_n, C_n; the remaining fields (q_0, q_u, R_P, eps, C_eps, R_l) at ccx's defaults.
    fmt::print(os,
               "*CONTROLS, PARAMETERS=FIELD, FIELD=DISPLACEMENT\n{:.6g}, {:.6g}, , , 0.02, "
               "1.e-5, 1.e-3, 1.e-8\n",
               options.residualTolerance > 0.0 ? options.residualTolerance : 0.005,
               options.correctionTolerance > 0.0 ? options.correctionTolerance : 0.01);
  }
  fmt::print(os, "*DLOAD, AMPLITUDE=RAMP\nCANOPY, {}, {:.14g}\n", kCalculixPressureFace,
             pl.pressure);
  os << "*NODE PRINT, NSET=PROBES, FREQUENCY=1\nU\n*END STEP\n";
}

}  // namespace chute::bench
