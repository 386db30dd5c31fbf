// `chute intersections` on a series written by the run's own writer (VtuSeries): the counts per
// frame, the frame read back equal to the state it was written from, --times, --csv, and the exit
// statuses (0, 6 with --expect-none when something meets, 2 for a path that is not a run).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "IntersectionFrames.hpp"
#include "VtuSeries.hpp"
#include "render/IntersectionFrameFile.hpp"

using namespace chute;
namespace fs = std::filesystem;

namespace {

const std::string kChute = CHUTE_BINARY;

struct Result {
  int status = -1;
  std::string out;
};

// bare: args is the whole command (a timeout around chute), not chute's arguments.
Result runChute(const std::string& args, bool bare = false) {
  Result r;
  FILE* p = ::popen(((bare ? "" : kChute + " ") + args + " 2>&1").c_str(), "r");
  char buf[4096];
  while (p && std::fgets(buf, sizeof buf, p)) r.out += buf;
  const int s = p ? ::pclose(p) : -1;
  r.status = WIFEXITED(s) ? WEXITSTATUS(s) : -1;
  return r;
}

void addCell(SceneFrame& f, CellShape shape, std::initializer_list<int> nodes) {
  f.shapes.push_back(shape);
  f.connectivity.insert(f.connectivity.end(), nodes.begin(), nodes.end());
  f.offsets.push_back(static_cast<int>(f.connectivity.size()));
}

// A quad (nodes 0-3) in z = 0, a triangle (4-6) and a segment (7, 8) that pass through it when
// `cross`, or hang beside it; node 9 is a point mass.
SceneFrame frame(double t, bool cross) {
  SceneFrame f;
  f.t = t;
  const double dx = cross ? 0.0 : 5.0;
  const double p[] = {0,        0,   0,  1,        0,   0, 1,       1,   0, 0, 1, 0,  // quad
                      0.5 + dx, 0.5, -1, 0.5 + dx, 0.5, 1, -1 + dx, 0.5, 0,           // triangle
                      0.3 + dx, 0.2, -1, 0.3 + dx, 0.2, 1, 9,       9,   9};
  f.points.assign(std::begin(p), std::end(p));
  addCell(f, CellShape::Quad, {0, 1, 2, 3});
  addCell(f, CellShape::Triangle, {4, 5, 6});
  addCell(f, CellShape::Line, {7, 8});
  addCell(f, CellShape::Vertex, {9});
  f.partNames = {"soup"};
  f.cellData.push_back({"kind", 1, {5, 5, 1, 6}, true});
  f.cellData.push_back({"part", 1, {0, 0, 0, 0}, true});
  return f;
}

}  // namespace

TEST(IntersectionsCommand, CountsEachFrameAndExitsAsDocumented) {
  const fs::path dir = fs::path(::testing::TempDir()) / "intersections_run";
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    VtuSeries series(dir.string(), "soup");
    series.write(frame(0.0, false));
    series.write(frame(0.5, true));
  }
  // The frame read back from its file is the state it was written from.
  const auto fromState = intersectionMesh(frame(0.5, true));
  const auto fromFile = render::readIntersectionMesh((dir / "soup_000001.vtu").string());
  EXPECT_EQ(fromFile.points, fromState.points);
  EXPECT_EQ(fromFile.triangles, fromState.triangles);
  EXPECT_EQ(fromFile.segments, fromState.segments);
  const auto n = mesh::countIntersections(fromState);
  std::printf("crossing frame: %zu triangles, %zu segments: %ld triangle pairs, %ld segment\n",
              fromState.triangles.size(), fromState.segments.size(), n.trianglePairs,
              n.segmentTriangle);
  // The triangle (in the plane y = 0.5) crosses one half of the quad and touches the other on
  // their diagonal at (0.5, 0.5, 0); the segment crosses the half y <= x at (0.3, 0.2, 0).
  EXPECT_EQ(n.trianglePairs, 2);
  EXPECT_EQ(n.segmentTriangle, 1);

  const Result all =
      runChute("intersections " + dir.string() + " --csv " + (dir / "counts.csv").string());
  std::printf("%s", all.out.c_str());
  EXPECT_EQ(all.status, 0);
  EXPECT_NE(all.out.find("soup_000000.vtu"), std::string::npos);
  EXPECT_NE(all.out.find("last frame checked (t = 0.5): 2 intersecting triangle pairs, 1 "
                         "segment-triangle pairs"),
            std::string::npos);
  std::ifstream csv(dir / "counts.csv");
  std::stringstream text;
  text << csv.rdbuf();
  EXPECT_EQ(text.str(),
            "t,triangle_pairs,segment_triangle,triangles,segments,file\n"
            "0,0,0,3,1,soup_000000.vtu\n0.5,2,1,3,1,soup_000001.vtu\n");

  EXPECT_EQ(runChute("intersections " + dir.string() + " --expect-none --quiet").status, 6);
  EXPECT_EQ(runChute("intersections " + dir.string() + " --times 0 --expect-none").status, 0);
  EXPECT_EQ(runChute("intersections " + (dir / "soup_000001.vtu").string()).status, 0);
  EXPECT_EQ(runChute("intersections " + (dir / "soup.pvd").string() + " --times 0.4 --quiet").out,
            "last frame checked (t = 0.5): 2 intersecting triangle pairs, 1 segment-triangle "
            "pairs\n");
  const Result missing = runChute("intersections " + (dir / "nothing").string());
  std::printf("%s", missing.out.c_str());
  EXPECT_EQ(missing.status, 2);
  fs::create_directories(dir / "empty");
  EXPECT_EQ(runChute("intersections " + (dir / "empty").string()).status, 2);
  std::ofstream(dir / "bad.vtu") << "not a vtu";
  const Result bad = runChute("intersections " + (dir / "bad.vtu").string());
  std::printf("%s", bad.out.c_str());
  EXPECT_EQ(bad.status, 2);
}

// A frame whose cells name points it does not have (a segment to point 10 of 10, one to -1) is
// bad input naming the file (status 2), like a frame VTK cannot read; it was status 1, an
// internal error (found by a hostile-input attack with mutated frames).
TEST(IntersectionsCommand, ACellNamingAMissingPointIsBadInput) {
  const fs::path dir = fs::path(::testing::TempDir()) / "intersections_missing_point";
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const int missing : {10, -1}) {
    SceneFrame f = frame(0.0, false);
    f.connectivity[7] = missing;  // the segment's first node (after the quad's 4, the triangle's 3)
    {
      VtuSeries series(dir.string(), "soup");
      series.write(f);
    }
    const Result r = runChute("intersections " + (dir / "soup_000000.vtu").string() + " --quiet");
    std::printf("segment node %d -> %d: %s", missing, r.status, r.out.c_str());
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.out.find("soup_000000.vtu: "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("names point " + std::to_string(missing)), std::string::npos) << r.out;
  }
}

// Frames with one attribute of their XML changed, which VTK's reader trusts: a negative point
// count, big-endian data, 64-bit block headers crashed `chute intersections` (SIGSEGV), a
// component count of 2^32 kept it busy for good. They are checked as `chute render` checks its
// frames (render/FrameFile.hpp) and refused with status 2.
TEST(IntersectionsCommand, AFrameVtksReaderWouldTrustIsCheckedFirst) {
  const fs::path dir = fs::path(::testing::TempDir()) / "intersections_hostile_xml";
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    VtuSeries series(dir.string(), "soup");
    series.write(frame(0.0, true));
  }
  std::ifstream in(dir / "soup_000000.vtu", std::ios::binary);
  const std::string good((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::pair<std::string, std::string> edits[] = {
      {"NumberOfPoints=\"10\"", "NumberOfPoints=\"-1\""},
      {"byte_order=\"LittleEndian\"", "byte_order=\"BigEndian\""},
      {"header_type=\"UInt32\"", "header_type=\"UInt64\""},
      {"NumberOfComponents=\"3\"", "NumberOfComponents=\"4294967296\""}};
  for (const auto& [from, to] : edits) {
    const auto at = good.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    std::string bad = good;
    bad.replace(at, from.size(), to);
    const fs::path file = dir / "edited.vtu";
    std::ofstream(file, std::ios::binary | std::ios::trunc) << bad;
    const auto t0 = std::chrono::steady_clock::now();
    const Result r = runChute(
        "timeout 60 " + kChute + " intersections " + file.string() + " --quiet", /*bare=*/true);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%s -> %d in %.2f s: %s", to.c_str(), r.status, s, r.out.c_str());
    EXPECT_EQ(r.status, 2) << to;
    EXPECT_LT(s, 30.0) << to;
  }
}
