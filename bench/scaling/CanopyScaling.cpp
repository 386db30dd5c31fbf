// Cost of a Newton iteration against problem size (issue 8, item 2): a pressurised flat
// circular canopy (structured disk of triangles, `rings` rings) with 28 suspension lines of
// 8 cable elements to a fixed confluence point, a few implicit dynamic steps from a bulged
// start. Prints one CSV row per size: dof, Newton iterations, time per iteration split into
// assembly / sliding search / factorisation / solve, and the floor: one numeric factorisation
// of the same (last) system matrix by the same SuiteSparse solver, timed alone (median of 5),
// and for scale CHOLMOD on the matrix's symmetric part. Wall times: run it on a quiet machine.
//
//   build/bin/bench_canopy_scaling [rings ...] > bench/results/scaling.csv
#include <fmt/core.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "StructuredMeshes.hpp"
#include "model/Model.hpp"
#include "solver/GeneralizedAlpha.hpp"
#include "solver/LinearSolver.hpp"
#include "solver/StructuralSystem.hpp"

using namespace chute;

namespace {

// A half-scale C-9-like canopy in ft, slug, s: diameter 14 ft, fabric E = 4.32e6 psf,
// t = 1e-3 ft (about 0.3 mm), density 0.6 slug/ft^3; lines E A = 4.32e6 * 1e-4 lbf, 11.5 ft.
Model canopyWithLines(int rings) {
  Model m;
  m.membraneMaterials.push_back({4.32e6, 0.3, 1e-3, 0.6});
  m.membraneMaterialName.push_back("fabric");
  m.membraneSets.push_back({"canopy", true, 0.0});
  const double R = 7.0;
  mesh::addDisk(m, "canopy", 0, 0, Vec3::Zero(), R, rings);
  const auto& rim = m.nodeSets.at("canopy.rim");
  // Bulged start over the flat pattern: the flat sheet has no stiffness across its plane.
  for (int n : m.nodeSets.at("canopy")) m.u0[n].z() += 0.5 * (1.0 - m.X[n].squaredNorm() / (R * R));

  kernels::LineMaterial line;
  line.E = 4.32e6;
  line.area = 1e-4;
  line.density = 0.6;
  line.tensionOnly = true;
  m.materials.push_back(line);
  m.materialName.push_back("line");
  m.lineSets.push_back({"lines", false});
  const int lines = 28, perLine = 8;
  const double lineLength = 11.5;
  const Vec3 apex(0.0, 0.0, -std::sqrt(lineLength * lineLength - R * R));
  const int confluence = m.addNode(apex, "confluence");
  m.constraint[confluence].fixed = {true, true, true};
  for (int k = 0; k < lines; ++k) {
    const int top = rim[static_cast<size_t>(k) * rim.size() / lines];
    int prev = top;
    const Vec3 a = m.X[top];
    for (int e = 1; e <= perLine; ++e) {
      const int next = e == perLine ? confluence : m.addNode(a + (apex - a) * e / double(perLine));
      if (e < perLine) m.u0[next] = m.u0[top] * (1.0 - e / double(perLine));
      m.cables.push_back({prev, next, (m.X[next] - m.X[prev]).norm(), 0, 0});
      prev = next;
    }
  }
  PressureLoadDef p;
  p.set = 0;
  p.pressure = 0.1;  // psf, the paper's C-9 internal pressure
  m.pressures.push_back(p);
  m.gravity = Vec3(0.0, 0.0, -32.2);
  return m;
}

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> sizes = {10, 15, 22, 32, 45, 65, 90, 130, 150};
  if (argc > 1) {
    sizes.clear();
    for (int i = 1; i < argc; ++i) sizes.push_back(std::atoi(argv[i]));
  }
  fmt::print(
      "rings,nodes,dof,nonzeros,linear_solver,steps,newton_iterations,assembly_s_per_it,"
      "search_s_per_it,factorisation_s_per_it,solve_s_per_it,total_s_per_it,"
      "floor_factorisation_s,ratio_to_floor,peak_rss_mb,cholmod_symmetric_part_s\n");
  for (int rings : sizes) {
    const Model m = canopyWithLines(rings);
    StructuralSystem sys(m, SliderSearch::MaterialCoordinate);
    NewtonSettings ns;
    ns.maxIterations = 25;
    ns.tolDisplacement = 1e-10 * 14.0;
    ns.nominalStep = 1e-3;
    ns.lengthScale = 14.0;
    GeneralizedAlpha integrator(sys, 0.9, AlphaScheme::Bossak, ns, 2e-4, 0.0);
    StructuralState s = sys.initialState();
    integrator.computeAcceleration(s);
    sys.commit(CommitPoint{s.x, s.t, 0.0, s.t});
    sys.timings() = Timings{};
    const int steps = 3;
    long iterations = 0;
    const auto t0 = std::chrono::steady_clock::now();
    // Steps of 2e-4 s from the bulged start; a step that fails is retried at half the size (as
    // chute run does), its iterations counted: the cost per iteration is what is measured.
    for (int k = 0; k < steps; ++k) {
      double h = 2e-4;
      for (;;) {
        const auto rep = integrator.tryStep(s, h);
        iterations += rep.iterations;
        if (rep.converged) break;
        h *= 0.5;
        if (h < 1e-7) {
          fmt::print(stderr, "rings {}: step {} failed: {}\n", rings, k, rep.failure);
          return 1;
        }
      }
    }
    const double total = seconds(t0) / iterations;
    const Timings t = sys.timings();
    // The floor: one numeric factorisation of the last matrix (the pattern analysed first).
    Timings scratch;
    LinearSolver floorSolver(sys.symmetric(), scratch);
    floorSolver.factorize(sys.matrix());
    std::vector<double> f;
    for (int r = 0; r < 5; ++r) {
      const auto t1 = std::chrono::steady_clock::now();
      floorSolver.factorize(sys.matrix());
      f.push_back(seconds(t1));
    }
    std::sort(f.begin(), f.end());  // the median of 5 is f[2]
    // For scale: CHOLMOD (supernodal, METIS/AMD) on the symmetric part, what a symmetric
    // system of this size and pattern would cost.
    double chol = 0.0;
    {
      SparseMatrix sym = SparseMatrix(sys.matrix().transpose());
      sym = 0.5 * (sym + sys.matrix());
      Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower> c;
      c.analyzePattern(sym);
      const auto t1 = std::chrono::steady_clock::now();
      c.factorize(sym);
      chol = seconds(t1);
      if (c.info() != Eigen::Success) chol = -chol;
    }
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    fmt::print(
        "{},{},{},{},{},{},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.3f},{:.1f},{:.6g}\n",
        rings, m.numNodes(), sys.numEquations(), sys.matrix().nonZeros(),
        integrator.linearSolver()->kindName(), steps, iterations, t.assembly / iterations,
        t.search / iterations, t.factorisation / iterations, t.solve / iterations, total, f[2],
        total / f[2], ru.ru_maxrss / 1024.0, chol);
    std::fflush(stdout);
  }
  return 0;
}
