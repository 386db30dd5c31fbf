#include "app/RunCase.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>

#include "OutputError.hpp"
#include "OutputFile.hpp"
#include "app/CheckpointFile.hpp"
#include "app/Progress.hpp"
#include "app/RestartSettings.hpp"
#include "app/RunOutput.hpp"
#include "app/SanityNotes.hpp"
#include "app/StopSignals.hpp"
#include "case/RunLimits.hpp"
#include "case/SolverSetup.hpp"
#include "solver/EnergyMonitor.hpp"
#include "solver/StaticLoadStepper.hpp"
#include "solver/TimeStepper.hpp"
#include "terms/CanopyFlowTerm.hpp"
#include "terms/contact/ContactTerm.hpp"
#include "terms/sliding/SlidingGroupTerm.hpp"

namespace chute {

namespace {

ExplicitRunInfo explicitSummary(const StableStepRecord& rec, const Model& m) {
  ExplicitRunInfo e;
  e.leastStep = rec.least;
  e.largestStep = rec.largest;
  if (rec.limitingNode >= 0)
    e.limitingNode = m.nodeName[rec.limitingNode].empty()
                         ? "node " + std::to_string(rec.limitingNode + 1)
                         : m.nodeName[rec.limitingNode];
  e.stepHistory = rec.history;
  e.addedMass = rec.addedMass;
  e.totalAddedMass = rec.totalAddedMass;
  e.targetStep = rec.targetStep;
  e.scaledNodes = rec.scaledNodes;
  e.partMass = rec.partMass;
  e.nodalSteps = rec.nodalSteps;
  return e;
}

// What fabric contact met (docs/contact.md CT13), and a note when it met more than it holds.
void noteContact(const ContactTerm& c, const Model& m, RunResult& r) {
  const auto& rec = c.record();
  ContactRunInfo& i = r.contact.emplace();
  i.thickness = m.contact.thickness;
  i.builds = rec.builds, i.treeBuilds = rec.treeBuilds, i.candidates = rec.candidates;
  i.largestActive = rec.largestActive, i.closest = rec.closest;
  i.largestApproachPerStep = rec.largestApproachPerStep;
  i.largestApproachEnergy = rec.largestApproachEnergy;
  if (i.largestApproachPerStep > 0.5)
    r.notes.push_back(fmt::format(
        "contact: a pair closed {:.3g} contact thicknesses in one step (docs/contact.md CT13): "
        "steps too long for the thickness; fabric may have passed through (shorten solver.dt, "
        "or raise contact.thickness)",
        i.largestApproachPerStep));
  // Per pair; a point in face contact is held by several (docs/contact.md CT13).
  if (i.largestApproachEnergy > 4.0)
    r.notes.push_back(fmt::format(
        "contact: a pair in contact approached with {:.3g} times the energy the contact stops "
        "(docs/contact.md CT13): fabric may have passed through; raise contact.thickness or "
        "contact.stiffness_scale",
        i.largestApproachEnergy));
}

// Output times are stops every step lands on (TimeStepper::advanceTo), so an output interval
// shorter than solver.dt caps the step of an integrator that takes the case's dt: chute says so
// rather than shrink dt silently (landing on output times keeps the rows at computed states, not
// interpolated ones; docs/output.md).
void noteOutputStepCap(const CaseSpec& spec, RunResult& r) {
  double cap = std::numeric_limits<double>::infinity();
  std::string key;
  if (spec.output.interval > 0.0 && spec.output.interval < cap)
    cap = spec.output.interval, key = "output.interval";
  if (spec.output.vtu.write && spec.output.vtu.interval > 0.0 && spec.output.vtu.interval < cap)
    cap = spec.output.vtu.interval, key = "output.vtu.interval";
  if (cap < spec.solver.dt) {
    r.outputStepCap = cap;
    r.notes.push_back(fmt::format(
        "{} = {:.6g} is shorter than solver.dt = {:.6g}: steps land on output times, so no "
        "step is longer than {:.6g}",
        key, cap, spec.solver.dt, cap));
  }
}

// A checkpoint to continue from, read and validated whole (file, fields, every term's history,
// the case's settings against the checkpointed run's) before anything of the output is touched;
// the state it holds is restored into the stepper.
Checkpoint readRestart(const std::string& file, const CaseSpec& spec, std::uint64_t hash,
                       TimeStepper& stepper, StructuralState& state) {
  Checkpoint restart = readCheckpoint(file);
  if (restart.caseName != spec.name || restart.modelHash != hash)
    throw std::runtime_error(file + ": a checkpoint of another case or model");
  checkRestartSettings(spec, restart.settings, file);
  const double t = restart.stepping.snapshot.state.t;
  if (!stepper.reached(spec.solver.tEnd, t) && spec.solver.tEnd < t)
    throw std::runtime_error(fmt::format(
        "{}: is {:.9g}, before the checkpoint's time {:.9g}: a restart goes on from the "
        "checkpoint to a later end",
        whereIn(spec.settings, spec.file, "solver.t_end"), spec.solver.tEnd, t));
  // The output clocks must be those of the checkpoint's time: the next probe (frame) time the
  // first output time after t. A clock beyond it wrote no more rows and still "completed".
  auto clockFits = [&](long index, double interval, const char* field) {
    if (!(interval > 0.0)) return;  // output every n steps: no time to check against
    const double next = static_cast<double>(index) * interval;
    const double slack = 1e-6 * interval + 1e-12 * std::abs(t);
    if (!(next >= t - slack && next - interval <= t + slack))
      throw std::runtime_error(fmt::format(
          "{}: not a valid chute checkpoint ({} {} puts the next output at t = {:.9g}, not the "
          "first after the checkpoint's time {:.9g})",
          file, field, index, next, t));
  };
  clockFits(restart.output.probeClockIndex, spec.output.interval, "probe_clock");
  if (spec.output.vtu.write)
    clockFits(restart.output.vtuClockIndex, spec.output.vtu.interval, "vtu_clock");
  try {
    state = stepper.resume(restart.stepping);
  } catch (const HistoryError& e) {
    throw std::runtime_error(file + ": not a valid chute checkpoint (" + e.what() + ")");
  }
  return restart;
}

// A static run: the load stepped to equilibrium from the model's positions.
void runStatics(const CaseSpec& spec, StructuralSystem& sys, const RunOptions& options,
                RunOutput& out, StructuralState& state, RunResult& r) {
  const SolverSpec& sv = spec.solver;
  if (options.handleSignals) endAtOnceOnStop();
  NewtonSettings ns = newtonSettings(sv, spec.model);
  ns.verbose = options.verboseNewton;
  Newton newton(sys, ns);
  state = sys.initialState();
  StaticLoadStepper statics(sys, newton);
  const auto rep = statics.solveFromStart(state, sv.loadSteps, sv.initialLoadFactor);
  r.newtonIterations = rep.iterations;
  r.maxNewtonInStep = statics.maxIterationsInStep();
  // A run that failed reports the increments that converged, and (state.t) the load factor of
  // its last equilibrium, the state it writes.
  r.steps = rep.converged ? sv.loadSteps : statics.incrementsTaken();
  if (!rep.converged) r.status = RunStatus::Diverged, r.reason = rep.failure;
  r.symbolicAnalyses = newton.linearSolver().analyses();
  r.linearSolver = newton.linearSolver().kindName();
  out.record(state);
  out.frame(state);
}

// What a dynamic run needs besides its system: the integrator, the loop, the output, the energy
// balance and the checkpoints.
struct DynamicRun {
  const CaseSpec& spec;
  const RunOptions& options;
  StructuralSystem& sys;
  TimeIntegrator& integrator;
  TimeStepper& stepper;
  RunOutput& out;
  EnergyMonitor& monitor;
  std::uint64_t hash;
  bool restarted;
  RunResult& r;

  bool writes() const { return !options.outDir.empty(); }

  void checkpoint(const StructuralState& state) {
    if (!writes()) return;
    ScopedTimer timer(sys.timings().output);
    out.flush();  // the frames up to the checkpoint are on disk before it is
    Checkpoint c;
    c.caseName = spec.name;
    c.modelHash = hash;
    c.settings = restartFingerprint(spec);
    c.stepping = stepper.save(state);
    c.output = out.mark();
    writeCheckpoint(options.outDir + "/checkpoint.cbor", c);
    ++r.checkpoints;
  }

  // The output's last row and frame: the state the run ended in when it is one to trust, else
  // the last row written while the energy balance held (the rows and frames after it removed).
  // A run that stopped early ends in the state before the step it could not take; that state
  // is trusted if the balance holds there (it is taken there now when the last one was not).
  void endOutput(StructuralState& state, const StructuralState& previous) {
    r.finalTime = state.t;
    if (r.status == RunStatus::Completed) return;
    bool good = r.status == RunStatus::Interrupted;
    if (r.status == RunStatus::Diverged)
      good = previous.t == state.t
                 ? monitor.withinBounds()
                 : monitor.afterStep(previous, state, integrator.equilibrium(state),
                                     state.t - previous.t) &&
                       monitor.withinBounds();
    if (good) {
      out.lastGoodState(state);
      return;
    }
    const double t = out.cutBackToLastGoodRow();
    if (std::isnan(t)) return;
    r.finalTime = t;
    r.reason += fmt::format(
        "; the output ends at t = {:.9g}, the last row where the energy balance held", t);
  }

  void run(StructuralState& state) {
    if (!restarted) state = stepper.start();
    // A restarted run's balance starts afresh from the restored state (docs/output.md).
    monitor.start(state, integrator.equilibrium(state));
    out.setEnergyMonitor(&monitor);
    if (!restarted) {
      out.record(state);
      out.frame(state);
    }
    out.markLastGood();
    StructuralState previous = state;  // the state the balance was last taken at, for the work
    // The balance (a residual of the loads and an energy of the whole model) is taken every
    // integrator.balanceStride() steps, and at every probe row and the last step (EB1,
    // docs/explicit.md): the work of a window is f . (x_end - x_start), the same rectangle rule
    // an implicit step of that length gets.
    const long stride = integrator.balanceStride();
    long stepsSinceBalance = 0;
    // The step that ends a window keeps the loads it applied (EnergyMonitor::takesStepLoads); a
    // balance at a probe row or the last step between windows evaluates them.
    const bool stepLoads = monitor.takesStepLoads();
    sys.captureStepLoads(stepLoads && stride <= 1);
    const double tEnd = spec.solver.tEnd;
    Progress progress(options.progress, state.t, tEnd, integrator.takesNominalStep());
    const auto result = stepper.advanceTo(
        state, tEnd, [&](double) { return out.nextStop(); },
        [&](const StructuralState& s, int newton) {
          const auto& n = stepper.counters();
          const bool last = stepper.reached(s.t, tEnd);
          if (++stepsSinceBalance >= stride || last || out.recordsAt(s.t, n.steps)) {
            stepsSinceBalance = 0;
            // Timed as the balance's own work: an assembly it asks for (the loads at a probe row
            // between windows) stays the assembly's.
            const double assemblyBefore = sys.timings().assembly;
            const auto balanceStart = std::chrono::steady_clock::now();
            const bool balanced =
                monitor.afterStep(previous, s, integrator.equilibrium(s), s.t - previous.t);
            sys.timings().balance +=
                std::chrono::duration<double>(std::chrono::steady_clock::now() - balanceStart)
                    .count() -
                (sys.timings().assembly - assemblyBefore);
            previous = s;
            if (!balanced) {
              r.status = RunStatus::Unstable;
              r.reason = monitor.reason();
              return false;
            }
          }
          sys.captureStepLoads(stepLoads && stepsSinceBalance + 1 >= stride);
          out.afterStep(s, n.steps, last);
          if (options.checkpointEvery > 0 && n.steps % options.checkpointEvery == 0 && !last)
            checkpoint(s);
          progress.update({n.steps, s.t, s.control.dt, newton, n.newtonPerStep(), n.rejectedSteps});
          if (options.handleSignals && stopRequested() && !last) {
            r.status = RunStatus::Interrupted;
            r.reason = fmt::format("stopped by a signal at t = {:.9g}; restart with --restart {}",
                                   s.t, writes() ? options.outDir + "/checkpoint.cbor" : "(none)");
            // The checkpoint is the state the output ends with: a restart cuts the output back
            // to it (RunOutput), so rows written after it never reach the restarted run.
            return false;
          }
          // Limits a run cannot get round (docs/limits.md): a stable step that shrank, the rows
          // or frames at their limits.
          if (!last) {
            if (auto why =
                    stopReason(spec, integrator, s, n.steps, out.probeRows(), out.vtuFrames());
                !why.empty()) {
              r.status = RunStatus::Diverged;
              r.reason = std::move(why);
              return false;
            }
          }
          return true;
        });
    if (result.outcome == TimeStepper::Outcome::BelowMinimum) {
      r.status = RunStatus::Diverged;
      r.reason = result.reason;
    }
    if (r.status == RunStatus::Completed && !monitor.finish()) {
      r.status = RunStatus::Unstable;
      r.reason = monitor.reason();
    }
    if (r.status == RunStatus::Interrupted) checkpoint(state);
    const auto& n = stepper.counters();
    progress.update({n.steps, state.t, state.control.dt, 0, n.newtonPerStep(), n.rejectedSteps},
                    true);
    progress.finish();
    endOutput(state, previous);
    r.steps = n.steps, r.rejectedSteps = n.rejectedSteps, r.eventRetries = n.eventRetries;
    r.newtonIterations = n.newtonIterations, r.maxNewtonInStep = n.maxNewtonInStep;
    if (const auto* rec = integrator.stableSteps())
      r.explicitRun = explicitSummary(*rec, spec.model);
    if (const ContactTerm* c = sys.termList().contact()) noteContact(*c, spec.model, r);
    r.balanceMax = monitor.largestBalance(), r.balanceScale = monitor.scale();
    r.externalWork = monitor.work();
    // Central differences solve no linear system.
    const LinearSolver* ls = integrator.linearSolver();
    r.linearSolver = ls ? ls->kindName() : "none";
    r.symbolicAnalyses = ls ? ls->analyses() : 0;
  }
};

// What the run did, from the system once it has ended.
void reportSystem(StructuralSystem& sys, RunResult& r) {
  r.timings = sys.timings();
  r.work = sys.work();
  r.equations = sys.numEquations();
  r.nonZeros = sys.matrix().nonZeros();
  r.concurrentAssemblies = sys.concurrentAssemblies();
  r.serialAssemblies = sys.serialAssemblies();
  for (const auto* g : sys.termList().slidingGroups())
    r.handovers.push_back(g->state().committedHandovers());
}

// The flight figures of a run with a canopy probe and a force probe (docs/flight.md), from the
// series RunOutput collected as it wrote the rows (the rows themselves are not kept).
void reportFlight(const CaseSpec& spec, const StructuralSystem& sys, const FlightSeries* series,
                  RunResult& r) {
  // A run that diverged or went unstable flew no parachute to its end: its rows hold no steady
  // state, and their last may be the blow-up's.
  if (r.status != RunStatus::Completed) return;
  if (!series || series->t.empty()) return;
  for (const auto& p : spec.output.probes)
    if (p.kind == ProbeKind::Canopy)
      for (const auto* c : sys.termList().canopyFlows())
        if (c->set() == p.membraneSet) {
          r.flight = flightFigures(*series, c->nominalDiameter(), c->nominalArea(),
                                   spec.model.totalMass() * spec.model.gravity.norm());
          return;
        }
}

}  // namespace

std::string_view runStatusName(RunStatus s) {
  switch (s) {
    case RunStatus::Completed:
      return "completed";
    case RunStatus::Diverged:
      return "diverged";
    case RunStatus::Unstable:
      return "unstable";
    case RunStatus::Interrupted:
      return "interrupted";
  }
  return "unknown";
}

std::ostream& operator<<(std::ostream& out, RunStatus s) {
  return out << runStatusName(s);
}

namespace {
// A free node that no element, load or point mass touches has neither stiffness nor mass: the
// equations are singular there. Refused by name before anything is written (an implicit run
// had halved its first step down to dt_min and stopped with exit 3).
void refuseUntouchedNodes(const CaseSpec& spec, const StructuralSystem& sys) {
  const auto& loose = sys.untouchedFreeNodes();
  if (loose.empty()) return;
  const Model& m = spec.model;
  const int first = loose.front();
  const std::string key =
      !m.nodeName[first].empty() && spec.settings.count("nodes." + m.nodeName[first])
          ? "nodes." + m.nodeName[first]
          : "mesh.file";
  throw std::runtime_error(
      whereIn(spec.settings, spec.file, key) + ": " + std::to_string(loose.size()) +
      " free node(s) in no element, load or point mass (" + nodeNames(m, loose) +
      "): with neither stiffness nor mass the equations are singular there "
      "(connect them, fix them under boundary.fixed, or remove them)");
}
}  // namespace

RunResult runCase(const CaseSpec& spec, const RunOptions& options) {
  const auto wall0 = std::chrono::steady_clock::now();
  RunResult r;
  r.notes = sanityNotes(spec);  // values outside their physical range, much slower settings
  const Model& m = spec.model;
  const SolverSpec& sv = spec.solver;
  StructuralSystem sys(m, sv.search);
  refuseUntouchedNodes(spec, sys);
  const bool dynamic = sv.type == AnalysisType::Dynamic;
  std::unique_ptr<TimeIntegrator> integrator;
  std::optional<TimeStepper> stepper;
  if (dynamic) {
    integrator = makeIntegrator(sys, sv, m, options.verboseNewton);
    stepper.emplace(sys, *integrator, sv.dt);
    if (integrator->takesNominalStep()) noteOutputStepCap(spec, r);
  }

  // The model's fingerprint: checked against a restart file and written into every checkpoint.
  const auto hash = modelHash(m);
  StructuralState state;
  std::optional<Checkpoint> restart;
  if (!options.restartFile.empty()) {
    if (!dynamic) throw std::runtime_error("static runs cannot be restarted");
    restart = readRestart(options.restartFile, spec, hash, *stepper, state);
  }
  // An explicit run's step is the stable step: its steps, rows and frames are judged now, before
  // anything is written (docs/limits.md).
  if (integrator)
    checkRunSize(spec, *integrator, restart ? state : sys.initialState(),
                 restart ? stepper->counters().steps : 0);
  RunOutput out(spec, sys, options.outDir, restart ? &restart->output : nullptr, r,
                options.keepRows);
  if (integrator)
    out.setEquilibrium([&](const StructuralState& s) { return integrator->equilibrium(s); });
  EnergyMonitor monitor(sys, sv.energyTolerance, integrator && integrator->equationsAtStepEnds());

  try {
    if (!dynamic) {
      runStatics(spec, sys, options, out, state, r);
      r.finalTime = state.t;
    } else {
      DynamicRun run{spec, options, sys,  *integrator,         *stepper,
                     out,  monitor, hash, restart.has_value(), r};
      run.run(state);
    }
    out.flush();
    r.probeRows = out.probeRows();
    sys.timings().outputBackground = out.backgroundSeconds();
    r.vtuFrames = out.vtuFrames();
    reportSystem(sys, r);
    reportFlight(spec, sys, out.flightSeries(), r);
    r.work.vtuSeries = spec.output.vtu.write && !options.outDir.empty() ? 1 : 0;
    r.work.vtuFrames = r.vtuFrames;
    r.wallTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    {
      // The reference is not part of the run: timed apart, not in wall_time.total.
      const auto ref0 = std::chrono::steady_clock::now();
      r.reference = out.reference();
      r.referenceTime =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - ref0).count();
    }
    if (!options.outDir.empty()) writeSummary(options.outDir + "/summary.json", spec, r);
  } catch (const OutputError& e) {
    // A full disk, a file size limit, a removed directory: what the output holds whole is named
    // from the files themselves (a row cut mid-number was cut off; a torn frame is not listed).
    // The frames queued before the failure are written (or dropped) first, so that the count
    // named is the one the .pvd holds when the run has ended; a second failure there is the
    // same one, already being reported.
    try {
      out.flush();
    } catch (const std::exception&) {
    }
    const std::string whole = out.wholeSoFar();
    throw OutputError(fmt::format(
        "{}; stopped at t = {:.9g}{}{}; no summary.json", e.what(), state.t,
        whole.empty() ? "" : "; " + whole,
        r.checkpoints > 0 ? "; the last checkpoint is in " + options.outDir + "/checkpoint.cbor"
                          : ""));
  }
  return r;
}

void writeSummary(const std::string& path, const CaseSpec& spec, const RunResult& r) {
  using nlohmann::json;
  const auto& t = r.timings;
  json j;
  j["case"] = spec.name;
  j["case_file"] = spec.file;
  j["status"] = runStatusName(r.status);
  if (!r.reason.empty()) j["reason"] = r.reason;
  j["steps"] = r.steps;
  j["rejected_steps"] = r.rejectedSteps;
  j["event_retries"] = r.eventRetries;  // steps cut to end where a slider meets a node
  j["newton_iterations"] = r.newtonIterations;
  j["newton_iterations_per_step"] = r.newtonPerStep();
  j["max_newton_iterations_in_a_step"] = r.maxNewtonInStep;
  j["final_time"] = r.finalTime;
  const double accounted = t.assembly + t.search + t.factorisation + t.solve + t.output + t.passes +
                           t.commits + t.stableStep + t.balance;
  j["wall_time"] = {{"total", r.wallTime},
                    {"assembly", t.assembly},
                    {"search", t.search},
                    {"factorisation", t.factorisation},
                    {"solve", t.solve},
                    {"output", t.output},
                    {"passes", t.passes},
                    {"commits", t.commits},
                    {"stable_step", t.stableStep},
                    {"balance", t.balance},
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
               {"whirl_damping_kernels", w.whirlDamping},
               {"point_mass_kernels", w.pointMass},
               {"membrane_kernels", w.membrane},
               {"pressure_kernels", w.pressure},
               {"drag_kernels", w.drag},
               {"face_drag_kernels", w.faceDrag},
               {"slider_searches", w.sliderSearch},
               {"contact_pair_kernels", w.contact},
               {"contact_builds", w.contactLists},
               {"energy_evaluations", w.energy},
               {"scene_frames", w.sceneFrames},
               {"vtu_series", w.vtuSeries},
               {"vtu_frames", w.vtuFrames}};
  j["system"] = {{"equations", r.equations},
                 {"nonzeros", r.nonZeros},
                 {"linear_solver", r.linearSolver},
                 {"assemblies_on_two_threads", r.concurrentAssemblies},
                 {"assemblies_split_on_one_thread", r.serialAssemblies}};
  j["solver"] = {
      {"type", analysisName(spec.solver.type)},
      {"dt", spec.solver.dt},
      {"rho_inf", spec.solver.rhoInf},
      {"integrator", integratorName(spec.solver.integrator)},
      {"slack_events", spec.solver.slackTautEvents},
      {"mass", spec.model.massKind == kernels::MassKind::Lumped ? "lumped" : "consistent"},
      {"search", spec.solver.search == SliderSearch::NearestLength ? "nearest_length"
                                                                   : "material_coordinate"}};
  if (std::isfinite(r.outputStepCap)) j["solver"]["dt_capped_by_output"] = r.outputStepCap;
  if (!r.notes.empty()) j["notes"] = r.notes;
  j["sliding_handovers"] = r.handovers;
  if (r.explicitRun) {
    const auto& e = *r.explicitRun;
    json added = json::object();
    for (const auto& [part, mass] : e.addedMass) added[part] = mass;
    json partMass = json::object();
    for (const auto& [part, mass] : e.partMass) partMass[part] = mass;
    json history = json::array();
    for (const auto& [time, dt] : e.stepHistory) history.push_back({time, dt});
    j["explicit"] = {{"safety_factor", spec.solver.safetyFactor},
                     {"target_dt", e.targetStep},
                     {"mass_scaling_quantile", spec.solver.massScalingQuantile},
                     {"stiffness_damping", spec.solver.stiffnessDamping},
                     {"least_step", e.leastStep},
                     {"largest_step", e.largestStep},
                     {"limiting_node", e.limitingNode},
                     {"stable_step_history", history},
                     {"added_mass", added},
                     {"added_mass_total", e.totalAddedMass},
                     {"scaled_nodes", e.scaledNodes},
                     {"scaled_parts_mass", partMass},
                     {"nodal_stable_steps",
                      {{"least", e.nodalSteps[0]},
                       {"quantile_01", e.nodalSteps[1]},
                       {"quantile_10", e.nodalSteps[2]},
                       {"median", e.nodalSteps[3]}}}};
  }
  if (r.contact) {
    const auto& c = *r.contact;
    j["contact"] = {{"thickness", c.thickness},
                    {"broad_phase_builds", c.builds},
                    {"tree_builds", c.treeBuilds},
                    {"candidates_at_end", c.candidates},
                    {"most_pairs_in_contact", c.largestActive},
                    {"closest_over_thickness", c.closest},
                    {"largest_approach_per_step", c.largestApproachPerStep},
                    {"largest_approach_energy", c.largestApproachEnergy}};
  }
  j["output"] = {
      {"probe_rows", r.probeRows}, {"vtu_frames", r.vtuFrames}, {"checkpoints", r.checkpoints}};
  if (!spec.units.empty()) j["units"] = spec.units;
  if (r.flight) {
    const auto& f = *r.flight;
    j["flight"] = {{"frame", f.held ? "held in a wind (infinite mass)" : "free flight"},
                   {"peak_opening_force", f.peakForce},
                   {"peak_opening_force_time", f.peakForceTime},
                   {"opening_force_factor", f.openingForceFactor},
                   {"filling_time", f.fillingTime},
                   {"filling_distance", f.fillingDistance},
                   {"steady_from", f.steadyFrom},
                   {"steady_force", f.steadyForce},
                   {"steady_force_variation", f.steadyVariation},
                   {"steady_descent_speed", f.steadyDescentSpeed},
                   {"steady_airspeed", f.steadyAirspeed},
                   {"drag_area", f.dragArea},
                   {"drag_coefficient", f.dragCoefficient},
                   {"projected_diameter_ratio", f.projectedDiameterRatio},
                   {"largest_swing", f.largestSwing}};
  }
  j["energy"] = {
      {"initial", r.energyInitial}, {"max_drift", r.energyMaxDrift}, {"max_kinetic", r.kineticMax}};
  if (std::isfinite(r.balanceMax))
    j["energy"]["balance"] = {
        {"max", r.balanceMax}, {"scale", r.balanceScale}, {"work", r.externalWork}};
  if (r.reference) {
    const auto& e = *r.reference;
    j["reference"] = {{"kind", e.kind},
                      {"evaluation_time", r.referenceTime},
                      {"probe", e.probe},
                      {"max_error", e.maxError},
                      {"motion_size", e.motionSize},
                      {"relative_max_error", e.relative()}};
  }
  replaceFile(path, j.dump(2) + "\n", false);
}

}  // namespace chute
