#include "CalculixInp.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

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
  os << "*NODE, NSET=NALL\n";
  for (int n = 0; n < m.numNodes(); ++n)
    fmt::print(os, "{}, {:.17g}, {:.17g}, {:.17g}\n", id(n), m.X[n].x(), m.X[n].y(), m.X[n].z());
  int element = 0;
  os << "*ELEMENT, TYPE=M3D3, ELSET=CANOPY\n";
  for (const auto& e : m.membranes) {
    if (e.numNodes != 3) throw std::invalid_argument("the peer writer takes triangles only");
    fmt::print(os, "{}, {}, {}, {}\n", ++element, id(e.nodes[0]), id(e.nodes[1]), id(e.nodes[2]));
  }
  os << "*ELEMENT, TYPE=T3D2, ELSET=LINES\n";
  for (const auto& c : m.cables) fmt::print(os, "{}, {}, {}\n", ++element, id(c.a), id(c.b));
  fmt::print(os, "*NSET, NSET=PROBES\n{}, {}, {}\n", id(problem.probes.apex),
             id(problem.probes.rim), id(problem.probes.lineMid));
  fmt::print(os, "*NSET, NSET=FIXED\n{}\n", id(problem.confluence));

  const auto& fab = m.membraneMaterials.at(0);
  const auto& line = m.materials.at(0);
  fmt::print(os, "*MATERIAL, NAME=FABRIC\n*ELASTIC\n{:.17g}, {:.17g}\n*DENSITY\n{:.17g}\n", fab.E,
             fab.nu, fab.density);
  // nu = 0: a truss is uniaxial St Venant-Kirchhoff with a constant reference area, as in chute.
  fmt::print(os, "*MATERIAL, NAME=LINE\n*ELASTIC\n{:.17g}, 0.0\n*DENSITY\n{:.17g}\n", line.E,
             line.density);
  fmt::print(os, "*MEMBRANE SECTION, ELSET=CANOPY, MATERIAL=FABRIC\n{:.17g}\n", fab.thickness);
  fmt::print(os, "*SOLID SECTION, ELSET=LINES, MATERIAL=LINE\n{:.17g}\n", line.area);
  os << "*BOUNDARY\nFIXED, 1, 3\n";

  const auto& pl = m.pressures.at(0);
  const double tEnd = sv.tEnd;
  os << "*AMPLITUDE, NAME=RAMP\n";
  if (pl.rampTime > 0.0)
    fmt::print(os, "0.0, 0.0, {:.17g}, 1.0, {:.17g}, 1.0\n", pl.rampTime,
               std::max(2.0 * tEnd, 2.0 * pl.rampTime));
  else
    fmt::print(os, "0.0, 1.0, {:.17g}, 1.0\n", 2.0 * tEnd);
  const long increments = std::lround(tEnd / sv.dt);
  fmt::print(os, "*STEP, NLGEOM, INC={}\n*DYNAMIC, DIRECT, ALPHA={:.17g}\n{:.17g}, {:.17g}\n",
             increments + 10, options.alpha, sv.dt, tEnd);
  if (options.residualTolerance > 0.0 || options.correctionTolerance > 0.0) {
    // R_n, C_n; the remaining fields (q_0, q_u, R_P, eps, C_eps, R_l) at ccx's defaults.
    fmt::print(os,
               "*CONTROLS, PARAMETERS=FIELD, FIELD=DISPLACEMENT\n{:.6g}, {:.6g}, , , 0.02, "
               "1.e-5, 1.e-3, 1.e-8\n",
               options.residualTolerance > 0.0 ? options.residualTolerance : 0.005,
               options.correctionTolerance > 0.0 ? options.correctionTolerance : 0.01);
  }
  fmt::print(os, "*DLOAD, AMPLITUDE=RAMP\nCANOPY, {}, {:.17g}\n", kCalculixPressureFace,
             pl.pressure);
  os << "*NODE PRINT, NSET=PROBES, FREQUENCY=1\nU\n*END STEP\n";
}

}  // namespace chute::bench
