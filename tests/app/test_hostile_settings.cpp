// Legal settings that would never end, restarts that would change the physics, and runs that end
// badly, through the `chute` command as a user types it: each refused with one line and a
// documented status before anything is written, or ended with its output whole and truthful
// (docs/limits.md, docs/exit-codes.md). One test per class of the second hostile-input round.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/RunChute.hpp"
#include "support/TempDir.hpp"

namespace fs = std::filesystem;
using chute::testing::bytes;
using chute::testing::lines;
using chute::testing::Outcome;

namespace {
const std::string kChute = CHUTE_BINARY;
const std::string kBead = CHUTE_SOURCE_DIR "/cases/bead_5.toml";
const std::string kDrop = CHUTE_SOURCE_DIR "/cases/contact_drop.toml";

Outcome runChute(const std::string& args) {
  return chute::testing::runChute(kChute, args);
}

fs::path scratch(const std::string& name, bool create = false) {
  return chute::testing::freshTempDir("chute_hostile_", name, create);
}

// Refused: status 2, one stderr line holding `fragment`, and no output directory.
void expectRefused(const std::string& what, const std::string& args, const std::string& fragment) {
  const fs::path out = scratch("refused");
  const Outcome o = runChute(args + " --out " + out.string());
  std::printf("%-44s -> %d: %s", what.c_str(), o.status, o.err.c_str());
  EXPECT_EQ(o.status, 2) << what;
  EXPECT_EQ(lines(o.err), 1) << what;
  EXPECT_NE(o.err.find(fragment), std::string::npos) << what << ": " << o.err;
  EXPECT_FALSE(fs::exists(out)) << what << ": the refused run created its output directory";
}

std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream s(line);
  for (std::string c; std::getline(s, c, ',');) cells.push_back(c);
  return cells;
}
}  // namespace

// Output settings that are legal numbers but would write without end (4e11 rows, 4e9 frames).
TEST(HostileSettings, OutputIntervalsThatWouldNeverEndAreRefused) {
  expectRefused("output.interval = 1e-11", "run " + kBead + " --set output.interval=1e-11",
                "output.max_rows");
  expectRefused("output.vtu.interval = 1e-9",
                "run " CHUTE_SOURCE_DIR "/cases/c9_slider.toml --set output.vtu.interval=1e-9",
                "max_frames");
}

// Explicit runs whose stable step would take more than the 1e9 steps a run may take: refused,
// naming the key, before anything is written.
TEST(HostileSettings, ExplicitStepsThatWouldNeverEndAreRefused) {
  expectRefused("density 1e-300", "run " + kDrop + " --set materials.cloth.density=1e-300",
                "without mass");
  expectRefused("E 1e300", "run " + kDrop + " --set materials.cloth.E=1e300",
                "a stiffness out of scale");
  expectRefused("safety_factor 1e-300", "run " + kDrop + " --set solver.safety_factor=1e-300",
                "solver.safety_factor");
  expectRefused("stiffness_damping 1e3", "run " + kDrop + " --set solver.stiffness_damping=1e3",
                "solver.stiffness_damping");
  // A line's E overridden where the case gives both E and density: the override is named.
  expectRefused("tape E 1e300",
                "run " CHUTE_SOURCE_DIR "/cases/c9_slider.toml --set materials.tape.E=1e300",
                "--set materials.tape.E=1e300: materials.tape.E:");
}

// Selective mass scaling: a quantile outside [0, 0.5], or asked for together with target_dt.
TEST(HostileSettings, MassScalingQuantileOutOfRangeOrWithTargetDtIsRefused) {
  expectRefused("mass_scaling_quantile 0.9",
                "run " + kDrop + " --set solver.mass_scaling_quantile=0.9",
                "solver.mass_scaling_quantile");
  expectRefused("mass_scaling_quantile -0.1",
                "run " + kDrop + " --set solver.mass_scaling_quantile=-0.1",
                "solver.mass_scaling_quantile");
  expectRefused(
      "mass_scaling_quantile with target_dt",
      "run " + kDrop + " --set solver.mass_scaling_quantile=0.01 --set solver.target_dt=1e-4",
      "solver.mass_scaling_quantile");
}

// A line of 100,000 elements: the work per step grows with the elements, not their square (two
// steps took more than 180 s, 20,000 elements 161 s; now seconds).
TEST(HostileSettings, ALongLineCostsInProportionToItsElements) {
  const fs::path dir = scratch("long_line", true);
  const fs::path caseFile = dir / "line.toml";
  std::ofstream(caseFile) << R"(name = "line"
[nodes]
a = [0.0, 0.0, 0.0]
b = [100.0, 0.0, 0.0]
[materials.rope]
kind = "cable"
E = 1.0e9
area = 1.0e-4
density = 1000.0
[[cables]]
name = "long"
material = "rope"
path = ["a", "b"]
elements_per_segment = 100000
[boundary]
fixed = ["a"]
[loads]
gravity = [0.0, 0.0, -9.81]
[solver]
type = "dynamic"
dt = 1.0e-3
t_end = 2.0e-3
)";
  const auto t0 = std::chrono::steady_clock::now();
  const Outcome o =
      runChute("run " + caseFile.string() + " --quiet --out " + (dir / "out").string());
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("100,000-element line, 2 implicit steps: status %d in %.1f s\n", o.status, s);
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_LT(s, 90.0) << "a line's cost grew faster than its elements";
}

// A restart continues the checkpointed run: only the end time (and output limits) may differ.
// Every physics or output setting given anew is refused, with the output left as it was; a
// refused restart into an empty directory leaves nothing there; an end before the checkpoint is
// refused.
TEST(HostileSettings, ARestartRefusesOtherPhysicsAndLeavesNothing) {
  const fs::path dir = scratch("restart", true);
  const fs::path out = dir / "out";
  const Outcome first = runChute("run " + kBead + " --quiet --set solver.t_end=0.1 " +
                                 "--checkpoint-every 2 --out " + out.string());
  ASSERT_EQ(first.status, 0) << first.err;
  const fs::path ckpt = out / "checkpoint.cbor";
  ASSERT_TRUE(fs::exists(ckpt));
  const std::string probes = bytes(out / "probes.csv");
  for (const std::string set :
       {"loads.gravity=[0.0, 0.0, -5.0]", "materials.rope.E=2e10", "point_masses.0.mass=2.0",
        "output.interval=0.02", "solver.energy_tolerance=0.5", "solver.rho_inf=0.5"}) {
    const Outcome o = runChute("run " + kBead + " --quiet --set solver.t_end=0.2 --set '" + set +
                               "' --restart " + ckpt.string() + " --out " + out.string());
    std::printf("restart with --set %-32s -> %d: %s", set.c_str(), o.status, o.err.c_str());
    EXPECT_EQ(o.status, 2) << set;
    EXPECT_EQ(lines(o.err), 1) << set;
    EXPECT_EQ(bytes(out / "probes.csv"), probes) << set << ": the output changed";
  }
  const Outcome early = runChute("run " + kBead + " --quiet --set solver.t_end=0.05 --restart " +
                                 ckpt.string() + " --out " + out.string());
  std::printf("restart to t_end 0.05 < the checkpoint's time -> %d: %s", early.status,
              early.err.c_str());
  EXPECT_EQ(early.status, 2);
  EXPECT_NE(early.err.find("before the checkpoint's time"), std::string::npos) << early.err;
  EXPECT_EQ(bytes(out / "probes.csv"), probes);
  const fs::path empty = dir / "empty";
  fs::create_directories(empty);
  const Outcome into = runChute("run " + kBead + " --quiet --set solver.t_end=0.2 --restart " +
                                ckpt.string() + " --out " + empty.string());
  std::printf("restart into an empty directory -> %d: %s", into.status, into.err.c_str());
  EXPECT_EQ(into.status, 2);
  EXPECT_TRUE(fs::is_empty(empty)) << "a refused restart left something (a lock?)";
}

// A run that ends unstable writes as its last probe row the last state whose energy balance
// held, not the blown-up one: the row's time is the summary's final time and every value is
// finite.
TEST(HostileSettings, AnUnstableRunsLastRowIsItsLastGoodState) {
  const fs::path out = scratch("unstable");
  const Outcome o =
      runChute("run " CHUTE_SOURCE_DIR "/cases/stress_snatch.toml --quiet " +
               std::string("--set solver.t_end=1 --set materials.line.density=10000 ") + "--out " +
               out.string());
  std::printf("snatch with a massive line: status %d: %s", o.status, o.err.c_str());
  ASSERT_EQ(o.status, 3) << "expected to end unstable";
  std::ifstream csv(out / "probes.csv");
  std::string line, last;
  while (std::getline(csv, line))
    if (!line.empty()) last = line;
  const auto cells = splitCsv(last);
  ASSERT_FALSE(cells.empty());
  for (const auto& c : cells) EXPECT_TRUE(std::isfinite(std::stod(c))) << last;
  const std::string summary = bytes(out / "summary.json");
  const auto at = summary.find("\"final_time\":");
  ASSERT_NE(at, std::string::npos);
  const double finalTime = std::stod(summary.substr(at + 13));
  std::printf("last row at t = %s, summary final_time %.9g\n", cells[0].c_str(), finalTime);
  EXPECT_NEAR(std::stod(cells[0]), finalTime, 1e-12 * (1.0 + finalTime));
}

// A --set value with a newline in it: still one stderr line (the newline shown escaped).
TEST(HostileSettings, ASetValueWithANewlineGivesOneLine) {
  expectRefused("--set with a newline", "run " + kBead + " --set $'solver.dt=1\\n2'", "solver.dt");
}

// `chute mesh parachute --case` writes a case only if `chute run` would start it: a payload of
// 1e-6 on a box's corners set a stable step of 5e-10 s (4e9 steps), and the case was written.
TEST(HostileSettings, AGeneratedCaseARunWouldRefuseIsNotWritten) {
  const fs::path dir = scratch("generated", true);
  const fs::path msh = dir / "p.msh", toml = dir / "p.toml";
  const Outcome o = runChute(
      "mesh parachute --gores 8 --diameter 2 --line-length 2 --element-size 0.4 "
      "--line-elements 4 --payload-box 0.2,0.2,0.2 --riser-length 0.5 --payload-mass 1e-6 --out " +
      msh.string() + " --case " + toml.string() + " --quiet");
  std::printf("payload 1e-6 on a box -> %d: %s", o.status, o.err.c_str());
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(lines(o.err), 1);
  EXPECT_NE(o.err.find("--payload-mass: the case would not run"), std::string::npos) << o.err;
  EXPECT_FALSE(fs::exists(msh));
  EXPECT_FALSE(fs::exists(toml));
}

// A generator refused after it has meshed (the case it would write is one a run refuses) leaves
// the files --out and --case name as they were: it wrote over them and removed them on refusing,
// saying "nothing written" (found by the third hostile-input attack).
TEST(HostileSettings, ARefusedGeneratorLeavesTheFilesItNamedAsTheyWere) {
  const fs::path dir = scratch("generated_over", true);
  const fs::path msh = dir / "mine.msh", toml = dir / "mine.toml";
  std::ofstream(msh) << "precious mesh\n";
  std::ofstream(toml) << "precious case\n";
  const Outcome o = runChute(
      "mesh parachute --gores 8 --diameter 2 --line-length 2 --element-size 0.4 "
      "--line-elements 4 --payload-box 0.2,0.2,0.2 --riser-length 0.5 --payload-mass 1e-6 --out " +
      msh.string() + " --case " + toml.string() + " --quiet");
  std::printf("over existing files -> %d: %s", o.status, o.err.c_str());
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(lines(o.err), 1);
  EXPECT_EQ(bytes(msh), "precious mesh\n");
  EXPECT_EQ(bytes(toml), "precious case\n");
  // Nothing else left in the directory (the files kept aside while it meshed included).
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 2);
}

// Outputs that cannot be files are refused before meshing: a FIFO as --case (the generator waited
// for a reader for ever, its mesh written), a link to nothing (a link to the --out mesh passed the
// check that the two differ, and the case was written over the mesh).
TEST(HostileSettings, AGeneratorRefusesAFifoOrALinkToNothingBeforeMeshing) {
  const fs::path dir = scratch("generated_targets", true);
  const std::string args =
      "mesh parachute --gores 6 --diameter 1 --line-length 1 --element-size 0.3 --units si ";
  ASSERT_EQ(::mkfifo((dir / "f.toml").c_str(), 0644), 0);
  const auto t0 = std::chrono::steady_clock::now();
  const Outcome fifo = runChute(args + "--out " + (dir / "q.msh").string() + " --case " +
                                (dir / "f.toml").string() + " --quiet");
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("--case a FIFO -> %d in %.2f s: %s", fifo.status, s, fifo.err.c_str());
  EXPECT_EQ(fifo.status, 2);
  EXPECT_NE(fifo.err.find("not a regular file"), std::string::npos) << fifo.err;
  EXPECT_FALSE(fs::exists(dir / "q.msh"));
  EXPECT_LT(s, 30.0);
  fs::create_symlink("t.msh", dir / "tl.toml");
  const Outcome link = runChute(args + "--out " + (dir / "t.msh").string() + " --case " +
                                (dir / "tl.toml").string() + " --quiet");
  std::printf("--case a link to the coming mesh -> %d: %s", link.status, link.err.c_str());
  EXPECT_EQ(link.status, 2);
  EXPECT_NE(link.err.find("link to nothing"), std::string::npos) << link.err;
  EXPECT_FALSE(fs::exists(dir / "t.msh"));
  EXPECT_TRUE(fs::is_symlink(dir / "tl.toml"));
}

// `chute couple --window` longer than the run ran no window and reported "completed" at t = 0;
// one shorter than the case's least step started the run and failed in it (exit 3, output
// written). The first runs to the end in one window, the second is refused before anything.
TEST(HostileSettings, ACoupledRunsWindowIsCheckedAndNeverSkipsTheRun) {
  const std::string coupled = CHUTE_SOURCE_DIR "/cases/canopy_coupled.toml";
  const fs::path out = scratch("coupled_long_window");
  const Outcome o =
      runChute("couple " + coupled + " --t-end 0.002 --window 1e12 --quiet --out " + out.string());
  std::printf("--window 1e12 -> %d: %s", o.status, o.err.c_str());
  ASSERT_EQ(o.status, 0) << o.err;
  const std::string summary = bytes(out / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"completed\""), std::string::npos) << summary;
  const auto at = summary.find("\"final_time\": ");
  ASSERT_NE(at, std::string::npos) << summary;
  EXPECT_NEAR(std::stod(summary.substr(at + 14)), 0.002, 1e-12) << summary;
  expectRefused("couple --window 1e-20", "couple " + coupled + " --window 1e-20", "--window");
  expectRefused("couple --t-end 1e-300", "couple " + coupled + " --t-end 1e-300", "--t-end");
}

// Sub-iterations per window are bounded: 1e9 with an unreachable --tolerance kept the first
// window going for hours (each sub-iteration a structural solve).
TEST(HostileSettings, ACoupledRunsSubIterationsAreBounded) {
  expectRefused("couple --max-iterations 1e9",
                "couple " CHUTE_SOURCE_DIR "/cases/canopy_coupled.toml --max-iterations 1000000000",
                "--max-iterations");
}

// `chute mesh cluster` wrote a case `chute run` refuses (risers of 1e-9: a step of 4e-21 s): its
// risers are now checked as a parachute's (0 or at least D/1000), and its case is read back and
// judged before it is kept, as the parachute's is.
TEST(HostileSettings, AClusterWithRisersNoRunCanStepIsRefused) {
  const fs::path dir = scratch("cluster_risers", true);
  const Outcome o = runChute(
      "mesh cluster --gores 6 --diameter 1.0 --line-length 0.9 --element-size 0.25 "
      "--payload-mass 3 --units si --t-end 0.01 --canopies 2 --riser-length 1e-9 --out " +
      (dir / "c.msh").string() + " --case " + (dir / "c.toml").string() + " --quiet");
  std::printf("cluster risers 1e-9 -> %d: %s", o.status, o.err.c_str());
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(lines(o.err), 1);
  EXPECT_NE(o.err.find("--riser-length"), std::string::npos) << o.err;
  EXPECT_FALSE(fs::exists(dir / "c.msh"));
  EXPECT_FALSE(fs::exists(dir / "c.toml"));
}

// A finite wind so large that the coupled flow law's pressures overflow: on the start, refused
// before anything is written (it was status 2 after the output was made); after a window, the
// run ends as diverged with its last good window (it was status 1, an internal error).
TEST(HostileSettings, ACoupledFlowsPressuresThatOverflowAreBadInputOrADivergedRun) {
  const std::string coupled = CHUTE_SOURCE_DIR "/cases/canopy_coupled.toml";
  expectRefused("couple --wind 0 0 1e160", "couple " + coupled + " --wind 0 0 1e160",
                "pressures on the start are not finite");
  const fs::path out = scratch("coupled_overflow");
  const Outcome o = runChute("couple " + coupled + " --wind 1e200 0 0 --t-end 0.01 --quiet --out " +
                             out.string());
  std::printf("--wind 1e200 0 0 -> %d: %s", o.status, o.err.c_str());
  EXPECT_EQ(o.status, 3);
  EXPECT_EQ(lines(o.err), 1);
  EXPECT_NE(o.err.find("not finite"), std::string::npos) << o.err;
  EXPECT_NE(bytes(out / "summary.json").find("\"status\": \"diverged\""), std::string::npos);
}

// A static run that fails writes its last equilibrium at the load factor it was reached at: the
// Hencky membrane under 1e300 reached none, and its start was written as the state at the full
// load (t = 1, no deflection) with final_time 1 and 30 steps (third hostile-input attack).
TEST(HostileSettings, AFailedStaticRunsLastRowIsWhereItsLastEquilibriumIs) {
  const fs::path out = scratch("static_failed");
  const Outcome o =
      runChute("run " CHUTE_SOURCE_DIR "/cases/hencky.toml --quiet " +
               std::string("--set loads.pressure.0.pressure=1e300 --out ") + out.string());
  std::printf("hencky under 1e300: status %d: %s", o.status, o.err.c_str());
  EXPECT_EQ(o.status, 3);
  std::ifstream in(out / "probes.csv");
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  const auto cells = splitCsv(last);
  ASSERT_FALSE(cells.empty());
  EXPECT_EQ(std::stod(cells[0]), 0.0) << last;  // no increment converged: the start, unloaded
  const std::string summary = bytes(out / "summary.json");
  EXPECT_NE(summary.find("\"final_time\": 0.0"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"steps\": 0"), std::string::npos) << summary;
}

// The output intervals of a generated case (limits.md names them; the generator checked them but
// the command line did not take them): given, they are the case's; beyond what a case writes by
// default, refused by name before meshing.
TEST(HostileSettings, AGeneratedCasesOutputIntervalsAreOptionsAndBounded) {
  const fs::path dir = scratch("generated_intervals", true);
  const std::string args =
      "mesh parachute --gores 6 --diameter 1 --line-length 1 --element-size 0.3 --units si "
      "--t-end 0.1 --out " +
      (dir / "p.msh").string() + " --case " + (dir / "p.toml").string() + " --quiet ";
  ASSERT_EQ(runChute(args + "--probe-interval 0.02 --vtu-interval 0").status, 0);
  const std::string text = bytes(dir / "p.toml");
  EXPECT_NE(text.find("[output]\ninterval = 0.02"), std::string::npos) << text;
  EXPECT_EQ(text.find("[output.vtu]"), std::string::npos) << text;
  const Outcome rows = runChute(args + "--probe-interval 1e-8");
  std::printf("--probe-interval 1e-8 -> %d: %s", rows.status, rows.err.c_str());
  EXPECT_EQ(rows.status, 2);
  EXPECT_NE(rows.err.find("--probe-interval"), std::string::npos) << rows.err;
}

// A static load that equilibrium follows only in increments halved near their floor (gravity
// 1e9 on the capstan belt) converged one 1e-8 step of the load after another for hours; the
// load stepping's increments are bounded (docs/limits.md) and the run ends as diverged.
TEST(HostileSettings, AStaticLoadOfEndlessIncrementsEnds) {
  const fs::path out = scratch("static_load");
  const auto t0 = std::chrono::steady_clock::now();
  const Outcome o = runChute("run " CHUTE_SOURCE_DIR "/cases/capstan_belt.toml --quiet " +
                             std::string("--set loads.gravity.0=1e9 --out ") + out.string());
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("capstan belt under gravity 1e9: status %d in %.1f s: %s", o.status, s,
              o.err.c_str());
  EXPECT_EQ(o.status, 3);
  EXPECT_EQ(lines(o.err), 1);
  EXPECT_NE(o.err.find("load increments"), std::string::npos) << o.err;
  EXPECT_LT(s, 60.0);
}

// A first load factor so small that its inverse overflows (5e-324, in the documented (0, 1]):
// the geometric growth came out infinite, the increment after the first infinite, and halving it
// never ended (found by the attack's mutated Hencky case). The run now steps its 30 increments.
TEST(HostileSettings, ASubnormalFirstLoadFactorStillStepsToTheLoad) {
  const fs::path out = scratch("subnormal_load");
  const auto t0 = std::chrono::steady_clock::now();
  const Outcome o =
      runChute("run " CHUTE_SOURCE_DIR "/cases/hencky.toml --quiet " +
               std::string("--set solver.initial_load_factor=5e-324 --out ") + out.string());
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("hencky from load factor 5e-324: status %d in %.1f s: %s\n", o.status, s,
              o.err.c_str());
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_LT(s, 60.0);
  // The same equilibrium as from the case's own first factor (1e-6): the last probe rows agree.
  const fs::path ref = scratch("subnormal_load_reference");
  ASSERT_EQ(
      runChute("run " CHUTE_SOURCE_DIR "/cases/hencky.toml --quiet --out " + ref.string()).status,
      0);
  auto lastRow = [](const fs::path& dir) {
    std::ifstream in(dir / "probes.csv");
    std::string line, last;
    while (std::getline(in, line))
      if (!line.empty()) last = line;
    std::vector<double> v;
    for (const auto& cell : splitCsv(last)) v.push_back(std::stod(cell));
    return v;
  };
  const auto a = lastRow(out), b = lastRow(ref);
  ASSERT_EQ(a.size(), b.size());
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
    worst = std::max(worst, std::abs(a[i] - b[i]) / std::max(1.0, std::abs(b[i])));
  std::printf("largest difference of the last probe row from the reference run: %.3g\n", worst);
  EXPECT_LT(worst, 1e-6);
}

// An output path given empty (an unset shell variable in `--out "$DIR"`) is refused by name with
// status 2 by every verb that writes, instead of falling back to the default in silence; a case
// file next to it is not written.
TEST(HostileSettings, AnEmptyOutputPathIsRefusedByName) {
  const fs::path dir = scratch("empty_out", true);
  const std::string caseFile = (dir / "p.toml").string();
  // (verb, arguments, the option named)
  const std::vector<std::array<std::string, 3>> verbs = {
      {"run", "run " + kBead + " --out ''", "--out"},
      {"couple", "couple " + kBead + " --out ''", "--out"},
      {"render", "render " + dir.string() + " --out ''", "--out"},
      {"plot", "plot " + dir.string() + " --out ''", "--out"},
      {"mesh parachute", "mesh parachute --out '' --case " + caseFile, "--out"},
      {"mesh parachute --case", "mesh parachute --out " + (dir / "p.msh").string() + " --case ''",
       "--case"},
      {"mesh geo", "mesh geo " + (dir / "x.geo").string() + " --out ''", "--out"},
  };
  for (const auto& [what, args, option] : verbs) {
    const Outcome o = runChute(args);
    std::printf("%-24s -> %d: %s", what.c_str(), o.status, o.err.c_str());
    EXPECT_EQ(o.status, 2) << what;
    EXPECT_EQ(lines(o.err), 1) << what;
    EXPECT_NE(o.err.find(option + ": an empty path"), std::string::npos) << what << ": " << o.err;
  }
  EXPECT_FALSE(fs::exists(caseFile));
  EXPECT_FALSE(fs::exists(dir / "p.msh"));
}

// A free node in no element, load or point mass (a stray entry of [nodes]): refused by name with
// status 2 before anything is written, implicit or explicit (an implicit run had halved its first
// step down to dt_min and stopped with status 3; an explicit one named it as massless).
TEST(HostileSettings, AFreeNodeNothingTouchesIsRefusedByName) {
  const fs::path dir = scratch("stray", true);
  std::ifstream in(CHUTE_SOURCE_DIR "/cases/pulley.toml");
  std::stringstream text;
  text << in.rdbuf();
  std::string toml = text.str();
  const std::string anchor = "right_end = [0.0, 0.0, -60.0]\n";
  const size_t at = toml.find(anchor);
  ASSERT_NE(at, std::string::npos);
  toml.insert(at + anchor.size(), "stray = [5.0, 0.0, 0.0]\n");
  const fs::path stray = dir / "stray.toml";
  std::ofstream(stray) << toml;
  expectRefused("stray node, implicit", "run " + stray.string(), "nodes.stray: 1 free node(s)");
  expectRefused("stray node, explicit",
                "run " + stray.string() + " --set solver.integrator='\"central_difference\"'",
                "nodes.stray: 1 free node(s)");
}

// `chute mesh parachute --config`: a number written as a TOML string is refused by name, as the
// case reader refuses one, rather than read as the command line's text.
TEST(HostileSettings, AParameterFileNumberGivenAsAStringIsRefused) {
  const fs::path dir = scratch("config_string", true);
  const fs::path config = dir / "p.toml";
  std::ofstream(config) << "gores = \"8\"\ndiameter = 5.0\nline-length = 6.0\nelement-size = 0.5\n";
  const Outcome o = runChute("mesh parachute --config " + config.string() + " --units si --out " +
                             (dir / "p.msh").string());
  std::printf("gores = \"8\" -> %d: %s", o.status, o.err.c_str());
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(lines(o.err), 1);
  EXPECT_NE(o.err.find("p.toml:1: gores: a number, not a string"), std::string::npos) << o.err;
  EXPECT_FALSE(fs::exists(dir / "p.msh"));
}

// The verbs that draw or read frames back live in a plugin (app/cli/RenderPlugin.hpp): a run never
// loads it, and a plugin that cannot be loaded is named in one line with status 1 (an
// installation fault, docs/exit-codes.md).
TEST(HostileSettings, TheRenderPluginIsLoadedOnlyByTheVerbsThatDraw) {
  const std::string missing = "/nonexistent/libchute_render.so";
  const std::string env = "CHUTE_RENDER_PLUGIN=" + missing + " ";
  const fs::path out = scratch("plugin");
  const Outcome run = chute::testing::runChute(
      kChute, "run " + kBead + " --quiet --set solver.t_end=0.01 --out " + out.string(), env);
  EXPECT_EQ(run.status, 0) << run.err;
  for (const std::string verb : {"render", "plot", "intersections"}) {
    const Outcome o = chute::testing::runChute(kChute, verb + " " + out.string(), env);
    std::printf("%-14s without its plugin -> %d: %s", verb.c_str(), o.status, o.err.c_str());
    EXPECT_EQ(o.status, 1) << verb;
    EXPECT_EQ(lines(o.err), 1) << verb;
    EXPECT_NE(o.err.find(missing), std::string::npos) << verb << ": " << o.err;
  }
  // With the plugin next to chute, the same verb runs (and refuses a run without a series).
  const Outcome found = runChute("intersections " + out.string());
  EXPECT_EQ(found.status, 2) << found.err;
  EXPECT_NE(found.err.find("no .pvd series"), std::string::npos) << found.err;
}
