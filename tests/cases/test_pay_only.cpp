// "Pay only for what the scene uses" (issue 8, item 4): a cable-only scene, a membrane-only scene
// and a full scene (membrane + cables + sliding group + drag + pressure), each run with and
// without a VTU series. The work counters of the run (kernel evaluations per kind of term,
// slider searches, energies, output frames) show that no drag, sliding-search, membrane or
// output work happens where the scene declares none, and which terms the system builds.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/RunCase.hpp"
#include "case/CaseSpec.hpp"
#include "solver/StructuralSystem.hpp"
#include "support/Scenes.hpp"

using namespace chute;
using chute::testing::writeCase;

namespace {

// Pieces of the scenes. Units m, kg, s, N.
const char* kLines = R"(
[materials.line]
E = 1.0e9
area = 1.0e-6
density = 1000.0
[[cables]]
name = "risers"
material = "line"
path = ["top", "payload"]
elements_per_segment = 4
prestrain = 1.0e-4
)";
const char* kSliding = R"(
[materials.rope]
E = 1.0e9
area = 1.0e-6
[[sliding_groups]]
name = "reefing"
material = "rope"
path = ["left", "ring", "right"]
sliders = ["ring"]
elements = 4
prestrain = 1.0e-4
[[point_masses]]
node = "ring"
mass = 0.05
)";
const char* kMembrane = R"(
[materials.fabric]
kind = "membrane"
E = 5.0e8
nu = 0.3
thickness = 1.0e-4
density = 1000.0
[[membranes]]
name = "canopy"
material = "fabric"
mesh = "rectangle"
corner = [-0.5, -0.5, 0.0]
size = [1.0, 1.0, 0.0]
divisions = [4, 4]
element = "quad"
prestrain = 1.0e-3
)";
const char* kSolver = R"(
[solver]
dt = 1.0e-3
t_end = 0.02
rho_inf = 0.8
[output]
every = 2
)";
const char* kVtu = R"(
[output.vtu]
every = 5
)";

std::string nodes(bool lines, bool sliding) {
  std::string s = "[nodes]\n";
  if (lines) s += "top = [0.0, 0.0, 0.0]\npayload = [0.0, 0.0, -0.5]\n";
  if (sliding)
    s += "left = [-0.5, -0.5, 0.0]\nring = [0.0, -0.5, -0.2]\nright = [0.5, -0.5, 0.0]\n";
  return s;
}

std::string scene(const std::string& kind, bool vtu) {
  const bool lines = kind != "membrane", membrane = kind != "cable", full = kind == "full";
  std::string s = nodes(lines, full);
  if (membrane) s += kMembrane;
  if (lines) s += kLines;
  if (full) s += kSliding;
  s += "[boundary]\n";
  if (lines && !membrane) s += "fixed = [\"top\"]\n";
  if (full) s += "fixed = [\"top\", \"left\", \"right\", \"canopy.c00\", \"canopy.c10\"]\n";
  if (membrane && !full) s += "fixed = [\"canopy.c00\", \"canopy.c10\", \"canopy.c11\"]\n";
  s += "[loads]\ngravity = [0.0, 0.0, -9.81]\n";
  if (full)
    s += R"(
[[loads.pressure]]
membranes = "canopy"
pressure = 50.0
ramp_time = 0.01
[[loads.drag]]
set = "risers"
diameter = 0.002
cd = 1.2
air_density = 1.2
wind = [0.0, 0.0, 5.0]
[[loads.drag]]
set = "reefing"
diameter = 0.002
cd = 1.2
air_density = 1.2
wind = [0.0, 0.0, 5.0]
[[loads.face_drag]]
membranes = "canopy"
cd = 1.2
air_density = 1.2
wind = [0.0, 0.0, 5.0]
subtract_steady = true
)";
  s += kSolver;
  if (vtu) s += kVtu;
  return s;
}

struct Row {
  std::string name;
  RunResult r;
  std::vector<std::string> terms;
  long lineElements = 0, membranes = 0;
};

Row run(const std::string& kind, bool vtu) {
  const std::string name = kind + (vtu ? "_vtu" : "");
  const CaseSpec spec = readCase(writeCase("pay_only_" + name, scene(kind, vtu)));
  Row row{name, {}, {}};
  const StructuralSystem sys(spec.model, spec.solver.search);
  for (const auto& t : sys.terms()) row.terms.push_back(t->name());
  row.lineElements = static_cast<long>(spec.model.cables.size());
  for (const auto& g : spec.model.groups) row.lineElements += g.numElements();
  row.membranes = static_cast<long>(spec.model.membranes.size());
  const std::string out = ::testing::TempDir() + "pay_only_out_" + name;
  std::filesystem::remove_all(out);
  row.r = runCase(spec, RunOptions::writingTo(out));
  return row;
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ",") + x;
  return s;
}
}  // namespace

TEST(PayOnly, NoWorkForWhatTheSceneDoesNotDeclare) {
  std::vector<Row> rows;
  for (const char* kind : {"cable", "membrane", "full"})
    for (bool vtu : {false, true}) rows.push_back(run(kind, vtu));

  std::printf(
      "\nwork counters (kernel evaluations per element per residual evaluation; searches per "
      "slider)\n%-13s %6s %7s %7s %7s %6s %7s %7s %6s %6s %7s %6s %6s %5s %5s  %s\n",
      "scene", "steps", "line", "sliding", "lmass", "pmass", "membr", "press", "drag", "fdrag",
      "search", "energy", "frames", "vtuS", "vtuF", "terms built");
  for (const auto& row : rows) {
    const auto& w = row.r.work;
    std::printf("%-13s %6ld %7ld %7ld %7ld %6ld %7ld %7ld %6ld %6ld %7ld %6ld %6ld %5ld %5ld  %s\n",
                row.name.c_str(), row.r.steps, w.lineElastic, w.sliding, w.lineMass, w.pointMass,
                w.membrane, w.pressure, w.drag, w.faceDrag, w.sliderSearch, w.energy, w.sceneFrames,
                w.vtuSeries, w.vtuFrames, joined(row.terms).c_str());
  }

  for (const auto& row : rows) {
    SCOPED_TRACE(row.name);
    ASSERT_EQ(row.r.status, RunStatus::Completed) << row.r.reason;
    const auto& w = row.r.work;
    const bool vtu = row.name.find("_vtu") != std::string::npos;
    const bool full = row.name.rfind("full", 0) == 0;
    const bool cable = row.name.rfind("cable", 0) == 0;
    const bool membrane = row.name.rfind("membrane", 0) == 0;
    // Output work only when a VTU series is asked for.
    if (vtu) {
      EXPECT_EQ(w.vtuSeries, 1);
      EXPECT_GT(w.vtuFrames, 0);
      EXPECT_EQ(w.sceneFrames, w.vtuFrames);
    } else {
      EXPECT_EQ(w.vtuSeries, 0);
      EXPECT_EQ(w.vtuFrames, 0);
      EXPECT_EQ(w.sceneFrames, 0);
    }
    // One energy evaluation per probe row (the probes and the drift share it), and the energy
    // balance's (solver/EnergyMonitor.hpp): one per step, one at the start, two for the floor
    // m |g| L of its scale (every scene here has gravity).
    EXPECT_EQ(w.energy, static_cast<long>(row.r.times.size()) + row.r.steps + 1 + 2);
    // No scene here declares [contact]: no contact work at all.
    EXPECT_EQ(w.contact, 0);
    EXPECT_EQ(w.contactLists, 0);
    if (cable) {
      EXPECT_GT(w.lineElastic, 0);
      EXPECT_EQ(w.membrane, 0);
      EXPECT_EQ(w.pressure, 0);
      EXPECT_EQ(w.drag, 0);
      EXPECT_EQ(w.faceDrag, 0);
      EXPECT_EQ(w.sliding, 0);
      EXPECT_EQ(w.sliderSearch, 0);
      EXPECT_EQ(w.pointMass, 0);
      EXPECT_EQ(row.r.timings.searches, 0);
      EXPECT_EQ(row.terms, std::vector<std::string>{"cables"});
    }
    if (membrane) {
      EXPECT_GT(w.membrane, 0);
      EXPECT_EQ(w.lineElastic, 0);
      EXPECT_EQ(w.lineMass, 0);
      EXPECT_EQ(w.sliding, 0);
      EXPECT_EQ(w.sliderSearch, 0);
      EXPECT_EQ(w.pressure, 0);
      EXPECT_EQ(w.drag, 0);
      EXPECT_EQ(w.faceDrag, 0);
      EXPECT_EQ(w.pointMass, 0);
      EXPECT_EQ(row.r.timings.searches, 0);
      EXPECT_EQ(row.terms, std::vector<std::string>{"membranes"});
    }
    if (full) {
      for (long c : {w.lineElastic, w.sliding, w.lineMass, w.pointMass, w.membrane, w.pressure,
                     w.drag, w.faceDrag, w.sliderSearch})
        EXPECT_GT(c, 0);
      EXPECT_EQ(row.r.timings.searches, w.sliderSearch);  // one group, one slider
      EXPECT_EQ(row.terms.size(), 7u);
    }
  }
  // The same scene with and without VTU does the same mechanical work; a VTU frame adds two
  // residual evaluations (reactions and applied loads), nothing else.
  for (size_t k = 0; k + 1 < rows.size(); k += 2) {
    const auto &plain = rows[k], &with = rows[k + 1];
    SCOPED_TRACE(with.name);
    const long frames = with.r.work.sceneFrames;
    EXPECT_EQ(with.r.steps, plain.r.steps);
    EXPECT_EQ(with.r.work.membrane - plain.r.work.membrane, 2 * frames * with.membranes);
    EXPECT_EQ(with.r.work.lineElastic + with.r.work.sliding -
                  (plain.r.work.lineElastic + plain.r.work.sliding),
              2 * frames * with.lineElements);
  }
}

// Contact only with a [contact] section: cases/contact_drop.toml as shipped (the sheet bounces on
// the floor) and with contact.enabled = false. Without it no contact term is built and no pair
// distance computed, no candidate list built.
TEST(PayOnly, ContactOnlyWhereTheCaseAsksForIt) {
  const std::string file = std::string(CHUTE_SOURCE_DIR) + "/cases/contact_drop.toml";
  for (const bool on : {true, false}) {
    const CaseSpec spec =
        readCase(file, {"solver.t_end=0.1", on ? "contact.enabled=true" : "contact.enabled=false"});
    const StructuralSystem sys(spec.model, spec.solver.search);
    std::vector<std::string> terms;
    for (const auto& t : sys.terms()) terms.push_back(t->name());
    const RunResult r = runCase(spec, RunOptions{});
    ASSERT_EQ(r.status, RunStatus::Completed) << r.reason;
    std::printf("contact_drop %s contact: terms %s; %ld pair distances, %ld candidate lists\n",
                on ? "with" : "without", joined(terms).c_str(), r.work.contact,
                r.work.contactLists);
    const bool built = std::find(terms.begin(), terms.end(), "contact") != terms.end();
    EXPECT_EQ(built, on);
    if (on) {
      EXPECT_GT(r.work.contact, 0);
      EXPECT_GT(r.work.contactLists, 0);
    } else {
      EXPECT_EQ(r.work.contact, 0);
      EXPECT_EQ(r.work.contactLists, 0);
    }
  }
}
