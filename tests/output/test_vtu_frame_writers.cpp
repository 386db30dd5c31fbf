// The two ways a frame becomes a .vtu file agree: the direct writer of small frames
// (VtuRawFrame) and VTK's XML writer (VtuVtkFrame), read back with VTK's reader, give the same
// points, cells and arrays bit for bit; and the background writer of a series makes the same
// files as writing in the caller, reports writer errors, and is complete after flush().
#include <gtest/gtest.h>
#include <vtkAbstractArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

#include "VtuRawFrame.hpp"
#include "VtuSeries.hpp"
#include "VtuVtkFrame.hpp"
#include "support/TempDir.hpp"

using namespace chute;
namespace fs = std::filesystem;

namespace {
fs::path freshDir(const std::string& name) {
  return chute::testing::freshTempDir("chute_test_vtu_writers_", name, true);
}

// Every shape, NaN and -1 fields, 1-, 2- and 3-component arrays, several parts.
SceneFrame sampleFrame(int nodesPerSide, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  SceneFrame f;
  f.t = 0.1 * seed + 1.0 / 3.0;
  const int n = nodesPerSide;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) f.points.insert(f.points.end(), {1.0 * i, 1.0 * j, u(rng)});
  auto cell = [&](CellShape s, std::initializer_list<int> nodes) {
    f.shapes.push_back(s);
    f.connectivity.insert(f.connectivity.end(), nodes);
    f.offsets.push_back(static_cast<int>(f.connectivity.size()));
  };
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i;
      if ((i + j) % 2)
        cell(CellShape::Quad, {a, a + 1, a + n + 1, a + n});
      else
        cell(CellShape::Triangle, {a, a + 1, a + n + 1}),
            cell(CellShape::Triangle, {a, a + n + 1, a + n});
    }
  for (int i = 0; i + 1 < n; ++i) cell(CellShape::Line, {i, i + 1});
  cell(CellShape::Vertex, {n * n - 1});
  const size_t np = f.points.size() / 3, nc = f.shapes.size();
  FieldArray disp{"displacement", 3, {}}, state{"wrinkling_state", 1, {}, true};
  FieldArray stress{"principal_stress", 2, {}, false, {"S1", "S2"}}, part{"part", 1, {}, true};
  for (size_t p = 0; p < 3 * np; ++p) disp.values.push_back(u(rng));
  for (size_t c = 0; c < nc; ++c) {
    const bool line = f.shapes[c] == CellShape::Line || f.shapes[c] == CellShape::Vertex;
    state.values.push_back(line ? -1 : static_cast<int>(c % 3));
    part.values.push_back(static_cast<double>(c % 4));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    stress.values.insert(stress.values.end(), {line ? nan : u(rng), line ? nan : u(rng)});
  }
  f.pointData = {disp};
  f.cellData = {part, state, stress};
  f.partNames = {"canopy", "lines", "", "slider edges"};
  return f;
}

vtkSmartPointer<vtkUnstructuredGrid> readText(const fs::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
  vtkNew<vtkXMLUnstructuredGridReader> r;
  r->SetFileName(file.c_str());
  r->Update();
  EXPECT_EQ(r->GetErrorCode(), 0u) << file;
  auto g = vtkSmartPointer<vtkUnstructuredGrid>::New();
  g->DeepCopy(r->GetOutput());
  return g;
}

// Differences between two arrays' values (bitwise: NaN equals NaN); -1 if the shapes differ.
long differences(vtkDataArray* a, vtkDataArray* b) {
  if (!a || !b || a->GetNumberOfTuples() != b->GetNumberOfTuples() ||
      a->GetNumberOfComponents() != b->GetNumberOfComponents() ||
      a->GetDataType() != b->GetDataType())
    return -1;
  long d = 0;
  for (vtkIdType t = 0; t < a->GetNumberOfTuples(); ++t)
    for (int c = 0; c < a->GetNumberOfComponents(); ++c) {
      const double x = a->GetComponent(t, c), y = b->GetComponent(t, c);
      d += std::memcmp(&x, &y, sizeof x) != 0;
    }
  return d;
}

void expectSameGrid(vtkUnstructuredGrid* a, vtkUnstructuredGrid* b) {
  ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
  ASSERT_EQ(a->GetNumberOfCells(), b->GetNumberOfCells());
  EXPECT_EQ(differences(a->GetPoints()->GetData(), b->GetPoints()->GetData()), 0);
  long cellDiffs = 0;
  for (vtkIdType c = 0; c < a->GetNumberOfCells(); ++c) {
    cellDiffs += a->GetCellType(c) != b->GetCellType(c);
    vtkNew<vtkIdList> pa, pb;
    a->GetCellPoints(c, pa);
    b->GetCellPoints(c, pb);
    cellDiffs += pa->GetNumberOfIds() != pb->GetNumberOfIds();
    for (vtkIdType k = 0; k < std::min(pa->GetNumberOfIds(), pb->GetNumberOfIds()); ++k)
      cellDiffs += pa->GetId(k) != pb->GetId(k);
  }
  EXPECT_EQ(cellDiffs, 0);
  for (auto [da, db] :
       {std::pair<vtkFieldData*, vtkFieldData*>{a->GetPointData(), b->GetPointData()},
        {a->GetCellData(), b->GetCellData()}}) {
    ASSERT_EQ(da->GetNumberOfArrays(), db->GetNumberOfArrays());
    for (int i = 0; i < da->GetNumberOfArrays(); ++i) {
      EXPECT_EQ(differences(da->GetArray(i), db->GetArray(da->GetArrayName(i))), 0)
          << da->GetArrayName(i);
      // The same component names (none, or ParaView's labels such as S1, S2).
      auto* ai = da->GetArray(i);
      auto* bi = db->GetArray(da->GetArrayName(i));
      if (!ai || !bi) continue;
      for (int c = 0; c < ai->GetNumberOfComponents(); ++c) {
        const char* na = ai->GetComponentName(c);
        const char* nb = bi->GetComponentName(c);
        EXPECT_EQ(na ? std::string(na) : "", nb ? std::string(nb) : "") << da->GetArrayName(i);
      }
    }
  }
  EXPECT_EQ(differences(a->GetFieldData()->GetArray("TimeValue"),
                        b->GetFieldData()->GetArray("TimeValue")),
            0);
  auto* na = vtkStringArray::SafeDownCast(a->GetFieldData()->GetAbstractArray("part_names"));
  auto* nb = vtkStringArray::SafeDownCast(b->GetFieldData()->GetAbstractArray("part_names"));
  ASSERT_TRUE(na && nb);
  ASSERT_EQ(na->GetNumberOfValues(), nb->GetNumberOfValues());
  for (vtkIdType i = 0; i < na->GetNumberOfValues(); ++i)
    EXPECT_EQ(na->GetValue(i), nb->GetValue(i));
}
}  // namespace

TEST(VtuFrameWriters, DirectWriterReadsBackAsVtksWriterBitForBit) {
  const auto dir = freshDir("same");
  for (int n : {2, 5, 17}) {
    const SceneFrame f = sampleFrame(n, static_cast<unsigned>(n));
    const auto raw = readText(dir / "raw.vtu", vtuRawText(f));
    const auto vtk = readText(dir / "vtk.vtu", vtuVtkText(f, VtkCompression::None));
    const auto lz4 = readText(dir / "lz4.vtu", vtuVtkText(f, VtkCompression::LZ4));
    std::printf("%d x %d nodes, %lld cells: direct file %zu bytes, VTK raw %zu, VTK LZ4 %zu\n", n,
                n, static_cast<long long>(raw->GetNumberOfCells()), vtuRawText(f).size(),
                vtuVtkText(f, VtkCompression::None).size(),
                vtuVtkText(f, VtkCompression::LZ4).size());
    expectSameGrid(raw, vtk);
    expectSameGrid(raw, lz4);
    // And the values are the frame's own.
    EXPECT_EQ(raw->GetFieldData()->GetArray("TimeValue")->GetTuple1(0), f.t);
    EXPECT_EQ(raw->GetNumberOfPoints() * 3, static_cast<vtkIdType>(f.points.size()));
    EXPECT_EQ(raw->GetPointData()->GetArray("displacement")->GetComponent(1, 2),
              f.pointData[0].values[5]);
    // Component names reach the file (ParaView shows S1, S2 rather than X, Y).
    for (const auto& g : {raw, vtk}) {
      auto* stress = g->GetCellData()->GetArray("principal_stress");
      ASSERT_TRUE(stress && stress->GetComponentName(0) && stress->GetComponentName(1));
      EXPECT_EQ(std::string(stress->GetComponentName(0)), "S1");
      EXPECT_EQ(std::string(stress->GetComponentName(1)), "S2");
    }
  }
}

TEST(VtuFrameWriters, DirectWriterIsCheaperThanVtksWriter) {
  const SceneFrame f = sampleFrame(3, 7);  // a small scene, as the pulley's
  auto time = [](auto&& fn) {
    std::vector<double> runs;
    for (int r = 0; r < 5; ++r) {
      const auto t0 = std::chrono::steady_clock::now();
      for (int i = 0; i < 200; ++i) fn();
      runs.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() /
                     200);
    }
    std::nth_element(runs.begin(), runs.begin() + 2, runs.end());
    return runs[2];
  };
  size_t sink = 0;
  const double direct = time([&] { sink += vtuRawText(f).size(); });
  const double vtk = time([&] { sink += vtuVtkText(f, VtkCompression::None).size(); });
  std::printf("small frame (median of 5 x 200): direct %.1f us, VTK's writer %.1f us: %.1fx\n",
              1e6 * direct, 1e6 * vtk, vtk / direct);
  EXPECT_GT(sink, 0u);
  EXPECT_LT(direct, vtk);
}

TEST(VtuFrameWriters, BackgroundSeriesWritesTheSameFilesAsWritingInTheCaller) {
  const auto a = freshDir("caller"), b = freshDir("background");
  {
    VtuSeries inCaller(a.string(), "s", Writing::InCaller);
    VtuSeries background(b.string(), "s", Writing::Background);
    for (int k = 0; k < 40; ++k) {
      SceneFrame f = sampleFrame(k % 2 ? 3 : 60, static_cast<unsigned>(k));  // small and LZ4
      f.t = 0.01 * k;
      inCaller.write(f);
      background.write(std::move(f));
    }
    background.flush();
    EXPECT_EQ(background.frames(), 40);
    // After flush() the collection lists every frame.
    EXPECT_EQ(readPvd(background.pvdPath()).size(), 40u);
    std::printf("40 frames: background thread %.2f ms\n", 1e3 * background.backgroundSeconds());
  }
  auto bytes = [](const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  };
  int same = 0;
  for (const auto& e : fs::directory_iterator(a))
    same += bytes(e.path()) == bytes(b / e.path().filename());
  EXPECT_EQ(same, 41);  // 40 frames and the .pvd
}

TEST(VtuFrameWriters, BackgroundWriterErrorReachesTheCaller) {
  const auto dir = freshDir("error");
  VtuSeries series(dir.string(), "s", Writing::Background);
  series.write(sampleFrame(3, 1));
  series.flush();
  fs::remove_all(dir);  // the frames' directory disappears under the run
  series.write(sampleFrame(3, 2));
  try {
    series.flush();
    ADD_FAILURE() << "no error";
  } catch (const std::exception& e) {
    std::printf("reported: %s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("cannot create"), std::string::npos);
  }
}
