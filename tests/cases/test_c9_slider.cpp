// The half-scale C-9 with its slider (cases/c9_slider.toml, central differences as shipped)
// through its first hand-overs: the first second of the 5 s run. Grommets pass line nodes
// (head on or beside them, F12b) in the step where they do, so no step is cut; the slider reefs
// the canopy, and the canopy keeps opening while the slider comes down the lines
// (docs/applications/c9.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "app/RunCase.hpp"
#include "case/CaseSpec.hpp"

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
