// What the viewers read and how they label it, without drawing: the units of both unit systems
// chute writes, the quantity of every probe column and VTU field, the streamed probes CSV (bounded
// points per column, the curve's envelope exact), and the checks of a frame's cells.
#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "case/CaseSpec.hpp"
#include "render/ColourLayers.hpp"
#include "render/FrameFile.hpp"
#include "render/ImageOutput.hpp"
#include "render/ProbeCsv.hpp"
#include "render/Quantities.hpp"

using namespace chute::render;

// The two unit systems `chute mesh parachute` writes (and the shipped cases' notes): every
// quantity a picture or plot shows has its unit, in engineering names (psf, Pa, J).
TEST(Quantities, BothUnitSystemsChuteWritesGiveEveryUnit) {
  const UnitSystem ft = parseUnits("ft, slug, s, lbf"), si = parseUnits("m, kg, s, N");
  const UnitSystem siPa = parseUnits("m, kg, s, N, Pa"),
                   any = parseUnits("m, kg, s, N (any consistent set)");
  struct Row {
    Quantity q;
    const char *ft, *si;
  };
  const std::vector<Row> rows = {{Quantity::Length, "ft", "m"},
                                 {Quantity::Velocity, "ft/s", "m/s"},
                                 {Quantity::Acceleration, "ft/s²", "m/s²"},
                                 {Quantity::Force, "lbf", "N"},
                                 {Quantity::ForcePerLength, "lbf/ft", "N/m"},
                                 {Quantity::Stress, "psf", "Pa"},
                                 {Quantity::Energy, "ft·lbf", "J"},
                                 {Quantity::Time, "s", "s"},
                                 {Quantity::Strain, "-", "-"},
                                 {Quantity::AngleDeg, "deg", "deg"},
                                 {Quantity::AngleRad, "rad", "rad"}};
  for (const auto& r : rows) {
    std::printf("%-18s ft-lbf-s: %-8s SI: %s\n", quantityName(r.q).c_str(), unitOf(r.q, ft).c_str(),
                unitOf(r.q, si).c_str());
    EXPECT_EQ(unitOf(r.q, ft), r.ft);
    EXPECT_EQ(unitOf(r.q, si), r.si);
    EXPECT_EQ(unitOf(r.q, siPa), r.si);
    EXPECT_EQ(unitOf(r.q, any), r.si);
  }
  EXPECT_EQ(withUnit("membrane stress S1", Quantity::Stress, ft), "membrane stress S1 (psf)");
  // A note that names no unit: no unit shown rather than a wrong one.
  const UnitSystem none = parseUnits("consistent units");
  EXPECT_EQ(withUnit("line force", Quantity::Force, none), "line force");
  EXPECT_EQ(unitOf(Quantity::Time, none), "s");
}

// Every probe kind's columns (as the case reader makes them) have a quantity in the table, and
// the one ambiguous column name ("strain": an energy of an energy probe, a strain of a line
// force probe) is told apart by the probe's other columns.
TEST(Quantities, EveryProbeColumnHasItsQuantity) {
  // The table of chute's probe kinds (case/CaseSpec.hpp) and this one list the same columns.
  const auto table = probeKindColumns();
  std::map<std::string, std::vector<std::string>> kinds, ours(table.begin(), table.end());
  for (const auto& k : chute::probeKinds())
    for (const char* q : k.quantities) kinds[k.name].push_back(q);
  EXPECT_EQ(ours, kinds);
  std::vector<std::string> header = {"t"};
  for (const auto& [kind, columns] : table)
    for (const auto& c : columns) header.push_back("p_" + kind + "." + c);
  // The kinds of docs/case-files.md (output.probes[].kind): 11 when the table was written, 15
  // since the flight probes (support_force, line_pull, line_force_max, canopy) came in.
  EXPECT_EQ(table.size(), 15u);
  for (size_t k = 1; k < header.size(); ++k) {
    const ColumnInfo info = probeColumn(header[k], header);
    EXPECT_NE(info.quantity, Quantity::Unknown) << header[k];
  }
  EXPECT_EQ(probeColumn("p_energy.strain", header).quantity, Quantity::Energy);
  EXPECT_EQ(probeColumn("p_line_force.strain", header).quantity, Quantity::Strain);
  EXPECT_EQ(probeColumn("p_skirt_radius.mean", header).title, "skirt radius");
  EXPECT_EQ(probeColumn("p_canopy.inflow", header).quantity, Quantity::VolumeFlow);
  EXPECT_EQ(withUnit("canopy volume", Quantity::Volume, parseUnits("m, kg, s, N")),
            "canopy volume (m³)");
  EXPECT_EQ(probeColumn("nonsense", header).quantity, Quantity::Unknown);
}

// The VTU fields: names and units of the continuous ones, categories of the categorical ones.
TEST(Quantities, VtuFieldsAreNamedAndCategoricalOnesListTheirCategories) {
  const UnitSystem ft = parseUnits("ft, slug, s, lbf");
  EXPECT_EQ(withUnit(vtuField("axial_force").title, vtuField("axial_force").quantity, ft),
            "line force (lbf)");
  EXPECT_EQ(vtuField("principal_stress").components.at(0), "S1");
  const FieldInfo w = vtuField("wrinkling_state");
  ASSERT_EQ(w.quantity, Quantity::Category);
  ASSERT_EQ(w.categories.size(), 3u);
  EXPECT_EQ(w.categories[0].name, "taut");
  EXPECT_EQ(w.notApplicable, -1.0);  // lines: -1, drawn grey as "n/a", not "0 taut"
  EXPECT_TRUE(std::isnan(vtuField("slider_stick_state").notApplicable));
  EXPECT_EQ(vtuField("no_such").quantity, Quantity::Unknown);
}

namespace {
std::string tempFile(const std::string& name) {
  return ::testing::TempDir() + name;
}
}  // namespace

// The envelope decimation: a million points of a noisy curve into about 2 x 600 buckets, the
// least and largest value of the whole curve (and of every stretch of it) kept exactly, and a
// short curve kept whole.
TEST(ProbeCsv, AMillionRowsKeepABoundedEnvelopeWithTheExtremes) {
  EnvelopeDecimator d(600);
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  double lo = 1e300, hi = -1e300;
  const int n = 1000000;
  for (int i = 0; i < n; ++i) {
    const double t = i * 1e-4, y = std::sin(t) + 0.1 * noise(rng) + (i == 777777 ? 50.0 : 0.0);
    lo = std::min(lo, y), hi = std::max(hi, y);
    d.add(t, y);
  }
  std::vector<double> t, y;
  d.points(t, y);
  std::printf("%d rows -> %zu points (%llu rows per bucket), least %.6f largest %.6f\n", n,
              t.size(), static_cast<unsigned long long>(d.rowsPerBucket()), lo, hi);
  EXPECT_LE(t.size(), 4u * 2u * 600u);
  EXPECT_EQ(*std::min_element(y.begin(), y.end()), lo);
  EXPECT_EQ(*std::max_element(y.begin(), y.end()), hi);  // the spike at row 777777
  EXPECT_TRUE(std::is_sorted(t.begin(), t.end()));
  EnvelopeDecimator small(600);
  for (int i = 0; i < 1000; ++i) small.add(i, i * i);
  small.points(t, y);
  EXPECT_EQ(t.size(), 1000u);  // fewer rows than 2 x buckets: every row
}

// readProbeColumns streams the file and keeps only the asked columns; every cell is still
// checked; the time column cannot be asked for as a curve (`--columns t` once crashed plot with
// "basic_string: construction from null is not valid").
TEST(ProbeCsv, StreamsOnlyTheAskedColumnsAndChecksEveryCell) {
  const std::string path = tempFile("probes_stream.csv");
  {
    std::ofstream f(path);
    f << "t,a.x,a.y,b.N\n";
    for (int i = 0; i < 200000; ++i)
      f << i * 1e-3 << "," << std::sin(i * 1e-3) << "," << i << "," << -i << "\n";
  }
  const ProbeColumns c = readProbeColumns(path, {"b.N", "missing"}, 500);
  std::printf("%llu rows, %zu columns in the header, kept %zu points of b.N\n",
              static_cast<unsigned long long>(c.rows), c.header.size(), c.series.at(0).t.size());
  EXPECT_EQ(c.rows, 200000u);
  ASSERT_EQ(c.series.size(), 1u);  // "missing" is not in the file
  EXPECT_EQ(c.series[0].name, "b.N");
  EXPECT_LE(c.series[0].t.size(), 4u * 1000u);
  EXPECT_EQ(c.series[0].y.front(), 0.0);
  EXPECT_EQ(c.series[0].y.back(), -199999.0);
  // A non-number in a column nobody asked for is still an error naming its line.
  {
    std::ofstream f(path, std::ios::app);
    f << "200,1,abc,2\n";
  }
  try {
    readProbeColumns(path, {"b.N"}, 500);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    std::printf("%s\n", e.what());
    EXPECT_NE(std::string(e.what()).find(path + ":200002: 'abc' is not a number"),
              std::string::npos);
  }
}

// The image size limit: the memory budget of docs/limits.md.
TEST(ImageOutput, SizesBeyondTheBudgetAreRefusedAndLargeOnesDrawnWithoutMultisampling) {
  EXPECT_FALSE(imageSizeProblem(1280, 720));
  EXPECT_FALSE(imageSizeProblem(8192, 4096));
  EXPECT_TRUE(imageSizeProblem(8192, 8192));  // 67 Mpx: 4.1 GB with multisampling
  EXPECT_TRUE(imageSizeProblem(8193, 16));
  EXPECT_TRUE(imageSizeProblem(15, 100));
  EXPECT_EQ(multiSamplesFor(3840, 2160), 4);
  EXPECT_EQ(multiSamplesFor(8192, 4096), 0);
  std::printf("8192x8192: %s\n", imageSizeProblem(8192, 8192)->c_str());
}

namespace {
// Two cells (a triangle and a line) over four points, as a frame of chute's.
vtkSmartPointer<vtkUnstructuredGrid> frame() {
  auto g = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> p;
  for (int i = 0; i < 4; ++i) p->InsertNextPoint(i, i % 2, 0.0);
  g->SetPoints(p);
  const vtkIdType tri[3] = {0, 1, 2}, line[2] = {2, 3};
  g->InsertNextCell(VTK_TRIANGLE, 3, tri);
  g->InsertNextCell(VTK_LINE, 2, line);
  vtkNew<vtkIntArray> kind;
  kind->SetName("kind");
  kind->InsertNextValue(5);
  kind->InsertNextValue(1);
  g->GetCellData()->AddArray(kind);
  return g;
}
}  // namespace

// A frame is checked before anything draws it: an index out of range, an unknown cell type, a
// cell of the wrong size, a kind out of range or a field of the wrong length is refused naming
// the file (one of them crashed `chute render` with a segmentation fault).
TEST(FrameFile, CellsOutOfRangeOrOfUnknownTypesAreRefused) {
  EXPECT_NO_THROW(checkFrame(frame(), "f.vtu"));
  auto bad = frame();
  bad->GetCells()->GetConnectivityArray()->SetComponent(4, 0, 7.0);  // the line's end: point 7 of 4
  EXPECT_THROW(checkFrame(bad, "f.vtu"), std::runtime_error);
  bad = frame();
  bad->GetCellTypesArray()->SetValue(1, 42);  // a polyhedron
  try {
    checkFrame(bad, "f.vtu");
    ADD_FAILURE();
  } catch (const std::runtime_error& e) {
    std::printf("%s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("f.vtu: cell 1 is of VTK type 42"), std::string::npos);
  }
  bad = frame();
  bad->GetCellTypesArray()->SetValue(0, VTK_QUAD);  // three points
  EXPECT_THROW(checkFrame(bad, "f.vtu"), std::runtime_error);
  bad = frame();
  bad->GetCellData()->GetArray("kind")->SetComponent(0, 0, 9.0);
  EXPECT_THROW(checkFrame(bad, "f.vtu"), std::runtime_error);
  bad = frame();
  bad->GetPoints()->SetPoint(2, std::nan(""), 0, 0);
  EXPECT_THROW(checkFrame(bad, "f.vtu"), std::runtime_error);
}

// The percentile of a stress scale is taken over a bounded uniform sample when a series holds
// more values than kSampleSize: its memory does not grow with the series, and the scale's top
// stays within a small fraction of the exact percentile.
TEST(ColourLayers, APercentileOverMoreValuesThanTheSampleStaysBoundedAndClose) {
  ColourLayer l;
  l.field = "principal_stress";
  l.percentile = 99.0;
  l.seen = true;
  const std::size_t n = 3 * kSampleSize;
  l.range = {0.0, double(n - 1)};
  for (std::size_t i = 0; i < n; ++i) sampleValue(l, double(i));
  EXPECT_EQ(l.values.size(), kSampleSize);
  EXPECT_EQ(l.counted, n);
  std::vector<ColourLayer> layers = {l};
  finishRanges(layers);
  const double exact = 0.99 * double(n);
  std::printf(
      "%zu values, %zu kept: scale top %.0f, exact 99th percentile %.0f (%.2e of the "
      "range)\n",
      n, kSampleSize, layers[0].range[1], exact, std::abs(layers[0].range[1] - exact) / n);
  EXPECT_LT(std::abs(layers[0].range[1] - exact), 1e-3 * double(n));
  EXPECT_TRUE(layers[0].above);
}
