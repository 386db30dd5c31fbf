// The half-scale C-9 with its slider (cases/c9_slider.toml, central differences as shipped)
// through its first hand-overs: the first second of the 5 s run. Grommets pass line nodes
// (head on or beside them, F12b) in the step where they do, so no step is cut; the slider reefs
// the canopy, and the canopy keeps opening while the slider comes down the lines
// (docs/applications/c9.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "app/RunCase.hpp"
#include "case/CaseSpec.hpp"
#include "model/History.hpp"
#include "solver/StructuralSystem.hpp"

using namespace chute;

namespace {
RunResult runShipped(const std::string& name, double tEnd) {
  const CaseSpec spec = readCase(CHUTE_SOURCE_DIR "/cases/" + name + ".toml",
                                 {"solver.t_end=" + std::to_string(tEnd)});
  return runCase(spec, RunOptions{});
}

// Index of probe column `name`.
long column(const RunResult& r, const std::string& name) {
  const auto col = std::find(r.columns.begin(), r.columns.end(), name) - r.columns.begin();
  EXPECT_LT(col, static_cast<long>(r.columns.size())) << name;
  return col;
}

// Probe column `name` at the output time nearest t.
double at(const RunResult& r, const std::string& name, double t) {
  const auto i =
      std::min_element(r.times.begin(), r.times.end(),
                       [&](double a, double b) { return std::abs(a - t) < std::abs(b - t); }) -
      r.times.begin();
  return r.rows[i][column(r, name)];
}
}  // namespace

TEST(C9Slider, ReefsAndComesDownTheLinesWithoutCuttingSteps) {
  const auto slider = runShipped("c9_slider", 1.0);
  const auto open = runShipped("c9_no_slider", 0.75);
  ASSERT_EQ(slider.status, RunStatus::Completed) << slider.reason;
  ASSERT_EQ(open.status, RunStatus::Completed) << open.reason;
  const long handovers = std::accumulate(slider.handovers.begin(), slider.handovers.end(), 0L);
  const double r75 = at(slider, "skirt.mean", 0.75), r100 = at(slider, "skirt.mean", 1.0);
  const double open75 = at(open, "skirt.mean", 0.75);
  double least = r75;
  const long radius = column(slider, "skirt.mean");
  for (size_t i = 0; i < slider.times.size(); ++i)
    if (slider.times[i] >= 0.75) least = std::min(least, slider.rows[i][radius]);
  std::printf(
      "c9_slider to 1 s: %ld steps, %ld rejected, %ld event retries, %ld line nodes passed, "
      "%.2f Newton/step, %.1f s wall\n  skirt radius at 0.75 s %.3f ft (no slider %.3f), at "
      "1.0 s %.3f, least after 0.75 s %.3f; slider %.2f ft down line 0 at 1.0 s\n",
      slider.steps, slider.rejectedSteps, slider.eventRetries, handovers, slider.newtonPerStep(),
      slider.wallTime, r75, open75, r100, least, at(slider, "slider_0.s", 1.0));
  EXPECT_EQ(slider.eventRetries, 0);
  EXPECT_GE(handovers, 56);                       // past the first two line nodes on every line
  EXPECT_LT(r75, 0.8 * open75);                   // reefed: 2.63 against 3.84 ft when shipped
  EXPECT_GT(r100, r75 + 0.4);                     // still opening: 3.27 ft at 1.0 s when shipped
  EXPECT_GE(least, r75 - 1e-3);                   // and never closing again on the way
  EXPECT_GT(at(slider, "slider_0.s", 1.0), 3.0);  // the grommet came down the line
}

// The explicit step's settling of the sliders (StructuralSystem::settleExplicitMotion), made in
// two parts of the grommets' lines (the parts share no free node: the confluence is held), gives
// the bits of the sources one after the other as they were: every note, then every move onto a
// node in order, then the searches, then the moves at the step's end. Random motions from the
// folded start, large enough to carry sliders past nodes.
TEST(C9Slider, SettlingTheSlidersInTwoPartsGivesTheBitsOfTheSourcesInOrder) {
  const CaseSpec spec = readCase(CHUTE_SOURCE_DIR "/cases/c9_slider.toml", {});
  StructuralSystem parts(spec.model, spec.solver.search), inOrder(spec.model, spec.solver.search);
  for (StructuralSystem* s : {&parts, &inOrder}) s->prepareFor(IntegrationTraits{true, false});
  ASSERT_TRUE(parts.settlesInTwoParts());
  const Eigen::VectorXd x = parts.initialState().x;
  for (StructuralSystem* s : {&parts, &inOrder}) s->commit(CommitPoint{x, 0.0, 0.0, 0.0});
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  long moved = 0, changed = 0;
  for (int trial = 0; trial < 8; ++trial) {
    Eigen::VectorXd motion(x.size());
    const double size = 0.1 * (trial + 1);  // ft; line elements are about 0.4 ft
    for (long d = 0; d < motion.size(); ++d) motion[d] = size * unit(rng);
    for (int d : parts.constrainedDofs()) motion[d] = 0.0;
    Eigen::VectorXd xEnd = x + motion;
    // Every third line's node at the end of its slider's element next to the slider, so that the
    // slider arrives there (a move onto the node).
    for (size_t g = trial % 3; g < spec.model.groups.size(); g += 3) {
      const auto& group = spec.model.groups[g];
      const int node = group.chain[group.initialActive[0] + 1], slider = group.sliders[0];
      for (int c = 0; c < 3; ++c) xEnd[3 * node + c] = xEnd[3 * slider + c] + 1e-8 * unit(rng);
    }
    motion = xEnd - x;
    Eigen::VectorXd a = xEnd, b = xEnd;
    parts.settleExplicitMotion(x, a);
    std::vector<EventSource*> sources;
    for (const auto& t : inOrder.terms())
      if (auto* e = t->events(); e && e->watchesExplicitMotion()) sources.push_back(e);
    for (auto* e : sources) e->noteExplicitMotion(x, motion);
    for (auto* e : sources) e->afterExplicitMotion(x, motion, b);
    inOrder.updateState(b);
    inOrder.onConverged(b);
    EXPECT_TRUE((a.array() == b.array()).all()) << "trial " << trial;
    moved += (a.array() != xEnd.array()).count();
    for (size_t i = 0; i < parts.terms().size(); ++i) {
      History ha, hb, h0;
      parts.terms()[i]->save(ha);
      inOrder.terms()[i]->save(hb);
      EXPECT_TRUE(ha == hb) << parts.terms()[i]->name() << ", trial " << trial;
      parts.terms()[i]->revert();
      parts.terms()[i]->save(h0);
      changed += !(ha == h0);
      inOrder.terms()[i]->revert();
    }
  }
  std::printf(
      "settled in two parts: %ld coordinates moved onto nodes, %ld group states changed "
      "in 8 trials, the same bits as in order\n",
      moved, changed);
  EXPECT_GT(moved, 0);
  EXPECT_GT(changed, 0);
}
