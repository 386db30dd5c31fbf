// Every term's history round-trips through StructuralSystem::saveState / loadState: a second
// system loaded from a snapshot taken mid-run goes on bit for bit like the first. The scenes
// together contain every kind of term the system can build (TermList::kinds), so a
// new kind, or a term that remembers something save() leaves out, fails here.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <limits>
#include <set>
#include <string>

#include "case/CaseSpec.hpp"
#include "case/SolverSetup.hpp"
#include "solver/TimeStepper.hpp"

using namespace chute;

namespace {
struct Scene {
  std::string file;
  std::vector<std::string> sets;
  double tSave, tEnd;  // snapshot at tSave, both systems go on to tEnd
};

struct SteppedSystem {
  explicit SteppedSystem(const CaseSpec& spec)
      : sys(spec.model, spec.solver.search),
        integrator(makeIntegrator(sys, spec.solver, spec.model)),
        stepper(sys, *integrator, spec.solver.dt) {}
  void advance(StructuralState& s, double t) {
    const auto r = stepper.advanceTo(
        s, t, [](double) { return 1e300; }, [](const StructuralState&, int) { return true; });
    ASSERT_EQ(r.outcome, TimeStepper::Outcome::Reached) << r.reason;
  }
  StructuralSystem sys;
  std::unique_ptr<TimeIntegrator> integrator;
  TimeStepper stepper;
};

bool sameBits(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}
}  // namespace

TEST(History, EveryTermKindRoundTripsThroughASnapshot) {
  // capstan_pulley: a slider with friction that sticks and slips (split, stick state, slip
  // rate); bead_5: hand-overs along a sliding rope; c9_slider: canopy, pressure, face drag, line
  // drag, sliders passing line nodes inside the step, point masses, slack / taut lines.
  const std::vector<Scene> scenes{
      {"capstan_pulley", {}, 1.5, 1.8},
      {"bead_5", {}, 0.6, 0.9},
      {"c9_slider", {}, 0.05, 0.08},
      {"capstan_masses", {}, 0.2, 0.3},
      // c9_flight: the airflow's loads (captured air, apparent mass, supplied energy).
      {"c9_flight", {}, 0.02, 0.03},
      // contact_drop: fabric contact (its candidate lists' build and friction's lag) with the
      // sheet on the floor.
      {"contact_drop", {"solver.dt=5e-4", "contact.friction=0.3"}, 0.07, 0.08},
  };
  std::set<std::string> covered;
  for (const auto& sc : scenes) {
    const CaseSpec spec = readCase(CHUTE_SOURCE_DIR "/cases/" + sc.file + ".toml", sc.sets);
    SteppedSystem a(spec);
    StructuralState sa = a.stepper.start();
    a.advance(sa, sc.tSave);
    const SystemSnapshot snap = a.sys.saveState(sa);

    SteppedSystem b(spec);
    b.stepper.start();
    StructuralState sb = b.sys.loadState(snap);
    // The loaded system saves exactly what it was given.
    const SystemSnapshot again = b.sys.saveState(sb);
    EXPECT_EQ(again.termNames, snap.termNames) << sc.file;
    for (size_t k = 0; k < snap.histories.size(); ++k) {
      EXPECT_TRUE(again.histories[k] == snap.histories[k]) << sc.file << " " << snap.termNames[k];
      covered.insert(snap.termNames[k]);
    }
    a.advance(sa, sc.tEnd);
    b.advance(sb, sc.tEnd);
    const SystemSnapshot ea = a.sys.saveState(sa), eb = b.sys.saveState(sb);
    bool histories = true;
    for (size_t k = 0; k < ea.histories.size(); ++k) {
      const bool same = ea.histories[k] == eb.histories[k];
      EXPECT_TRUE(same) << sc.file << ": history of " << ea.termNames[k] << " differs";
      histories &= same;
    }
    const bool state = sameBits(sa.x, sb.x) && sameBits(sa.v, sb.v) && sameBits(sa.a, sb.a) &&
                       sa.t == sb.t && sa.control.dt == sb.control.dt;
    EXPECT_TRUE(state) << sc.file;
    std::printf(
        "%-15s snapshot at t = %.3f, continued to %.3f: %zu terms, %ld / %ld steps after "
        "it, state and histories bit for bit: %s\n",
        sc.file.c_str(), sc.tSave, sc.tEnd, ea.histories.size(), a.stepper.counters().steps,
        b.stepper.counters().steps, state && histories ? "yes" : "NO");
  }
  for (const auto& kind : TermList::kinds())
    EXPECT_TRUE(covered.count(kind)) << "no scene here has a term of kind " << kind;
}

TEST(History, AForgedRecordIsRefusedAndChangesNothing) {
  const CaseSpec spec = readCase(CHUTE_SOURCE_DIR "/cases/capstan_pulley.toml", {});
  SteppedSystem a(spec);
  StructuralState s = a.stepper.start();
  a.advance(s, 0.5);
  const SystemSnapshot good = a.sys.saveState(s);
  int refused = 0, cases = 0;
  auto expectRefused = [&](SystemSnapshot bad, const char* what) {
    ++cases;
    try {
      a.sys.loadState(bad);
      ADD_FAILURE() << what << ": accepted";
    } catch (const HistoryError& e) {
      ++refused;
      std::printf("refused (%s): %s\n", what, e.what());
    }
    const SystemSnapshot after = a.sys.saveState(s);
    for (size_t k = 0; k < after.histories.size(); ++k)
      EXPECT_TRUE(after.histories[k] == good.histories[k]) << what << ": history changed";
  };
  size_t g = 0;
  while (good.termNames[g] != "sliding_group") ++g;
  {
    auto bad = good;
    auto ints = bad.histories[g].ints();
    ints[1] = 1000;  // an active element far outside the chain
    bad.histories[g] = History::fromRecords(bad.histories[g].reals(), ints);
    expectRefused(bad, "element index");
  }
  {
    auto bad = good;
    auto reals = bad.histories[g].reals();
    reals.pop_back();
    bad.histories[g] = History::fromRecords(reals, bad.histories[g].ints());
    expectRefused(bad, "short record");
  }
  {
    auto bad = good;
    bad.state.t = std::numeric_limits<double>::quiet_NaN();
    expectRefused(bad, "NaN time");
  }
  {
    auto bad = good;
    bad.state.control.dt = 0.0;
    expectRefused(bad, "zero step");
  }
  {
    auto bad = good;
    bad.termNames[g] = "membranes";
    expectRefused(bad, "term names");
  }
  EXPECT_EQ(refused, cases);
}
