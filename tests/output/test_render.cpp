// `chute render` and `chute plot` from the command line, with DISPLAY unset (they must start
// their own Xvfb): non-blank PNGs of the requested size, and clear errors for bad requests.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "render/ColourLayers.hpp"
#include "render/VirtualDisplay.hpp"
#include "support/TempDir.hpp"

namespace fs = std::filesystem;

namespace {
const std::string kChute = CHUTE_BINARY;

fs::path freshDir(const std::string& name) {
  return chute::testing::freshTempDir("chute_test_render_", name);
}

int run(const std::string& args) {
  // No display: chute must cope by itself.
  const std::string cmd = "env -u DISPLAY " + kChute + " " + args + " > /dev/null";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

struct Image {
  int width = 0, height = 0;
  double spread = 0.0;  // standard deviation of the grey level over all pixels
};

Image readPng(const fs::path& p) {
  vtkNew<vtkPNGReader> r;
  r->SetFileName(p.c_str());
  r->Update();
  Image im;
  int dims[3];
  r->GetOutput()->GetDimensions(dims);
  im.width = dims[0], im.height = dims[1];
  auto* px = r->GetOutput()->GetPointData()->GetScalars();
  double sum = 0, sum2 = 0;
  const vtkIdType n = px->GetNumberOfTuples();
  for (vtkIdType i = 0; i < n; ++i) {
    double g = 0;
    for (int c = 0; c < std::min(3, px->GetNumberOfComponents()); ++c) g += px->GetComponent(i, c);
    g /= 3;
    sum += g, sum2 += g * g;
  }
  im.spread = std::sqrt(std::max(0.0, sum2 / n - (sum / n) * (sum / n)));
  return im;
}

// A small run with a VTU series, shared by the tests.
fs::path smallRun(const std::string& name, const std::string& extra = "") {
  const fs::path dir = freshDir(name);
  const std::string args = "run " CHUTE_SOURCE_DIR "/cases/bead_5.toml --quiet --out " +
                           dir.string() + " --set output.vtu.write=true --set solver.t_end=1" +
                           extra;
  EXPECT_EQ(run(args), 0);
  return dir;
}
}  // namespace

TEST(Render, SnapshotsWithoutADisplayAreNonBlankAndOfTheRequestedSize) {
  const auto dir = smallRun("run");
  const auto out = dir / "snap";
  ASSERT_EQ(run("render " + dir.string() +
                " --times 0.5,1 --view side --color velocity --size "
                "640x360 --out " +
                out.string()),
            0);
  int count = 0;
  for (const auto& e : fs::directory_iterator(out)) {
    const Image im = readPng(e.path());
    std::printf("%s: %dx%d, grey-level spread %.1f\n", e.path().filename().c_str(), im.width,
                im.height, im.spread);
    EXPECT_EQ(im.width, 640);
    EXPECT_EQ(im.height, 360);
    EXPECT_GT(im.spread, 5.0);  // not a blank (uniform) image
    ++count;
  }
  EXPECT_EQ(count, 2);
}

namespace {
// A sheet of four quads under pressure, held at its rim, with a weight hanging from its centre on
// a cable: membranes, a line and a point mass in one series.
fs::path sheetRun(const std::string& name) {
  const fs::path dir = freshDir(name);
  fs::create_directories(dir);
  const fs::path file = dir / "sheet.toml";
  std::FILE* f = std::fopen(file.c_str(), "w");
  if (!f) ADD_FAILURE() << "cannot write " << file;
  if (!f) return dir;
  std::fprintf(f, "%s", R"(name = "sheet"
[nodes]
p00 = [0.0, 0.0, 0.0]
p10 = [0.5, 0.0, 0.0]
p20 = [1.0, 0.0, 0.0]
p01 = [0.0, 0.5, 0.0]
p11 = [0.5, 0.5, 0.0]
p21 = [1.0, 0.5, 0.0]
p02 = [0.0, 1.0, 0.0]
p12 = [0.5, 1.0, 0.0]
p22 = [1.0, 1.0, 0.0]
weight = [0.5, 0.5, -0.3]
[materials.film]
kind = "membrane"
E = 1.0e6
thickness = 1.0e-3
density = 100.0
[materials.cord]
E = 1.0e7
area = 1.0e-5
density = 1000.0
[[membranes]]
name = "sheet"
material = "film"
mesh = "elements"
quads = [["p00", "p10", "p11", "p01"], ["p10", "p20", "p21", "p11"],
         ["p01", "p11", "p12", "p02"], ["p11", "p21", "p22", "p12"]]
[[cables]]
name = "cord"
material = "cord"
path = ["p11", "weight"]
[[point_masses]]
node = "weight"
mass = 0.2
[boundary]
fixed = ["p00", "p10", "p20", "p01", "p21", "p02", "p12", "p22"]
[loads]
gravity = [0.0, 0.0, -9.81]
[[loads.pressure]]
membranes = "sheet"
pressure = 200.0
ramp_time = 0.02
[solver]
dt = 2.0e-3
t_end = 0.04
rho_inf = 0.0
[output.vtu]
every = 5
)");
  std::fclose(f);
  EXPECT_EQ(run("run " + file.string() + " --quiet --out " + dir.string()), 0);
  return dir;
}

// Every value of `field` (component c) over the cells of kinds [lo, hi] of every frame, sorted.
std::vector<double> valuesOver(const fs::path& dir, const char* field, int c, int lo, int hi) {
  std::vector<double> v;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".vtu") continue;
    vtkNew<vtkXMLUnstructuredGridReader> r;
    r->SetFileName(e.path().c_str());
    r->Update();
    auto* kind = r->GetOutput()->GetCellData()->GetArray("kind");
    auto* a = r->GetOutput()->GetCellData()->GetArray(field);
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
      if (kind->GetComponent(i, 0) >= lo && kind->GetComponent(i, 0) <= hi)
        v.push_back(a->GetComponent(i, c));
  }
  std::sort(v.begin(), v.end());
  return v;
}

// Each node's mean of a cell field over the cells of kind [lo, hi] around it, over every frame
// (what a membrane layer draws by default), sorted.
std::vector<double> nodalMeansOver(const fs::path& dir, const char* field, int c, int lo, int hi) {
  std::vector<double> v;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".vtu") continue;
    vtkNew<vtkXMLUnstructuredGridReader> r;
    r->SetFileName(e.path().c_str());
    r->Update();
    vtkUnstructuredGrid* g = r->GetOutput();
    auto* kind = g->GetCellData()->GetArray("kind");
    auto* a = g->GetCellData()->GetArray(field);
    std::vector<double> sum(static_cast<size_t>(g->GetNumberOfPoints()), 0.0);
    std::vector<int> count(sum.size(), 0);
    for (vtkIdType i = 0; i < g->GetNumberOfCells(); ++i) {
      if (!(kind->GetComponent(i, 0) >= lo && kind->GetComponent(i, 0) <= hi)) continue;
      vtkIdType n = 0;
      const vtkIdType* pts = nullptr;
      g->GetCellPoints(i, n, pts);
      for (vtkIdType j = 0; j < n; ++j) sum[pts[j]] += a->GetComponent(i, c), ++count[pts[j]];
    }
    for (size_t i = 0; i < sum.size(); ++i)
      if (count[i] > 0) v.push_back(sum[i] / count[i]);
  }
  std::sort(v.begin(), v.end());
  return v;
}

// The top of a stress or force scale: the 99th percentile of the values (kept as floats), or the
// largest value when the percentile is the smallest value (mostly unloaded).
double scaleTop(const std::vector<double>& v) {
  const double p99 = static_cast<float>(v[std::min(v.size() - 1, size_t(0.99 * v.size()))]);
  return p99 > v.front() ? std::min(p99, v.back()) : v.back();
}
}  // namespace

// A SIGTERM sent to `chute render` alone (as `timeout` or a batch system sends it) stops the
// Xvfb it started: before, the server was left running for good.
TEST(Render, ASigtermWhileRenderingStopsItsXvfb) {
  const fs::path dir = smallRun("sigterm");
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    ::unsetenv("DISPLAY");
    const int devnull = ::open("/dev/null", O_WRONLY);
    ::dup2(devnull, 1), ::dup2(devnull, 2);
    const std::string out = (dir / "frames").string();
    // Every frame at full HD: seconds of rendering, time enough to see the server start.
    ::execl(kChute.c_str(), kChute.c_str(), "render", dir.c_str(), "--all", "--size", "1920x1080",
            "--out", out.c_str(), "--quiet", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // The Xvfb whose parent is chute (from /proc: "pid (comm) state ppid ...").
  auto serverOf = [](pid_t parent) -> pid_t {
    for (const auto& e : fs::directory_iterator("/proc")) {
      std::ifstream in(e.path() / "stat");
      pid_t p = 0, pp = 0;
      std::string comm, state;
      if (in >> p >> comm >> state >> pp && pp == parent && comm == "(Xvfb)") return p;
    }
    return -1;
  };
  pid_t server = -1;
  for (int k = 0; k < 400 && server < 0; ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
    server = serverOf(pid);
  }
  ASSERT_GT(server, 0) << "chute render started no Xvfb within 10 s";
  // Wait for the first snapshot: the server is up and in use (a server killed while it starts
  // dies of the closed -displayfd pipe anyway, which would prove nothing).
  const fs::path frames = dir / "frames";
  bool rendering = false;
  for (int k = 0; k < 800 && !rendering; ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
    std::error_code ec;
    rendering = fs::exists(frames, ec) && !fs::is_empty(frames, ec);
  }
  ASSERT_TRUE(rendering) << "no snapshot written within 20 s";
  ::kill(pid, SIGTERM);
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
  bool gone = false;
  for (int k = 0; k < 200 && !gone; ++k) {  // it is reparented and reaped once it has exited
    gone = ::kill(server, 0) != 0;
    if (!gone) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  std::printf("chute render (pid %d) got SIGTERM; its Xvfb (pid %d) %s\n", pid, server,
              gone ? "exited" : "is still running after 10 s");
  EXPECT_TRUE(gone);
  if (!gone) ::kill(server, SIGKILL);
}

TEST(Render, ColoursMembranesByStressAndLinesByForceByDefault) {
  const auto dir = sheetRun("sheet");
  // The layers and their ranges over the series, as chute render computes them.
  std::vector<fs::path> frames;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".vtu") frames.push_back(e.path());
  ASSERT_GE(frames.size(), 5u);
  std::vector<chute::render::ColourLayer> layers, averaged;
  for (const auto& frame : frames) {
    vtkNew<vtkXMLUnstructuredGridReader> r;
    r->SetFileName(frame.c_str());
    r->Update();
    if (layers.empty()) layers = chute::render::colourLayers("stress", r->GetOutput(), {}, true);
    chute::render::widenRanges(layers, r->GetOutput());
    if (averaged.empty()) averaged = chute::render::colourLayers("stress", r->GetOutput());
    chute::render::widenRanges(averaged, r->GetOutput());
  }
  chute::render::finishRanges(layers);
  chute::render::finishRanges(averaged);
  ASSERT_EQ(layers.size(), 3u);
  // By default the fabric's stress is drawn as nodal means (the element field is a
  // checkerboard), and its scale is that of the means; --cell-values draws the elements.
  const auto means = nodalMeansOver(dir, "principal_stress", 0, 5, 5);
  ASSERT_FALSE(means.empty());
  std::printf("membrane stress S1, nodal means: scale [%g, %g], largest %g\n", averaged[0].range[0],
              averaged[0].range[1], means.back());
  EXPECT_TRUE(averaged[0].atNodes);
  EXPECT_FALSE(layers[0].atNodes);
  EXPECT_EQ(averaged[0].range[1], scaleTop(means));
  EXPECT_EQ(averaged[0].largest, means.back());
  EXPECT_NE(averaged[0].title.find("nodal mean"), std::string::npos);
  EXPECT_EQ(averaged[1].range[1], layers[1].range[1]);  // lines are not averaged
  const auto s1 = valuesOver(dir, "principal_stress", 0, 5, 5);
  const auto n = valuesOver(dir, "axial_force", 0, 1, 4);
  std::printf(
      "membrane stress S1: scale [%g, %g], largest %g (above the scale: %d); line force: "
      "scale [%g, %g], largest %g\n",
      layers[0].range[0], layers[0].range[1], s1.back(), layers[0].above, layers[1].range[0],
      layers[1].range[1], n.back());
  EXPECT_EQ(layers[0].field, "principal_stress");
  EXPECT_EQ(layers[0].range[0], 0.0);
  EXPECT_EQ(layers[0].range[1], scaleTop(s1));  // the same numbers, read independently
  EXPECT_EQ(layers[0].above, s1.back() > layers[0].range[1]);
  EXPECT_EQ(layers[0].largest, s1.back());
  EXPECT_EQ(layers[1].field, "axial_force");
  EXPECT_EQ(layers[1].range[0], 0.0);
  EXPECT_EQ(layers[1].range[1], scaleTop(n));
  EXPECT_EQ(layers[1].largest, n.back());
  EXPECT_GT(s1.back(), 0.0);  // the sheet is stressed and the cord pulled: two different scales
  EXPECT_GT(n.back(), 0.0);
  EXPECT_NE(layers[0].range[1], layers[1].range[1]);
  EXPECT_TRUE(layers[2].field.empty());  // point masses: grey

  // And chute render draws it with no --color: a non-blank picture.
  const auto out = dir / "snap";
  ASSERT_EQ(run("render " + dir.string() + " --view iso --size 640x360 --out " + out.string()), 0);
  ASSERT_EQ(std::distance(fs::directory_iterator(out), fs::directory_iterator()), 1);
  const Image im = readPng(fs::directory_iterator(out)->path());
  std::printf("default colouring: %dx%d, grey-level spread %.1f\n", im.width, im.height, im.spread);
  EXPECT_GT(im.spread, 5.0);
}

TEST(Render, StressScaleEndsAtThe99thPercentileWithTheRestAbove) {
  // 1000 values 0, 1, ..., 999 as widenRanges keeps them: the scale is [0, 990], and the ten
  // values above it are flagged for the colour of their own.
  chute::render::ColourLayer layer;
  layer.field = "principal_stress";
  layer.percentile = 99.0;
  for (int i = 999; i >= 0; --i) layer.values.push_back(static_cast<float>(i));
  layer.range = {0.0, 999.0};
  layer.seen = true;
  std::vector<chute::render::ColourLayer> layers = {layer};
  chute::render::finishRanges(layers);
  EXPECT_EQ(layers[0].range[0], 0.0);
  EXPECT_EQ(layers[0].range[1], 990.0);
  EXPECT_TRUE(layers[0].above);
  EXPECT_EQ(layers[0].largest, 999.0);
  // Mostly unloaded (99 % zeros): the scale ends at the largest value, nothing is above it.
  layer.values.assign(1000, 0.0f);
  layer.values.back() = 5.0f;
  layer.range = {0.0, 5.0};
  layers = {layer};
  chute::render::finishRanges(layers);
  EXPECT_EQ(layers[0].range[1], 5.0);
  EXPECT_FALSE(layers[0].above);
}

TEST(Render, ComparesTwoRunsSideBySide) {
  const auto a = smallRun("a");
  const auto b = smallRun("b", " --set solver.rho_inf=0.5");
  const auto out = a / "cmp";
  ASSERT_EQ(run("render " + a.string() + " --compare " + b.string() +
                " --times 1 --view iso --size 800x300 --out " + out.string()),
            0);
  ASSERT_EQ(std::distance(fs::directory_iterator(out), fs::directory_iterator()), 1);
  const Image im = readPng(fs::directory_iterator(out)->path());
  EXPECT_EQ(im.width, 800);
  EXPECT_GT(im.spread, 5.0);
}

TEST(Render, BadRequestsFailWithExitStatusTwo) {
  const auto dir = smallRun("bad");
  EXPECT_EQ(run("render " + dir.string() + " --color no_such_field --out " + dir.string()), 2);
  EXPECT_EQ(run("render " + dir.string() + " --view top --out " + dir.string()), 2);
  EXPECT_EQ(run("render /nonexistent/run"), 2);
  EXPECT_EQ(run("plot " + dir.string() + " --columns no.such --out " + (dir / "p.png").string()),
            2);
}

TEST(Plot, OverlaysRunsAndAReferenceCurve) {
  const auto a = smallRun("plot_a");
  const auto b = smallRun("plot_b", " --set solver.dt=1e-2");
  // A reference curve: the first run's own bead.x, shifted.
  const auto ref = a / "ref.csv";
  {
    std::FILE* f = std::fopen(ref.c_str(), "w");
    std::fprintf(f, "t,bead.x\n");
    for (int i = 0; i <= 100; ++i) std::fprintf(f, "%g,%g\n", i * 0.01, 0.5 + 0.1 * i * 0.01);
    std::fclose(f);
  }
  const auto png = a / "plot.png";
  ASSERT_EQ(run("plot " + a.string() + " " + b.string() + " --columns bead.x,bead.z --reference " +
                ref.string() + " --size 900x500 --out " + png.string()),
            0);
  const Image im = readPng(png);
  EXPECT_EQ(im.width, 900);
  EXPECT_EQ(im.height, 500);
  EXPECT_GT(im.spread, 5.0);
}

// A probes.csv whose first column is not the time was plotted with that column as the time; one of
// 200,000 columns asked for one it lacks gave an error line of 1.7 MB listing them all (third
// hostile-input attack). Both are refused with status 2 and one short line.
TEST(Plot, AFileThatIsNotARunsProbesOrHasTooManyColumnsGivesOneShortLine) {
  const fs::path dir = freshDir("plot_hostile");
  fs::create_directories(dir / "no_t");
  std::ofstream(dir / "no_t" / "probes.csv") << "tt,bead.x\n0,1\n1,2\n";
  fs::create_directories(dir / "wide");
  {
    std::ofstream f(dir / "wide" / "probes.csv");
    f << "t";
    for (int i = 0; i < 200000; ++i) f << ",c" << i;
    f << "\n";
  }
  for (const char* name : {"no_t", "wide"}) {
    const std::string sub = name;
    fs::path err = dir / sub, png = dir / sub;
    err += ".err";
    png += ".png";
    const std::string cmd = "env -u DISPLAY " + kChute + " plot " + (dir / sub).string() +
                            " --columns bead.x --out " + png.string() + " 2> " + err.string();
    const int status = std::system(cmd.c_str());
    std::ifstream in(err);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::printf("%s -> %d, %zu bytes: %.300s\n", sub.c_str(),
                WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.size(), text.c_str());
    EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 2) << sub;
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << sub;
    EXPECT_LT(text.size(), 2000u) << sub;
    EXPECT_FALSE(fs::exists(png)) << sub;
  }
}

namespace {
// ParaView's pvpython: the one scripts/install-paraview.sh unpacks into the build tree, else one on
// the PATH. Empty if neither exists.
std::string findPvpython() {
  const fs::path own = CHUTE_PARAVIEW_PREFIX "/usr/bin/pvpython";
  if (fs::exists(own)) return own.string();
  if (std::system("command -v pvpython > /dev/null 2>&1") == 0) return "pvpython";
  return "";
}
}  // namespace

// pvpython on a display of chute's own (VirtualDisplay: its render window aborts on the server
// xvfb-run starts). Run twice at most, each on a fresh server: in a full parallel test run its
// render window twice found the display gone ("bad X server connection", the scripts' data
// checks already passed), an Xvfb of a test just before still letting go of its display.
int runPvpython(const std::string& cmd) {
  int status = -1;
  for (int attempt = 0; attempt < 2 && status != 0; ++attempt) {
    chute::render::VirtualDisplay display;
    std::printf("%s%s\n", cmd.c_str(), attempt ? "   (again, on a new display)" : "");
    std::fflush(stdout);
    status = std::system(cmd.c_str());
  }
  return status;
}

TEST(ParaView, OpensTheSeriesWithItsOwnReader) {
  const std::string pvpython = findPvpython();
  if (pvpython.empty()) {
    // scripts/test.sh (CI) installs it and sets CHUTE_REQUIRE_PARAVIEW: there it must run.
    if (std::getenv("CHUTE_REQUIRE_PARAVIEW"))
      FAIL() << "pvpython not found (scripts/install-paraview.sh puts it in " CHUTE_PARAVIEW_PREFIX
                ")";
    GTEST_SKIP() << "ParaView's pvpython is not installed (bash scripts/install-paraview.sh): "
                    "skipped";
  }
  const auto dir = smallRun("paraview");
  int frames = 0;
  for (const auto& e : fs::directory_iterator(dir)) frames += e.path().extension() == ".vtu";
  const auto script = dir / "check.py";
  const auto png = dir / "paraview.png";
  {
    std::FILE* f = std::fopen(script.c_str(), "w");
    std::fprintf(
        f,
        "import os, sys\n"
        "# pvpython may list the system's dist-packages (python3-vtk9's modules, built for\n"
        "# another VTK) before its own: drop it, or ParaView imports the wrong vtkmodules.\n"
        "sys.path = [p for p in sys.path if os.path.normpath(p) != '/lib/python3/dist-packages']\n"
        "from paraview.simple import *\n"
        "r = OpenDataFile('%s/bead_5.pvd')\n"
        "times = r.TimestepValues\n"
        "assert len(times) == %d and abs(times[0]) < 1e-12 and abs(times[-1] - 1.0) < 1e-9, times\n"
        "r.UpdatePipeline(times[-1])\n"
        "names = r.PointData.keys() + r.CellData.keys()\n"
        "for n in ['displacement', 'velocity', 'axial_force', 'kind']:\n"
        "    assert n in names, names\n"
        "v = CreateView('RenderView')\n"
        "v.ViewSize = [640, 360]\n"
        "v.ViewTime = times[-1]\n"
        "v.UseColorPaletteForBackground = 0\n"
        "v.Background = [1, 1, 1]\n"
        "v.CameraPosition, v.CameraFocalPoint, v.CameraViewUp = [0, -10, 0], [0, 0, 0], [0, 0, 1]\n"
        "d = Show(r, v)\n"
        "ColorBy(d, ('CELLS', 'axial_force'))\n"
        "d.LineWidth = 6\n"
        "d.PointSize = 12\n"
        "ResetCamera(v)\n"
        "SaveScreenshot('%s', v, ImageResolution=[640, 360])\n"
        "print('paraview ok: %%d frames, t = %%g .. %%g, arrays %%s' %% (len(times), times[0], "
        "times[-1], sorted(names)))\n",
        dir.c_str(), frames, png.c_str());
    std::fclose(f);
  }
  // The display chute's own renderer uses (its Xvfb when there is no DISPLAY): ParaView's render
  // window aborts on the server xvfb-run starts ("bad X server connection"), not on this one.
  ASSERT_EQ(runPvpython(pvpython + " " + script.string()), 0);
  const Image im = readPng(png);
  std::printf("%s: %dx%d, grey-level spread %.1f\n", png.filename().c_str(), im.width, im.height,
              im.spread);
  EXPECT_EQ(im.width, 640);
  EXPECT_EQ(im.height, 360);
  EXPECT_GT(im.spread, 5.0);  // the rope and the bead drawn, not a blank image
}

// docs/output.md's ParaView convention, through ParaView itself: the points of a frame are the
// current positions (nothing to warp: Warp By Vector by `displacement` at +1 would double the
// motion), `displacement` is x - X, so warping by it at scale -1 gives the reference; the fabric
// load is shown by its named component `N1`.
TEST(ParaView, PointsAreCurrentAndTheNamedResultantComponentIsShown) {
  const std::string pvpython = findPvpython();
  if (pvpython.empty()) {
    if (std::getenv("CHUTE_REQUIRE_PARAVIEW"))
      FAIL() << "pvpython not found (scripts/install-paraview.sh puts it in " CHUTE_PARAVIEW_PREFIX
                ")";
    GTEST_SKIP() << "ParaView's pvpython is not installed (bash scripts/install-paraview.sh): "
                    "skipped";
  }
  const auto dir = sheetRun("paraview_convention");
  const auto script = dir / "convention.py";
  const auto png = dir / "resultant.png";
  {
    std::FILE* f = std::fopen(script.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fprintf(
        f,
        "import os, sys\n"
        "sys.path = [p for p in sys.path if os.path.normpath(p) != '/lib/python3/dist-packages']\n"
        "from paraview.simple import *\n"
        "from paraview import servermanager\n"
        "from vtkmodules.util.numpy_support import vtk_to_numpy\n"
        "r = OpenDataFile('%s/sheet.pvd')\n"
        "times = r.TimestepValues\n"
        "assert len(times) >= 3, times\n"
        "def at(source, t):\n"
        "    # ForceTime: the frame of time t whatever the view's time (Fetch updates at its "
        "own).\n"
        "    ft = ForceTime(Input=source, ForcedTime=t, IgnorePipelineTime=1)\n"
        "    g = servermanager.Fetch(ft)\n"
        "    Delete(ft)\n"
        "    return g\n"
        "def arrays(g):\n"
        "    x = vtk_to_numpy(g.GetPoints().GetData()).astype(float)\n"
        "    u = vtk_to_numpy(g.GetPointData().GetArray('displacement')).astype(float)\n"
        "    return x, u\n"
        "x0, u0 = arrays(at(r, times[0]))\n"
        "X = x0 - u0  # the reference, from the first frame\n"
        "x, u = arrays(at(r, times[-1]))\n"
        "scale = max(abs(X).max(), 1e-300)\n"
        "moved = abs(u).max() / scale\n"
        "assert moved > 1e-3, moved  # the sheet moved: the check below is not vacuous\n"
        "# The convention: the points are the current positions, X + displacement.\n"
        "err_current = abs(x - (X + u)).max() / scale\n"
        "# Warp By Vector by displacement at scale -1: the reference (cutting pattern).\n"
        "w = WarpByVector(Input=r, Vectors=['POINTS', 'displacement'], ScaleFactor=-1.0)\n"
        "xw = vtk_to_numpy(at(w, times[-1]).GetPoints().GetData()).astype(float)\n"
        "err_reference = abs(xw - X).max() / scale\n"
        "# Warping by +1 would double the motion: the points would be X + 2u.\n"
        "w2 = WarpByVector(Input=r, Vectors=['POINTS', 'displacement'], ScaleFactor=1.0)\n"
        "xd = vtk_to_numpy(at(w2, times[-1]).GetPoints().GetData()).astype(float)\n"
        "err_doubled = abs(xd - (X + 2 * u)).max() / scale\n"
        "print('paraview convention: %%d frames, largest displacement %%.3g of the size; points vs "
        "X + u %%.2e, warp -1 vs X %%.2e, warp +1 vs X + 2u %%.2e (relative)' %% (len(times), "
        "moved, err_current, err_reference, err_doubled))\n"
        "assert err_current <= 1e-9 and err_reference <= 1e-9 and err_doubled <= 1e-9\n"
        "# The fabric load by its named component.\n"
        "r.UpdatePipeline(times[-1])\n"
        "# Warp By Vector's own choice of vector is not displacement (which would double the "
        "motion).\n"
        "wd = WarpByVector(Input=r)\n"
        "assert wd.Vectors[1] != 'displacement', wd.Vectors\n"
        "print('paraview: Warp By Vector defaults to %%s' %% (wd.Vectors,))\n"
        "Delete(wd)\n"
        "info = r.GetCellDataInformation().GetArray('stress_resultant')\n"
        "names = [info.GetComponentName(c) for c in range(info.GetNumberOfComponents())]\n"
        "assert names == ['N1', 'N2'], names\n"
        "s = r.GetCellDataInformation().GetArray('principal_stress')\n"
        "assert [s.GetComponentName(0), s.GetComponentName(1)] == ['S1', 'S2']\n"
        "v = CreateView('RenderView')\n"
        "v.ViewSize = [640, 360]\n"
        "v.ViewTime = times[-1]\n"
        "v.UseColorPaletteForBackground = 0\n"
        "v.Background = [1, 1, 1]\n"
        "v.CameraPosition, v.CameraFocalPoint, v.CameraViewUp = [0.5, -3, 1], [0.5, 0.5, 0], [0, "
        "0, "
        "1]\n"
        "d = Show(r, v)\n"
        "ColorBy(d, ('CELLS', 'stress_resultant', 'N1'))\n"
        "lut = GetColorTransferFunction('stress_resultant')\n"
        "assert lut.VectorMode == 'Component' and lut.VectorComponent == 0, (lut.VectorMode, "
        "lut.VectorComponent)\n"
        "d.RescaleTransferFunctionToDataRange(False, True)\n"
        "ResetCamera(v)\n"
        "SaveScreenshot('%s', v, ImageResolution=[640, 360])\n"
        "print('paraview: coloured by stress_resultant component %%s, range %%s N/m' %% (names[0], "
        "info.GetComponentRange(0)))\n",
        dir.c_str(), png.c_str());
    std::fclose(f);
  }
  ASSERT_EQ(runPvpython(pvpython + " " + script.string()), 0);
  const Image im = readPng(png);
  EXPECT_EQ(im.width, 640);
  EXPECT_EQ(im.height, 360);
  EXPECT_GT(im.spread, 5.0);  // the sheet drawn, not a blank image
}

namespace {
// The Xvfb servers whose parent is `parent` (from /proc: "pid (comm) state ppid ...").
std::vector<pid_t> serversOf(pid_t parent) {
  std::vector<pid_t> out;
  for (const auto& e : fs::directory_iterator("/proc")) {
    std::ifstream in(e.path() / "stat");
    pid_t p = 0, pp = 0;
    std::string comm, state;
    if (in >> p >> comm >> state >> pp && pp == parent && comm == "(Xvfb)" && state != "Z")
      out.push_back(p);
  }
  return out;
}

// `chute args` with stderr captured: (exit status, stderr).
std::pair<int, std::string> runCaptured(const std::string& args, int seconds = 60) {
  const std::string err = ::testing::TempDir() + "render_stderr.txt";
  const std::string cmd = "env -u DISPLAY timeout -s KILL " + std::to_string(seconds) + " " +
                          kChute + " " + args + " > /dev/null 2> " + err;
  const int status = std::system(cmd.c_str());
  std::ifstream in(err);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text};
}
}  // namespace

// A series whose frame is damaged (a cell naming a point that does not exist, an unknown cell
// type) or is a FIFO, or whose .pvd is a FIFO, is refused with exit status 2 and one line before
// anything is drawn or written: it crashed the renderer (a segmentation fault, its Xvfb left
// running) or blocked `chute render` for ever.
TEST(Render, DamagedFramesAndFifosAreRefusedBeforeAnythingIsDrawn) {
  const auto dir = smallRun("damaged");
  std::string frame;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".vtu" && (frame.empty() || e.path().string() < frame))
      frame = e.path().string();
  ASSERT_FALSE(frame.empty());
  // An ASCII copy of a frame to damage: two points, a line, and an index or type changed.
  auto write = [](const fs::path& at, const std::string& connectivity, const std::string& types) {
    std::ofstream(at) << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
                         "version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
                         "<UnstructuredGrid><Piece NumberOfPoints=\"2\" NumberOfCells=\"1\">\n"
                         "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" "
                         "format=\"ascii\">0 0 0 1 0 0</DataArray></Points>\n<Cells>"
                         "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">"
                      << connectivity
                      << "</DataArray><DataArray type=\"Int64\" Name=\"offsets\" "
                         "format=\"ascii\">2</DataArray><DataArray type=\"UInt8\" Name=\"types\" "
                         "format=\"ascii\">"
                      << types
                      << "</DataArray></Cells>\n<CellData><DataArray type=\"Int32\" Name=\"kind\" "
                         "format=\"ascii\">1</DataArray><DataArray type=\"Float64\" "
                         "Name=\"axial_force\" format=\"ascii\">1</DataArray><DataArray "
                         "type=\"Float64\" Name=\"principal_stress\" NumberOfComponents=\"2\" "
                         "format=\"ascii\">0 0</DataArray></CellData>\n</Piece></UnstructuredGrid>"
                         "</VTKFile>\n";
  };
  struct Case {
    std::string what, expect;
    std::function<void(const fs::path&)> damage;
  };
  const std::vector<Case> cases = {
      {"a point index out of range", "cell 0 names point 7",
       [&](const fs::path& d) { write(d / "bad.vtu", "0 7", "3"); }},
      {"a negative point index", "cell 0 names point -1",
       [&](const fs::path& d) { write(d / "bad.vtu", "0 -1", "3"); }},
      {"an unknown cell type", "is of VTK type 99",
       [&](const fs::path& d) { write(d / "bad.vtu", "0 1", "99"); }},
      {"a frame that is a FIFO", "is not a regular file",
       [&](const fs::path& d) { ::mkfifo((d / "bad.vtu").c_str(), 0600); }}};
  for (const auto& c : cases) {
    const fs::path d = freshDir("damaged_" + std::to_string(&c - cases.data()));
    fs::create_directories(d);
    c.damage(d);
    std::ofstream(d / "s.pvd") << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
                                  "version=\"0.1\"><Collection>\n<DataSet timestep=\"0\" "
                                  "file=\"bad.vtu\"/>\n</Collection></VTKFile>\n";
    const auto t0 = std::chrono::steady_clock::now();
    const auto [status, err] =
        runCaptured("render " + d.string() + " --out " + (d / "snap").string());
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%-28s exit %d in %.2f s: %s", c.what.c_str(), status, seconds, err.c_str());
    EXPECT_EQ(status, 2) << c.what;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_NE(err.find(c.expect), std::string::npos) << err;
    EXPECT_FALSE(fs::exists(d / "snap")) << c.what << ": something was written";
  }
  // The .pvd itself a FIFO: refused at once, not read for ever.
  const fs::path d = freshDir("pvd_fifo");
  fs::create_directories(d);
  ASSERT_EQ(::mkfifo((d / "s.pvd").c_str(), 0600), 0);
  const auto [status, err] = runCaptured("render " + d.string(), 20);
  std::printf("a .pvd that is a FIFO: exit %d: %s", status, err.c_str());
  EXPECT_EQ(status, 2);
}

// chute render killed by SIGKILL (no handler runs) takes its Xvfb with it: the kernel sends the
// server SIGTERM when its parent dies (before, the server was left running).
TEST(Render, ASigkilledRenderLeavesNoXvfbRunning) {
  const fs::path dir = smallRun("sigkill");
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    ::unsetenv("DISPLAY");
    const int devnull = ::open("/dev/null", O_WRONLY);
    ::dup2(devnull, 1), ::dup2(devnull, 2);
    const std::string out = (dir / "frames").string();
    ::execl(kChute.c_str(), kChute.c_str(), "render", dir.c_str(), "--all", "--size", "1920x1080",
            "--out", out.c_str(), "--quiet", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  std::vector<pid_t> servers;
  for (int k = 0; k < 400 && servers.empty(); ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
    servers = serversOf(pid);
  }
  ASSERT_FALSE(servers.empty()) << "chute render started no Xvfb within 10 s";
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  bool gone = false;
  for (int k = 0; k < 200 && !gone; ++k) {
    gone = ::kill(servers[0], 0) != 0;
    if (!gone) {
      // Reparented to init: a zombie until reaped counts as gone.
      std::ifstream in("/proc/" + std::to_string(servers[0]) + "/stat");
      pid_t p = 0;
      std::string comm, state;
      gone = !(in >> p >> comm >> state) || state == "Z";
    }
    if (!gone) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  std::printf("chute render (pid %d) got SIGKILL; its Xvfb (pid %d) %s\n", pid, servers[0],
              gone ? "exited" : "is still running after 10 s");
  EXPECT_TRUE(gone);
  if (!gone) ::kill(servers[0], SIGKILL);
}

// Plot requests that cannot be drawn: the time as a curve (it crashed with "basic_string:
// construction from null is not valid"), an image beyond the memory budget (8192x8192 ran out
// of 4 GiB), a FIFO or symbolic link as the output.
TEST(Plot, TheTimeAsACurveAnImageBeyondTheBudgetOrAFifoOutIsRefused) {
  const auto dir = smallRun("plot_refusals");
  const std::string png = (dir / "p.png").string();
  for (const auto& [args, expect] : std::vector<std::pair<std::string, std::string>>{
           {"--columns t", "'t' is the time"},
           {"--columns bead.x --size 8192x8192", "67108864 pixels"},
           {"--columns bead.x,t", "'t' is the time"}}) {
    const auto [status, err] = runCaptured("plot " + dir.string() + " " + args + " --out " + png);
    std::printf("plot %s: exit %d: %s", args.c_str(), status, err.c_str());
    EXPECT_EQ(status, 2) << args;
    EXPECT_NE(err.find(expect), std::string::npos) << err;
  }
  ASSERT_EQ(::mkfifo((dir / "fifo.png").c_str(), 0600), 0);
  fs::create_symlink(dir / "elsewhere.png", dir / "link.png");
  for (const std::string out : {"fifo.png", "link.png"}) {
    const auto [status, err] =
        runCaptured("plot " + dir.string() + " --columns bead.x --out " + (dir / out).string(), 20);
    std::printf("plot --out %s: exit %d: %s", out.c_str(), status, err.c_str());
    EXPECT_EQ(status, 2) << out;
  }
  EXPECT_FALSE(fs::exists(dir / "elsewhere.png"));
}

// Two `chute plot` runs writing one --out at once (the attack corpus ran its plot inputs two at a
// time into one file): each image is written whole beside the target and renamed over it, so
// neither sees the other's half-written or truncated file. Before, each truncated and wrote the
// path itself and then checked its size; the other's truncation in between read as "the image
// could not be written" (exit 3). Both must succeed, leaving a whole image and no temporary file.
TEST(Plot, TwoPlotsOfOneOutWriteWholeImages) {
  const auto dir = smallRun("plot_concurrent");
  const std::string png = (dir / "p.png").string();
  const std::string plot = "env -u DISPLAY " + kChute + " plot " + dir.string() +
                           " --columns bead.x --size 320x200 --out " + png + " > /dev/null";
  for (int round = 0; round < 3; ++round) {
    const std::string both = "(" + plot + " 2> " + (dir / "e1.txt").string() + "; echo $? > " +
                             (dir / "s1.txt").string() + ") & (" + plot + " 2> " +
                             (dir / "e2.txt").string() + "; echo $? > " +
                             (dir / "s2.txt").string() + ") & wait";
    ASSERT_EQ(std::system(("bash -c '" + both + "'").c_str()), 0);
    for (const char* k : {"1", "2"}) {
      std::ifstream status(dir / (std::string("s") + k + ".txt"));
      std::ifstream err(dir / (std::string("e") + k + ".txt"));
      const std::string text((std::istreambuf_iterator<char>(err)),
                             std::istreambuf_iterator<char>());
      int code = -1;
      status >> code;
      EXPECT_EQ(code, 0) << "round " << round << ", plot " << k << ": " << text;
    }
    const Image im = readPng(png);
    std::printf("round %d: both plots exit 0, %s is %dx%d\n", round, png.c_str(), im.width,
                im.height);
    EXPECT_EQ(im.width, 320);
    EXPECT_EQ(im.height, 200);
  }
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().rfind(".chute-png-", 0), std::string::npos)
        << "a temporary image left behind: " << e.path();
}

// A frame whose XML or appended-data headers VTK's reader would trust is refused before the
// reader sees it (found by mutating real series: an unknown data type in <FieldData> and stray
// text inside <Cells> crashed the reader, a changed byte count ran it out of memory or past the
// end of the file).
TEST(Render, FramesTheVtkReaderWouldTrustAreCheckedFirst) {
  const auto dir = smallRun("trusted");
  std::vector<fs::path> frames;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".vtu") frames.push_back(e.path());
  std::sort(frames.begin(), frames.end());
  ASSERT_FALSE(frames.empty());
  std::ifstream in(frames.back(), std::ios::binary);
  const std::string good((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto underscore = good.find('_', good.find("<AppendedData"));
  ASSERT_NE(underscore, std::string::npos);
  struct Case {
    std::string what, expect;
    std::function<std::string(std::string)> damage;
  };
  const std::vector<Case> cases = {
      {"an unknown data type", "a data type VTK's reader does not take",
       [](std::string s) { return s.replace(s.find("Float64"), 7, "Float60"); }},
      {"text inside <Cells>", "text in <Cells>",
       [](std::string s) { return s.insert(s.find("<Cells>") + 7, "s"); }},
      {"no '_' before the data", "does not start with '_'",
       [&](std::string s) {
         s[underscore] = 'L';  // not replace(): GCC 12 warns falsely (-Wrestrict) on it here
         return s;
       }},
      {"a byte count of 2^31", "its header announces",
       [&](std::string s) { return s.replace(underscore + 1, 4, std::string("\0\0\0\x80", 4)); }},
      {"a count of points of 1e12", "NumberOfPoints or NumberOfCells", [](std::string s) {
         const auto at = s.find("NumberOfPoints=\"") + 16;
         return s.replace(at, s.find('"', at) - at, "1000000000000");
       }}};
  for (const auto& c : cases) {
    const fs::path d = freshDir("trusted_" + std::to_string(&c - cases.data()));
    fs::create_directories(d);
    std::ofstream(d / "f.vtu", std::ios::binary) << c.damage(good);
    std::ofstream(d / "s.pvd") << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
                                  "version=\"0.1\"><Collection>\n<DataSet timestep=\"0\" "
                                  "file=\"f.vtu\"/>\n</Collection></VTKFile>\n";
    const auto [status, err] = runCaptured("render " + d.string() + " --out " + (d / "s").string());
    std::printf("%-26s exit %d: %s", c.what.c_str(), status, err.c_str());
    EXPECT_EQ(status, 2) << c.what;
    EXPECT_NE(err.find(c.expect), std::string::npos) << err;
  }
  // The undamaged frame draws, its parts named in a categorical legend.
  const fs::path d = freshDir("trusted_good");
  fs::create_directories(d);
  std::ofstream(d / "f.vtu", std::ios::binary) << good;
  std::ofstream(d / "s.pvd") << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
                                "version=\"0.1\"><Collection>\n<DataSet timestep=\"0\" "
                                "file=\"f.vtu\"/>\n</Collection></VTKFile>\n";
  EXPECT_EQ(runCaptured("render " + d.string() + " --color part --size 320x180").first, 0);
}
