#include "app/Simulation.hpp"

#include <fmt/core.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>

#include "Probes.hpp"
#include "SceneFrame.hpp"
#include "VtuSeries.hpp"
#include "app/Checkpoint.hpp"
#include "case/SolverSetup.hpp"
#include "solver/GeneralizedAlpha.hpp"
#include "solver/StepController.hpp"
#include "terms/LineTerms.hpp"
#include "verification/HenckyReference.hpp"
#include "verification/References.hpp"

namespace chute {

namespace {

std::optional<ReferenceError> compareWithReference(const CaseSpec& spec, const RunResult& r,
                                                   const ProbeSet& probes) {
  if (!spec.reference) return std::nullopt;
  const auto& ref = *spec.reference;
  const Model& m = spec.model;
  const int node = probes.probes()[ref.probe].node;
  const int off = probes.columnOffset(ref.probe);
  std::vector<Vec3> expected;
  if (ref.kind == "pulley") {
    const Vec3 d = m.X[node] - m.X[ref.pulley];
    verification::PulleyReference p{ref.ropeLength, d.norm(), m.gravity.norm(), m.X[ref.pulley],
                                    d.normalized()};
    for (double t : r.times) expected.push_back(p.endPosition(t));
  } else if (ref.kind == "hencky") {
    // Static: the final state against the Foeppl-Hencky centre deflection.
    const verification::HenckyReference h{ref.E, ref.nu, ref.thickness, std::abs(ref.pressure),
                                          ref.radius};
    const double w0 = h.centreDeflection();
    const Vec3 d = (ref.pressure > 0 ? 1.0 : -1.0) * ref.direction;
    ReferenceError e;
    e.kind = ref.kind;
    e.probe = probes.probes()[ref.probe].name;
    const auto& last = r.rows.back();
    e.maxError = (Vec3(last[off], last[off + 1], last[off + 2]) - (m.X[node] + w0 * d)).norm();
    e.motionSize = w0;
    return e;
  } else if (ref.kind == "free_fall") {
    for (double t : r.times) expected.push_back(m.X[node] + 0.5 * t * t * m.gravity);
  } else {
    verification::BeadEllipseReference b(m.X[ref.anchor1], m.X[ref.anchor2], m.X[node], m.gravity);
    expected = b.positions(r.times);
  }
  ReferenceError e;
  e.kind = ref.kind;
  e.probe = probes.probes()[ref.probe].name;
  for (size_t k = 0; k < r.times.size(); ++k) {
    const Vec3 x(r.rows[k][off], r.rows[k][off + 1], r.rows[k][off + 2]);
    e.maxError = std::max(e.maxError, (x - expected[k]).norm());
    e.motionSize = std::max(e.motionSize, (expected[k] - expected.front()).norm());
  }
  return e;
}

// When output is due: every N steps, or at multiples of an interval (the stepping stops there).
struct OutputClock {
  bool on = true;
  int every = 1;
  double interval = 0.0;
  long index = 1;
  double nextTime() const {
    return on && interval > 0 ? static_cast<double>(index) * interval
                              : std::numeric_limits<double>::infinity();
  }
  bool due(double t, long steps, double dt) {
    if (!on) return false;
    if (interval <= 0) return steps % every == 0;
    if (t < static_cast<double>(index) * interval - 1e-9 * dt) return false;
    while (static_cast<double>(index) * interval <= t + 1e-9 * dt) ++index;
    return true;
  }
};

class Progress {
 public:
  explicit Progress(bool on) : on_(on && isatty(STDERR_FILENO)) {}
  void update(long step, double t, double tEnd, double dt, int newton, double avg, long rejected,
              bool force = false) {
    if (!on_) return;
    const auto now = std::chrono::steady_clock::now();
    if (!force && now - last_ < std::chrono::milliseconds(200)) return;
    last_ = now;
    std::fprintf(stderr,
                 "\r  step %7ld  t = %-10.6g / %-8.4g dt = %-9.3g newton %2d (avg %.2f)  "
                 "rejected %ld   ",
                 step, t, tEnd, dt, newton, avg, rejected);
  }
  void finish() {
    if (on_) std::fputc('\n', stderr);
  }

 private:
  bool on_;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace

namespace {
// Set by SIGINT / SIGTERM while a run handles them: the run stops after the step under way,
// writes a checkpoint and leaves valid output.
volatile std::sig_atomic_t gStopRequested = 0;
extern "C" void requestStop(int) {
  gStopRequested = 1;
}

class SignalGuard {
 public:
  explicit SignalGuard(bool on) : on_(on) {
    if (!on_) return;
    gStopRequested = 0;
    struct sigaction sa {};
    sa.sa_handler = requestStop;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &oldInt_);
    sigaction(SIGTERM, &sa, &oldTerm_);
  }
  ~SignalGuard() {
    if (!on_) return;
    sigaction(SIGINT, &oldInt_, nullptr);
    sigaction(SIGTERM, &oldTerm_, nullptr);
  }
  SignalGuard(const SignalGuard&) = delete;
  SignalGuard& operator=(const SignalGuard&) = delete;

 private:
  bool on_;
  struct sigaction oldInt_ {
  }, oldTerm_{};
};
}  // namespace

RunResult runCase(const CaseSpec& spec, const RunOptions& options) {
  const auto wall0 = std::chrono::steady_clock::now();
  RunResult r;
  const Model& m = spec.model;
  const SolverSpec& sv = spec.solver;
  StructuralSystem sys(m, sv.search);
  NewtonSettings ns = newtonSettings(sv, m);
  ns.verbose = options.verboseNewton;
  GeneralizedAlpha integrator(sys, sv.rhoInf, alphaScheme(sv), ns);
  ProbeSet probes(m, spec.output.probes);
  r.columns = probes.columns();

  // The model's fingerprint: checked against a restart file and written into every checkpoint.
  const auto hash = modelHash(m);
  std::optional<Checkpoint> restart;
  if (!options.restartFile.empty()) {
    restart = readCheckpoint(options.restartFile);
    if (restart->caseName != spec.name || restart->modelHash != hash ||
        restart->state.x.size() != 3 * m.numNodes() ||
        restart->active.size() != sys.slidingGroups().size())
      throw std::runtime_error(options.restartFile + ": a checkpoint of another case or model");
    if (sv.type == "static") throw std::runtime_error("static runs cannot be restarted");
  }
  const bool write = !options.outDir.empty();
  std::unique_ptr<CsvWriter> csv;
  if (write) {
    ScopedTimer timer(sys.timings().output);
    std::filesystem::create_directories(options.outDir);
    const std::string path = options.outDir + "/probes.csv";
    if (restart)
      csv = std::make_unique<CsvWriter>(path, r.columns, restart->state.t, r.times, r.rows);
    else
      csv = std::make_unique<CsvWriter>(path, r.columns);
  }
  // The VTU series only when the case asks for it: no VTK work otherwise.
  const auto& vtuSpec = spec.output.vtu;
  std::unique_ptr<VtuSeries> vtu;
  FrameFields fields;
  if (vtuSpec.write && write) {
    ScopedTimer timer(sys.timings().output);
    if (restart)
      vtu = std::make_unique<VtuSeries>(options.outDir, spec.name, restart->state.t,
                                        Writing::Background);
    else
      vtu = std::make_unique<VtuSeries>(options.outDir, spec.name, Writing::Background);
    if (!vtuSpec.fields.empty()) fields.select(vtuSpec.fields);
  }
  const bool inertia = sv.type != "static";
  double vtuLast = -std::numeric_limits<double>::infinity();
  auto writeVtu = [&](const DynamicState& s) {
    if (!vtu || s.t == vtuLast) return;
    ScopedTimer timer(sys.timings().output);
    vtu->write(buildFrame(sys, s, fields, inertia));
    vtuLast = s.t;
  };
  OutputClock probeClock{true, spec.output.everySteps, spec.output.interval};
  OutputClock vtuClock{static_cast<bool>(vtu), vtuSpec.everySteps, vtuSpec.interval};

  DynamicState state = integrator.initialState();
  auto record = [&](const DynamicState& s) {
    ScopedTimer timer(sys.timings().output);
    const auto e = sys.energy(s.x, s.v);
    r.times.push_back(s.t);
    r.rows.push_back(probes.evaluate(sys, s, e));
    if (csv) csv->row(s.t, r.rows.back());
    if (r.times.size() == 1) r.energyInitial = e.total();
    r.energyMaxDrift = std::max(r.energyMaxDrift, std::abs(e.total() - r.energyInitial));
    r.kineticMax = std::max(r.kineticMax, e.kinetic);
  };

  Progress progress(options.progress);
  SignalGuard signals(options.handleSignals);
  if (sv.type == "static") {
    sys.updateState(state.x);
    sys.commit(state.x);
    const auto rep = integrator.solveStatic(state, sv.loadSteps, sv.initialLoadFactor);
    r.newtonIterations = rep.iterations;
    r.steps = sv.loadSteps;
    if (!rep.converged) r.status = "diverged", r.reason = rep.failure;
    state.t = 1.0;
    record(state);
    writeVtu(state);
  } else {
    // A set cut at t (LineSet::cutAt) loads the step that ends at t; the acceleration just after
    // it is that of the structure without it (M a = f_ext - f_int there), as at a start.
    auto accelerationAfterCut = [&](DynamicState& s) {
      if (!m.hasCutAt(s.t)) return;
      DynamicState after = s;
      after.t = std::nextafter(s.t, std::numeric_limits<double>::infinity());
      for (int d = 0; d < after.a.size(); ++d)
        if (sys.dofs().eqOfDof(d) >= 0) after.a[d] = 0.0;
      integrator.computeInitialAcceleration(after);
      s.a = after.a;
    };
    StepController control(sv.dt, sv.dtMin);
    if (restart) {
      const Checkpoint& c = *restart;
      state = c.state;
      sys.updateState(state.x);
      for (size_t g = 0; g < c.active.size(); ++g) {
        sys.slidingGroups()[g]->state().restore(c.active[g], c.handovers[g], state.x);
        if (g < c.splits.size()) sys.slidingGroups()[g]->state().restoreSplits(c.splits[g]);
      }
      if (c.linearSolverLU) integrator.linearSolver().useLU();
      control.dt = c.dt, control.eventStep = c.eventStep;
      control.successesSinceCut = c.successesSinceCut;
      probeClock.index = c.probeClockIndex, vtuClock.index = c.vtuClockIndex;
      vtuLast = c.vtuLast;
      r.steps = c.steps, r.rejectedSteps = c.rejectedSteps, r.eventRetries = c.eventRetries;
      r.newtonIterations = c.newtonIterations, r.maxNewtonInStep = c.maxNewtonInStep;
      r.energyInitial = c.energyInitial, r.energyMaxDrift = c.energyMaxDrift;
      r.kineticMax = c.kineticMax;
    } else {
      integrator.computeInitialAcceleration(state);
      accelerationAfterCut(state);
      sys.commit(state.x);
      record(state);
      writeVtu(state);
    }
    auto checkpoint = [&] {
      if (!write) return;
      ScopedTimer timer(sys.timings().output);
      if (vtu) vtu->flush();  // the frames up to the checkpoint are on disk before it is
      Checkpoint c;
      c.caseName = spec.name;
      c.modelHash = hash;
      c.state = state;
      c.dt = control.dt, c.eventStep = control.eventStep;
      c.successesSinceCut = control.successesSinceCut;
      c.linearSolverLU =
          integrator.linearSolver().kind() == LinearSolver::Kind::Umfpack && sys.symmetric();
      c.probeClockIndex = probeClock.index, c.vtuClockIndex = vtuClock.index;
      c.vtuLast = vtuLast;
      for (const auto* g : sys.slidingGroups()) {
        std::vector<int> act;
        for (size_t s = 0; s < g->state().def().sliders.size(); ++s)
          act.push_back(g->state().committedActiveElement(static_cast<int>(s)));
        c.active.push_back(act);
        c.handovers.push_back(g->state().committedHandovers());
        std::vector<double> splits;
        for (size_t s = 0; s < g->state().def().sliders.size(); ++s)
          splits.push_back(g->state().friction(static_cast<int>(s)).s);
        c.splits.push_back(splits);
      }
      c.steps = r.steps, c.rejectedSteps = r.rejectedSteps, c.eventRetries = r.eventRetries;
      c.newtonIterations = r.newtonIterations, c.maxNewtonInStep = r.maxNewtonInStep;
      c.energyInitial = r.energyInitial, c.energyMaxDrift = r.energyMaxDrift;
      c.kineticMax = r.kineticMax;
      writeCheckpoint(options.outDir + "/checkpoint.cbor", c);
      ++r.checkpoints;
    };
    const double tEnd = sv.tEnd;
    while (state.t < tEnd - 1e-12 * sv.dt) {
      // The next stop: the end, the next output time or cable cut (StepController).
      const double stop =
          std::min({tEnd, probeClock.nextTime(), vtuClock.nextTime(), m.nextCutAfter(state.t)});
      const double h = control.propose(state.t, stop);
      const bool reachesStop = control.reachesStop();
      const NewtonReport rep = integrator.step(state, h);
      r.newtonIterations += rep.iterations;
      const auto verdict = control.judge(rep, h);
      if (verdict == StepController::Verdict::EventRetry) {
        ++r.eventRetries;  // retried to end where the event happens
        continue;
      }
      if (verdict != StepController::Verdict::Accepted) {
        ++r.rejectedSteps;
        if (verdict == StepController::Verdict::BelowMinimum) {
          r.status = "diverged";
          r.reason = fmt::format(
              "step rejected at t = {:.9g} with dt = {:.3g} ({}); dt would fall below dt_min = "
              "{:.3g}",
              state.t, h, rep.failure, sv.dtMin);
          break;
        }
        continue;
      }
      if (reachesStop) state.t = stop;  // no round-off drift of output times
      ++r.steps;
      accelerationAfterCut(state);
      r.maxNewtonInStep = std::max(r.maxNewtonInStep, rep.iterations);
      const bool last = state.t >= tEnd - 1e-12 * sv.dt;
      if (probeClock.due(state.t, r.steps, sv.dt) || last) record(state);
      if (vtuClock.due(state.t, r.steps, sv.dt) || last) writeVtu(state);
      if (options.checkpointEvery > 0 && r.steps % options.checkpointEvery == 0 && !last)
        checkpoint();
      progress.update(r.steps, state.t, tEnd, h, rep.iterations, r.newtonPerStep(),
                      r.rejectedSteps);
      if (gStopRequested && !last) {
        r.status = "interrupted";
        r.reason = fmt::format("stopped by a signal at t = {:.9g}; restart with --restart {}",
                               state.t, write ? options.outDir + "/checkpoint.cbor" : "(none)");
        checkpoint();
        break;
      }
    }
    progress.update(r.steps, state.t, tEnd, control.dt, 0, r.newtonPerStep(), r.rejectedSteps,
                    true);
    progress.finish();
    if (r.status != "completed") {  // the last good state
      if (r.times.empty() || r.times.back() != state.t) record(state);
      writeVtu(state);
    }
  }
  r.finalTime = state.t;
  if (vtu) {
    ScopedTimer timer(sys.timings().output);
    vtu->flush();
    sys.timings().outputBackground = vtu->backgroundSeconds();
  }
  r.vtuFrames = vtu ? vtu->frames() : 0;
  r.timings = sys.timings();
  r.work = sys.work();
  r.work.vtuSeries = vtu ? 1 : 0;
  r.work.vtuFrames = r.vtuFrames;
  r.linearSolver = integrator.linearSolver().kindName();
  r.symbolicAnalyses = integrator.linearSolver().analyses();
  r.equations = sys.numEquations();
  r.nonZeros = sys.matrix().nonZeros();
  for (const auto* g : sys.slidingGroups()) r.handovers.push_back(g->state().committedHandovers());
  r.wallTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  {
    // The reference is not part of the run: timed apart, not in wall_time.total.
    const auto ref0 = std::chrono::steady_clock::now();
    r.reference = compareWithReference(spec, r, probes);
    r.referenceTime =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - ref0).count();
  }
  if (write) writeSummary(options.outDir + "/summary.json", spec, r);
  return r;
}

void writeSummary(const std::string& path, const CaseSpec& spec, const RunResult& r) {
  using nlohmann::json;
  const auto& t = r.timings;
  json j;
  j["case"] = spec.name;
  j["case_file"] = spec.file;
  j["status"] = r.status;
  if (!r.reason.empty()) j["reason"] = r.reason;
  j["steps"] = r.steps;
  j["rejected_steps"] = r.rejectedSteps;
  j["event_retries"] = r.eventRetries;  // steps cut to end where a slider meets a node
  j["newton_iterations"] = r.newtonIterations;
  j["newton_iterations_per_step"] = r.newtonPerStep();
  j["max_newton_iterations_in_a_step"] = r.maxNewtonInStep;
  j["final_time"] = r.finalTime;
  const double accounted = t.assembly + t.search + t.factorisation + t.solve + t.output;
  j["wall_time"] = {{"total", r.wallTime},
                    {"assembly", t.assembly},
                    {"search", t.search},
                    {"factorisation", t.factorisation},
                    {"solve", t.solve},
                    {"output", t.output},
                    {"other", std::max(0.0, r.wallTime - accounted)},
                    {"output_background", t.outputBackground}};
  j["counts"] = {{"assemblies", t.assemblies},
                 {"searches", t.searches},
                 {"factorisations", t.factorisations},
                 {"solves", t.solves},
                 {"symbolic_analyses", r.symbolicAnalyses}};
  const auto& w = r.work;
  j["work"] = {{"line_elastic_kernels", w.lineElastic},
               {"sliding_kernels", w.sliding},
               {"line_mass_kernels", w.lineMass},
               {"point_mass_kernels", w.pointMass},
               {"membrane_kernels", w.membrane},
               {"pressure_kernels", w.pressure},
               {"drag_kernels", w.drag},
               {"face_drag_kernels", w.faceDrag},
               {"slider_searches", w.sliderSearch},
               {"energy_evaluations", w.energy},
               {"scene_frames", w.sceneFrames},
               {"vtu_series", w.vtuSeries},
               {"vtu_frames", w.vtuFrames}};
  j["system"] = {
      {"equations", r.equations}, {"nonzeros", r.nonZeros}, {"linear_solver", r.linearSolver}};
  j["solver"] = {
      {"type", spec.solver.type},
      {"dt", spec.solver.dt},
      {"rho_inf", spec.solver.rhoInf},
      {"integrator", spec.solver.integrator},
      {"slack_events", spec.solver.slackTautEvents},
      {"mass", spec.model.massKind == kernels::MassKind::Lumped ? "lumped" : "consistent"},
      {"search", spec.solver.search == SliderSearch::NearestLength ? "nearest_length"
                                                                   : "material_coordinate"}};
  j["sliding_handovers"] = r.handovers;
  j["output"] = {
      {"probe_rows", r.times.size()}, {"vtu_frames", r.vtuFrames}, {"checkpoints", r.checkpoints}};
  if (!spec.units.empty()) j["units"] = spec.units;
  j["energy"] = {
      {"initial", r.energyInitial}, {"max_drift", r.energyMaxDrift}, {"max_kinetic", r.kineticMax}};
  if (r.reference) {
    const auto& e = *r.reference;
    j["reference"] = {{"kind", e.kind},
                      {"evaluation_time", r.referenceTime},
                      {"probe", e.probe},
                      {"max_error", e.maxError},
                      {"motion_size", e.motionSize},
                      {"relative_max_error", e.relative()}};
  }
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp);
    f << j.dump(2) << "\n";
  }
  std::filesystem::rename(tmp, path);
}

}  // namespace chute
