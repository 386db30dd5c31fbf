// peer_bench: builds the issue-8 peer problem (canopy membranes + truss lines, ramped follower
// pressure), optionally writes the same problem as a CalculiX deck, and runs it in chute a number
// of times, printing one JSON object (sizes, wall times, Newton iterations) and writing the probe
// displacements of the last run as CSV. bench/peer/run_peer.py drives it and CalculiX.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "CalculixInp.hpp"
#include "PeerProblem.hpp"
#include "app/RunCase.hpp"

int main(int argc, char** argv) {
  using namespace chute;
  bench::PeerParams p;
  bench::CalculixOptions ccx;
  std::string inpFile, csvFile;
  int runs = 1;
  CLI::App app{"issue 8 peer problem: chute run and CalculiX deck"};
  app.add_option("--rings", p.rings, "radial cells (quads) or disk rings (triangles)")
      ->check(CLI::PositiveNumber);
  app.add_option("--square", p.square, "quads: cells along the central square's side (even)");
  bool triangles = false, lineDensity = false;
  app.add_flag("--triangles", triangles, "addDisk triangles (CalculiX M3D3) instead of quads");
  app.add_flag("--line-density", lineDensity,
               "distributed truss mass instead of point masses at the line nodes");
  app.add_option("--stride", p.lineStride, "a line at every n-th rim node (0: no lines, rim fixed)")
      ->check(CLI::Range(0, 1000000));
  app.add_option("--line-elements", p.lineElements, "trusses per line (even)");
  app.add_option("--dt", p.dt, "time step")->check(CLI::PositiveNumber);
  app.add_option("--steps", p.steps, "number of steps")->check(CLI::PositiveNumber);
  app.add_option("--rho-inf", p.rhoInf, "chute rho_inf")->check(CLI::Range(0.0, 1.0));
  app.add_option("--integrator", p.integrator, "chute integrator")
      ->check(CLI::IsMember({"bossak", "generalized_alpha"}));
  app.add_option("--pressure", p.pressure, "pressure, Pa");
  app.add_option("--ramp", p.rampTime, "pressure ramp time, s");
  app.add_option("--bulge", p.bulge, "reference cap height, m");
  app.add_option("--alpha", ccx.alpha, "CalculiX HHT alpha in [-1/3, 0]");
  app.add_option("--ccx-rtol", ccx.residualTolerance, "CalculiX residual tolerance (0: default)");
  app.add_option("--ccx-ctol", ccx.correctionTolerance,
                 "CalculiX correction tolerance (0: default)");
  app.add_option("--write-inp", inpFile, "write the CalculiX deck here");
  app.add_option("--csv", csvFile, "write the probe displacements of the last chute run here");
  app.add_option("--runs", runs, "chute runs (0: only write the deck)")
      ->check(CLI::Range(0, 1000000));
  CLI11_PARSE(app, argc, argv);
  p.quads = !triangles;
  p.lumpedLineMass = !lineDensity;

  const bench::PeerProblem problem = bench::buildPeerProblem(p);
  const Model& m = problem.spec.model;
  if (!inpFile.empty()) {
    std::ofstream f(inpFile);
    bench::writeCalculixInp(f, problem, p, ccx);
    if (!f) {
      std::cerr << inpFile << ": cannot write\n";
      return 2;
    }
  }
  nlohmann::json out;
  out["nodes"] = m.numNodes();
  out["membranes"] = m.membranes.size();
  out["trusses"] = m.cables.size();
  out["lines"] = m.cables.size() / p.lineElements;
  out["dofs"] = 3 * m.numNodes();
  out["element"] = p.quads ? "quad" : "triangle";
  out["probe_nodes"] = {problem.probes.apex + 1, problem.probes.rim + 1,
                        problem.probes.lineMid + 1};
  std::vector<double> walls;
  RunResult r;
  for (int k = 0; k < runs; ++k) {
    r = runCase(problem.spec, RunOptions{});
    walls.push_back(r.wallTime);
  }
  if (runs > 0) {
    out["status"] = runStatusName(r.status);
    out["equations"] = r.equations;
    out["steps"] = r.steps;
    out["rejected_steps"] = r.rejectedSteps;
    out["newton_iterations"] = r.newtonIterations;
    out["linear_solver"] = r.linearSolver;
    out["wall_times"] = walls;
    out["split_last_run"] = {{"assembly", r.timings.assembly},
                             {"factorisation", r.timings.factorisation},
                             {"solve", r.timings.solve},
                             {"output", r.timings.output},
                             {"factorisations", r.timings.factorisations}};
    std::vector<double> sorted = walls;
    std::sort(sorted.begin(), sorted.end());
    out["wall_median"] = sorted[sorted.size() / 2];
    if (!csvFile.empty()) {
      std::ofstream f(csvFile);
      f.precision(17);
      f << "t";
      for (const auto& c : r.columns) f << ",u_" << c;
      f << "\n";
      const int probeNodes[3] = {problem.probes.apex, problem.probes.rim, problem.probes.lineMid};
      for (size_t i = 0; i < r.times.size(); ++i) {
        f << r.times[i];
        for (size_t c = 0; c < r.rows[i].size(); ++c)
          f << "," << r.rows[i][c] - m.X[probeNodes[c / 3]][c % 3];
        f << "\n";
      }
    }
  }
  std::cout << out.dump() << std::endl;
  return r.status == RunStatus::Completed || runs == 0 ? 0 : 3;
}
