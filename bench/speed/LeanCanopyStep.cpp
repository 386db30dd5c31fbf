// chute's explicit step per canopy triangle against a lean, fused canopy loop on the same mesh
// (the real-time issue, item 5). The lean loop is what the arithmetic of a canopy step needs: one
// pass over the triangles, each gathered once (positions, velocities), its constant-strain St
// Venant-Kirchhoff membrane with a tension-field wrinkling test written without branches, the
// follower pressure and the face drag, and one scatter of its three nodal forces. It is a floor
// for the cost, not a second solver: no lines, no sliding, no stable-step estimate, no energy.
//
// chute's step is timed whole (every term of the case, the update, the energy balance, the stable
// step) by running the case twice to two end times and taking the difference, so set-up cancels.
// Both are CPU times of this thread (chute's run with CHUTE_THREADS=1), medians of `--repeat`
// measurements.
//
//   build/bin/bench_lean_canopy_step CASE.toml [--steps 400] [--repeat 5]
// prints one JSON object: triangles, ns per triangle for the lean loop and for chute's step,
// their ratio, steps per simulated second, CPU per simulated second.
#include <fmt/core.h>
#include <fmt/format.h>
#include <sys/resource.h>
#include <time.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "app/RunCase.hpp"
#include "case/CaseSpec.hpp"

using namespace chute;

namespace {

// This thread's CPU time: the process's would count the BLAS library's worker, which spins for
// about 0.1 s after start-up (it inflated the first lean measurement of each run 1.5-2x).
// CHUTE_THREADS=1 keeps chute's step on this thread.
double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// A triangle as the lean loop keeps it: node ids, the inverse of its reference edge matrix in
// its own plane, its reference area, and its material's plane-stress constants (thickness in).
struct LeanTriangle {
  std::array<int, 3> n;
  double di00, di01, di10, di11, area0, k, nu;
};

struct LeanCanopy {
  std::vector<LeanTriangle> tri;
  double pressure = 0.0, drag = 0.0;  // follower pressure; (1/2) rho Cd of the face drag
  std::array<double, 3> wind{0.0, 0.0, 0.0};
};

LeanCanopy leanCanopy(const Model& m) {
  LeanCanopy c;
  for (const auto& e : m.membranes) {
    if (e.numNodes != 3) continue;
    const Eigen::Vector3d X0 = m.X[e.nodes[0]], X1 = m.X[e.nodes[1]], X2 = m.X[e.nodes[2]];
    const Eigen::Vector3d a = X1 - X0, b = X2 - X0;
    const Eigen::Vector3d e1 = a.normalized(), e2 = a.cross(b).cross(a).normalized();
    const double p1x = a.norm(), p2x = b.dot(e1), p2y = b.dot(e2);
    const double det = p1x * p2y;  // Dm = [[p1x, p2x], [0, p2y]]
    if (!(std::abs(det) > 0.0)) continue;
    const auto& mat = m.membraneMaterials[e.material];
    LeanTriangle t;
    t.n = {e.nodes[0], e.nodes[1], e.nodes[2]};
    t.di00 = p2y / det, t.di01 = -p2x / det, t.di10 = 0.0, t.di11 = p1x / det;
    t.area0 = 0.5 * std::abs(det);
    t.k = mat.E * mat.thickness / (1.0 - mat.nu * mat.nu);
    t.nu = mat.nu;
    c.tri.push_back(t);
  }
  if (!m.pressures.empty()) c.pressure = m.pressures.front().pressure;
  if (c.pressure == 0.0) c.pressure = 1.0;
  if (!m.faceDrags.empty()) {
    c.drag = m.faceDrags.front().coefficient;
    for (int k = 0; k < 3; ++k) c.wind[k] = m.faceDrags.front().wind[k];
  }
  if (c.drag == 0.0) c.drag = 0.5 * 1.2 * 1.2;
  return c;
}

// One pass over the triangles: gather, compute, scatter into f (zeroed by the caller).
void leanPass(const LeanCanopy& c, const double* x, const double* v, double* f) {
  const double third = 1.0 / 3.0;
  for (const LeanTriangle& t : c.tri) {
    const double* x0 = x + 3 * t.n[0];
    const double* x1 = x + 3 * t.n[1];
    const double* x2 = x + 3 * t.n[2];
    double d1[3], d2[3], f1[3], f2[3];
    for (int k = 0; k < 3; ++k) {
      d1[k] = x1[k] - x0[k], d2[k] = x2[k] - x0[k];
      f1[k] = d1[k] * t.di00 + d2[k] * t.di10;  // F = [d1 d2] Dm^-1
      f2[k] = d1[k] * t.di01 + d2[k] * t.di11;
    }
    const double c11 = f1[0] * f1[0] + f1[1] * f1[1] + f1[2] * f1[2];
    const double c22 = f2[0] * f2[0] + f2[1] * f2[1] + f2[2] * f2[2];
    const double c12 = f1[0] * f2[0] + f1[1] * f2[1] + f1[2] * f2[2];
    const double e11 = 0.5 * (c11 - 1.0), e22 = 0.5 * (c22 - 1.0), e12 = 0.5 * c12;
    double s11 = t.k * (e11 + t.nu * e22), s22 = t.k * (e22 + t.nu * e11);
    double s12 = t.k * (1.0 - t.nu) * e12;
    // Tension field without branches: taut (s2 >= 0) keeps S; wrinkled (s1 > 0 > s2) keeps the
    // uniaxial part s1 d d^T along the first principal direction; slack (s1 <= 0) none.
    const double mean = 0.5 * (s11 + s22), half = 0.5 * (s11 - s22);
    const double r = std::sqrt(half * half + s12 * s12);
    const double s1 = mean + r, s2 = mean - r;
    const double taut = s2 >= 0.0 ? 1.0 : 0.0;
    const double uni = (s1 > 0.0 ? 1.0 : 0.0) * (1.0 - taut) * s1;
    const double cos2 = r > 0.0 ? half / r : 1.0, sin2 = r > 0.0 ? s12 / r : 0.0;
    const double dd11 = 0.5 * (1.0 + cos2), dd22 = 0.5 * (1.0 - cos2), dd12 = 0.5 * sin2;
    s11 = taut * s11 + uni * dd11, s22 = taut * s22 + uni * dd22, s12 = taut * s12 + uni * dd12;
    // Internal force: -A0 P Dm^-T with P = F S.
    double g1[3], g2[3];
    for (int k = 0; k < 3; ++k) {
      const double p1 = f1[k] * s11 + f2[k] * s12, p2 = f1[k] * s12 + f2[k] * s22;
      g1[k] = t.area0 * (p1 * t.di00 + p2 * t.di01);
      g2[k] = t.area0 * (p1 * t.di10 + p2 * t.di11);
    }
    // Follower pressure and face drag on the area vector a = (d1 x d2) / 2.
    const double a[3] = {0.5 * (d1[1] * d2[2] - d1[2] * d2[1]),
                         0.5 * (d1[2] * d2[0] - d1[0] * d2[2]),
                         0.5 * (d1[0] * d2[1] - d1[1] * d2[0])};
    const double area = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    const double* v0 = v + 3 * t.n[0];
    const double* v1 = v + 3 * t.n[1];
    const double* v2 = v + 3 * t.n[2];
    double un = 0.0;
    for (int k = 0; k < 3; ++k) un += ((v0[k] + v1[k] + v2[k]) * third - c.wind[k]) * a[k];
    un = area > 0.0 ? un / area : 0.0;
    const double load = third * (c.pressure - c.drag * std::abs(un) * un);
    double* y0 = f + 3 * t.n[0];
    double* y1 = f + 3 * t.n[1];
    double* y2 = f + 3 * t.n[2];
    for (int k = 0; k < 3; ++k) {
      const double pk = load * a[k];
      y0[k] += g1[k] + g2[k] + pk;
      y1[k] += -g1[k] + pk;
      y2[k] += -g2[k] + pk;
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"chute's explicit step per canopy triangle against a lean fused canopy loop"};
  std::string caseFile;
  int steps = 400, repeat = 5;
  app.add_option("case", caseFile, "a case (explicit, with membranes)")->required();
  app.add_option("--steps", steps, "steps of chute's run between its two end times");
  app.add_option("--repeat", repeat, "measurements, their median reported");
  CLI11_PARSE(app, argc, argv);

  CaseSpec spec = readCase(caseFile);
  const Model& m = spec.model;
  const LeanCanopy lean = leanCanopy(m);
  const int nd = 3 * m.numNodes();
  std::vector<double> x(nd), v(nd), f(nd);
  for (int n = 0; n < m.numNodes(); ++n)
    for (int k = 0; k < 3; ++k) {
      x[3 * n + k] = m.X[n][k] + (n < static_cast<int>(m.u0.size()) ? m.u0[n][k] : 0.0);
      v[3 * n + k] = 0.01 * std::sin(1.0 + n + 2.0 * k);  // some motion for the drag
    }
  // The lean loop: passes of about 0.2 s each.
  const int passes = std::max(1, static_cast<int>(2e6 / std::max<size_t>(1, lean.tri.size())));
  std::vector<double> leanNs;
  double checksum = 0.0;
  for (int r = 0; r < repeat; ++r) {
    const double t0 = cpuSeconds();
    for (int p = 0; p < passes; ++p) {
      std::fill(f.begin(), f.end(), 0.0);
      leanPass(lean, x.data(), v.data(), f.data());
      checksum += f[3 * lean.tri[p % lean.tri.size()].n[0]];
    }
    leanNs.push_back(1e9 * (cpuSeconds() - t0) / (double(passes) * lean.tri.size()));
  }

  // chute's whole step: two runs, to the end times of `steps` and 2 `steps` estimated steps.
  auto run = [&](double tEnd) {
    CaseSpec s = spec;
    s.solver.tEnd = tEnd;
    RunOptions o;  // no output directory: nothing written
    const double c0 = cpuSeconds();
    const RunResult r = runCase(s, o);
    return std::pair<double, long>(cpuSeconds() - c0, r.steps);
  };
  const auto probe = run(std::min(spec.solver.tEnd, 20 * spec.solver.dt));
  const double dtTaken = probe.second > 0
                             ? std::min(spec.solver.tEnd, 20 * spec.solver.dt) / probe.second
                             : spec.solver.dt;
  const double t1 = steps * dtTaken, t2 = 2 * steps * dtTaken;
  std::vector<double> chuteNs, perStep;
  for (int r = 0; r < repeat; ++r) {
    const auto a = run(t1), b = run(t2);
    const double cpuPerStep = (b.first - a.first) / double(b.second - a.second);
    perStep.push_back(cpuPerStep);
    chuteNs.push_back(1e9 * cpuPerStep / lean.tri.size());
  }
  const double leanMedian = median(leanNs), chuteMedian = median(chuteNs);
  rusage self{};
  getrusage(RUSAGE_SELF, &self);  // ru_maxrss in KiB: the peak of this process, runs included
  fmt::print(
      "{{\"case\": \"{}\", \"triangles\": {}, \"equations_dofs\": {}, \"lean_ns_per_triangle\": "
      "{:.2f}, \"chute_ns_per_triangle_step\": {:.2f}, \"ratio\": {:.3f}, \"step_s\": {:.4g}, "
      "\"steps_per_simulated_s\": {:.5g}, \"cpu_per_simulated_s\": {:.4g}, \"lean_all\": [{}], "
      "\"chute_all\": [{}], \"peak_rss_MiB\": {:.1f}, \"checksum\": {:.6g}}}\n",
      caseFile, lean.tri.size(), nd, leanMedian, chuteMedian, chuteMedian / leanMedian, dtTaken,
      1.0 / dtTaken, median(perStep) / dtTaken, fmt::join(leanNs, ", "), fmt::join(chuteNs, ", "),
      self.ru_maxrss / 1024.0, checksum);
  return 0;
}
