// chute's .msh reader (mesh/MshReader) against gmsh's: every .msh the repository ships and one
// `chute mesh parachute` writes (slider, payload box, folded start with its NodeData view), each
// re-saved by gmsh as 2.2 and 4.1, ASCII and binary, reads back identically through both readers
// (same nodes and coordinates bit for bit, same groups with the same elements in the same order,
// same views). Malformed and hostile files are one-line MeshErrors naming file and line, refused
// before anything of their claimed size is allocated.
#include <gmsh.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <array>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <random>
#include <regex>
#include <sstream>

#include "GmshMesh.hpp"
#include "GmshSession.hpp"
#include "MeshError.hpp"
#include "MshReader.hpp"
#include "ParachuteGenerator.hpp"
#include "support/TempDir.hpp"

using namespace chute::mesh;
namespace fs = std::filesystem;

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Re-saves a .msh with gmsh in another format (its NodeData views appended).
void resave(const std::string& from, const std::string& to, double version, bool binary) {
  GmshScope scope;
  callGmsh("resave " + from, [&] {
    gmsh::open(from);
    gmsh::option::setNumber("Mesh.MshFileVersion", version);
    gmsh::option::setNumber("Mesh.Binary", binary ? 1 : 0);
    gmsh::write(to);
    gmsh::option::setNumber("PostProcessing.SaveMesh", 0);
    std::vector<int> views;
    gmsh::view::getTags(views);
    for (int v : views) gmsh::view::write(v, to, true);
  });
}

// The two readers' results are the same, element for element; returns a one-line summary.
std::string expectSame(const GmshMesh& ours, const GmshMesh& gmshs, const std::string& what) {
  EXPECT_EQ(ours.nodeTags, gmshs.nodeTags) << what;
  EXPECT_EQ(ours.coords.size(), gmshs.coords.size()) << what;
  for (size_t i = 0; i < std::min(ours.coords.size(), gmshs.coords.size()); ++i)
    EXPECT_TRUE(ours.coords[i] == gmshs.coords[i]) << what << " node " << ours.nodeTags[i];
  EXPECT_EQ(ours.groups.size(), gmshs.groups.size()) << what;
  size_t elements = 0;
  for (size_t g = 0; g < std::min(ours.groups.size(), gmshs.groups.size()); ++g) {
    const auto &a = ours.groups[g], &b = gmshs.groups[g];
    EXPECT_EQ(a.name, b.name) << what;
    EXPECT_EQ(a.dim, b.dim) << what << " " << a.name;
    EXPECT_EQ(a.tag, b.tag) << what << " " << a.name;
    EXPECT_EQ(a.elements, b.elements) << what << " " << a.name;
    elements += a.elements.size();
  }
  EXPECT_EQ(ours.views.size(), gmshs.views.size()) << what;
  for (const auto& [name, values] : gmshs.views) {
    auto it = ours.views.find(name);
    EXPECT_NE(it, ours.views.end()) << what << " view " << name;
    if (it == ours.views.end()) continue;
    EXPECT_EQ(it->second.size(), values.size()) << what << " view " << name;
    for (const auto& [tag, v] : values) {
      auto jt = it->second.find(tag);
      EXPECT_NE(jt, it->second.end()) << what << " view " << name << " node " << tag;
      if (jt != it->second.end()) {
        EXPECT_TRUE(jt->second == v) << what << " view " << name << " node " << tag;
      }
    }
  }
  std::ostringstream s;
  s << ours.nodeTags.size() << " nodes, " << ours.groups.size() << " groups, " << elements
    << " elements, " << ours.views.size() << " views";
  return s.str();
}

// `back` with its node tags mapped onto those of `original` by position (bit-equal coordinates):
// gmsh renumbers the nodes of a mesh whose tags have gaps when it saves it as 2.2 (`chute mesh
// cluster` writes such tags); the model is the same up to the nodes' numbers. Returns false if
// the positions do not map one to one.
bool renumberedLike(GmshMesh& back, const GmshMesh& original) {
  if (back.nodeTags == original.nodeTags) return true;
  if (back.nodeTags.size() != original.nodeTags.size()) return false;
  std::map<std::array<double, 3>, std::size_t> byPosition;
  for (size_t i = 0; i < original.nodeTags.size(); ++i)
    if (!byPosition
             .emplace(std::array<double, 3>{original.coords[i].x(), original.coords[i].y(),
                                            original.coords[i].z()},
                      original.nodeTags[i])
             .second)
      return false;
  std::map<std::size_t, std::size_t> tagOf;
  for (size_t i = 0; i < back.nodeTags.size(); ++i) {
    const auto it = byPosition.find({back.coords[i].x(), back.coords[i].y(), back.coords[i].z()});
    if (it == byPosition.end()) return false;
    tagOf[back.nodeTags[i]] = it->second;
  }
  GmshMesh mapped = back;
  mapped.nodeTags = original.nodeTags;
  mapped.coords = original.coords;
  for (auto& g : mapped.groups)
    for (auto& e : g.elements)
      for (auto& n : e) n = tagOf.at(n);
  for (auto& [name, values] : mapped.views) {
    NodeVectors renamed;
    for (const auto& [tag, v] : values) renamed[tagOf.count(tag) ? tagOf.at(tag) : tag] = v;
    values = renamed;
  }
  mapped.buildIndex();
  back = mapped;
  return false;
}

// A small 4.1 mesh: a unit square of two triangles and a quad, a line, a point, one view.
const char* kMesh41 = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
3
0 1 "corner"
1 2 "edge"
2 3 "sheet"
$EndPhysicalNames
$Entities
1 1 1 0
1 0 0 0 1 1
1 0 0 0 1 0 0 1 2 0
1 0 0 0 2 1 0 1 3 0
$EndEntities
$Nodes
3 6 1 6
0 1 0 1
1
0 0 0
1 1 0 1
2
1 0 0
2 1 0 4
3
4
5
6
1 1 0
0 1 0
2 0 0
2 1 0
$EndNodes
$Elements
4 5 1 5
0 1 15 1
1 1
1 1 1 1
2 1 2
2 1 2 2
3 1 2 3
4 1 3 4
2 1 3 1
5 2 5 6 3
$EndElements
$NodeData
1
"u0"
1
0
3
0
3
2
1 0 0 0.5
3 0 0 0.25
$EndNodeData
)";

// The same mesh in format 2.2.
const char* kMesh22 = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
3
0 1 "corner"
1 2 "edge"
2 3 "sheet"
$EndPhysicalNames
$Nodes
6
1 0 0 0
2 1 0 0
3 1 1 0
4 0 1 0
5 2 0 0
6 2 1 0
$EndNodes
$Elements
5
1 15 2 1 1 1
2 1 2 2 1 1 2
3 2 2 3 1 1 2 3
4 2 2 3 1 1 3 4
5 3 2 3 1 2 5 6 3
$EndElements
$NodeData
1
"u0"
1
0
3
0
3
2
1 0 0 0.5
3 0 0 0.25
$EndNodeData
)";

std::string errorOf(const std::string& text, const std::string& name = "bad.msh") {
  try {
    parseMsh(text, name);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

int lineOf(const std::string& text, const std::string& what) {
  const auto at = text.find(what);
  return at == std::string::npos
             ? -1
             : 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

}  // namespace

TEST(MshReader, SmallMeshesInBothVersionsGiveTheGroupsGmshGives) {
  const std::string dir = chute::testing::freshTempDir("chute_", "msh_reader_small", true).string();
  for (const auto& [name, text] : {std::pair{"small41.msh", kMesh41}, {"small22.msh", kMesh22}}) {
    const std::string path = dir + "/" + name;
    std::ofstream(path) << text;
    const GmshMesh ours = readMsh(path);
    const GmshMesh theirs = readMeshWithGmsh(path);
    std::printf("%s: %s\n", name, expectSame(ours, theirs, name).c_str());
    ASSERT_EQ(ours.groups.size(), 3u);
    EXPECT_EQ(ours.groups[2].elements.size(), 3u);  // two triangles, then the quadrangle
    EXPECT_EQ(ours.groups[2].elements[2].size(), 4u);
    EXPECT_EQ(ours.views.at("u0").at(3).z(), 0.25);
  }
}

// The round trip through gmsh: every mesh the repository ships and three that `chute mesh
// parachute` writes (a slider with a folded start, a vent with an inflated start and a payload on
// a riser, a payload box with neither), opened in gmsh and saved by it as 2.2 and 4.1, ASCII and
// binary, read back as the same model: the same nodes and coordinates bit for bit, the same
// groups with the same elements in the same order, the same views. Format 2.2 writes an element
// once per physical group of its entity: read as two elements, a line in the groups 'lines' and
// 'line_0' made the case refuse the mesh ("group 'line_0' branches at node 326"). The originals
// (4.1) and gmsh's 4.1 saves also read as gmsh's own reader reads them. A mesh whose node tags
// have gaps (`chute mesh cluster`'s) gmsh renumbers when it saves it as 2.2: it reads back as
// the same model up to the numbers of its nodes (compared by position).
TEST(MshReader, ShippedAndGeneratedMeshesSavedByGmshIn22And41ReadBackUnchanged) {
  const std::string dir =
      chute::testing::freshTempDir("chute_", "msh_reader_formats", true).string();
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(CHUTE_SOURCE_DIR "/cases"))
    if (e.path().extension() == ".msh") files.push_back(e.path().string());
  for (const auto& e : fs::directory_iterator(CHUTE_SOURCE_DIR "/mesh/examples"))
    if (e.path().extension() == ".msh") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  ParachuteSpec base;
  base.gores = 8;
  base.diameter = 2.0;
  base.lineLength = 2.0;
  base.elementSize = 0.25;
  ParachuteSpec slider = base, vent = base, box = base;
  slider.sliderSide = 0.3;  // four sliding line groups through grommets, a quad slider
  slider.start = "folded";
  vent.ventDiameter = 0.3;  // a vent band, a payload point on a riser
  vent.payloadMass = 2.0;
  vent.riserLength = 0.4;
  vent.start = "inflated";
  box.payloadMass = 5.0;  // a braced box on four risers
  box.payloadBox = {0.3, 0.2, 0.2};
  box.riserLength = 0.3;
  for (const auto& [name, spec] : {std::pair{"slider", slider}, {"vent", vent}, {"box", box}}) {
    const std::string generated = dir + "/generated_" + name + ".msh";
    generateParachute(spec, generated);
    files.push_back(generated);
  }
  ASSERT_GE(files.size(), 7u);  // 3 in cases/, the example, the 3 generated ones
  int compared = 0;
  for (const auto& file : files) {
    const GmshMesh original = readMsh(file);
    expectSame(original, readMeshWithGmsh(file), file);
    for (const auto& [version, binary] :
         {std::pair{4.1, false}, {4.1, true}, {2.2, false}, {2.2, true}}) {
      const std::string to = dir + "/" + fs::path(file).stem().string() + "_" +
                             (version > 3 ? "41" : "22") + (binary ? "b" : "a") + ".msh";
      resave(file, to, version, binary);
      GmshMesh back = readMsh(to);
      const GmshMesh asRead = back;
      const bool sameTags = renumberedLike(back, original);
      const std::string summary = expectSame(back, original, to);
      if (!sameTags) {  // only a mesh with gaps in its node tags, saved as 2.2
        EXPECT_TRUE(version < 3) << to;
        EXPECT_NE(original.nodeTags.back(), original.nodeTags.size()) << to;
        std::printf("%-32s gmsh renumbered its nodes (tags with gaps): compared by position\n",
                    fs::path(to).filename().c_str());
      }
      if (version > 3) expectSame(asRead, readMeshWithGmsh(to), to + " (gmsh's reader)");
      ++compared;
      std::printf("%-32s %s: as the original\n", fs::path(to).filename().c_str(), summary.c_str());
    }
  }
  std::printf("%zu meshes, %d files saved by gmsh read back unchanged\n", files.size(), compared);
}

TEST(MshReader, CountsAreCheckedAgainstTheFileBeforeAnythingIsAllocated) {
  // A $NodeData count of 1e9 in a small file: refused at once, without a 24 GB allocation.
  const std::string bomb = replaced(kMesh41, "0\n3\n2\n1 0 0 0.5", "0\n3\n1000000000\n1 0 0 0.5");
  const auto t0 = std::chrono::steady_clock::now();
  const std::string e = errorOf(bomb);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  std::printf("$NodeData count 1e9: %.3f ms: %s\n", ms, e.c_str());
  EXPECT_NE(e.find("$NodeData count: 1000000000 is outside [0, 1000000]"), std::string::npos) << e;
  EXPECT_LT(ms, 1000.0);
  // Within the limit but beyond the bytes in the file.
  MshLimits big;
  big.maxNodes = 2000000000;
  try {
    parseMsh(bomb, "bomb.msh", big);
    ADD_FAILURE() << "accepted";
  } catch (const MeshError& x) {
    EXPECT_NE(std::string(x.what()).find("bytes are left in the file"), std::string::npos)
        << x.what();
  }
  // An entity in 50,000 physical groups would copy its elements into each: the copies count
  // against the element limit (here 100,000; 3 elements x 50,000 groups).
  std::string many = "1 1 1 0\n1 0 0 0 1 1\n1 0 0 0 1 0 0 1 2 0\n1 0 0 0 2 1 0 50000";
  for (int p = 1; p <= 50000; ++p) {
    many += ' ';
    many += std::to_string(p);
  }
  MshLimits small;
  small.maxElements = 100000;
  try {
    parseMsh(
        replaced(kMesh41, "1 1 1 0\n1 0 0 0 1 1\n1 0 0 0 1 0 0 1 2 0\n1 0 0 0 2 1 0 1 3", many),
        "groups.msh", small);
    ADD_FAILURE() << "accepted";
  } catch (const MeshError& x) {
    std::printf("  %s\n", x.what());
    EXPECT_NE(std::string(x.what()).find("the physical groups hold more than 100000 elements"),
              std::string::npos)
        << x.what();
  }
  // $Nodes / $Elements headers one below and one above their data.
  struct Row {
    std::string from, to, expect;
  };
  const std::vector<Row> rows = {
      {"3 6 1 6\n", "3 5 1 6\n", "$Nodes block size"},
      {"3 6 1 6\n", "3 7 1 6\n", "the header says 7 nodes, the blocks hold 6"},
      {"4 5 1 5\n", "4 4 1 5\n", "$Elements block size"},
      {"4 5 1 5\n", "4 6 1 5\n", "the header says 6 elements, the blocks hold 5"},
      {"0 1 0 1\n1\n", "0 1 0 2\n1\n", "$Nodes"},
  };
  for (const auto& r : rows) {
    const std::string m = errorOf(replaced(kMesh41, r.from, r.to));
    std::printf("  %s\n", m.c_str());
    EXPECT_NE(m.find(r.expect), std::string::npos) << m;
    EXPECT_EQ(m.rfind("bad.msh:", 0), 0u) << m;
  }
  const std::vector<Row> rows22 = {
      {"$Nodes\n6\n", "$Nodes\n5\n", "expected $EndNodes, found '6'"},
      {"$Nodes\n6\n", "$Nodes\n7\n", "$Nodes tag: expected an integer, found '$EndNodes'"},
      {"$Elements\n5\n", "$Elements\n4\n", "expected $EndElements, found '5'"},
      {"$Elements\n5\n", "$Elements\n6\n", "expected an integer, found '$EndElements'"},
  };
  for (const auto& r : rows22) {
    const std::string m = errorOf(replaced(kMesh22, r.from, r.to));
    std::printf("  %s\n", m.c_str());
    EXPECT_NE(m.find(r.expect), std::string::npos) << m;
  }
}

TEST(MshReader, NonFiniteOrHugeCoordinatesAreRefusedWithTheirLine) {
  for (const std::string bad : {"nan", "inf", "-inf", "1e308", "1e101", "1e999"}) {
    const std::string text = replaced(kMesh22, "5 2 0 0\n", "5 2 " + bad + " 0\n");
    const std::string m = errorOf(text);
    const int line = lineOf(text, "5 2 " + bad);
    EXPECT_EQ(m.rfind("bad.msh:" + std::to_string(line) + ": $Nodes coordinate: ", 0), 0u) << m;
    std::printf("  %s\n", m.c_str());
  }
  // A subnormal coordinate is a number (chute writes them).
  EXPECT_EQ(errorOf(replaced(kMesh22, "5 2 0 0\n", "5 2 4.9406564584124654e-324 0\n")), "");
  const std::string v = replaced(kMesh41, "3 0 0 0.25", "3 0 nan 0.25");
  EXPECT_NE(errorOf(v).find(":" + std::to_string(lineOf(v, "3 0 nan")) + ": $NodeData value"),
            std::string::npos)
      << errorOf(v);
}

TEST(MshReader, MalformedFilesAreOneLineErrors) {
  struct Row {
    std::string text, expect;
  };
  const std::vector<Row> rows = {
      {"", "empty file"},
      {"hello\n", "expected a section"},
      {"$Nodes\n1\n1 0 0 0\n$EndNodes\n", "does not start with $MeshFormat"},
      {replaced(kMesh41, "4.1 0 8", "4 0 8"), "version 4.0 is not read"},
      {replaced(kMesh41, "4.1 0 8", "3.0 0 8"), "chute reads versions 2.2 and 4.1"},
      {replaced(kMesh41, "4.1 0 8", "4.1 0 4"), "data size 4"},
      {replaced(kMesh22, "5 3 2 3 1 2 5 6 3", "5 99 2 3 1 2 5 6 3"), "99 is not a gmsh element"},
      {replaced(kMesh22, "5 3 2 3 1 2 5 6 3", "5 3 2 3 1 2 5 7 3"), "node 7 is not in $Nodes"},
      {replaced(kMesh22, "6 2 1 0\n", "5 2 1 0\n"), "node tag 5 appears twice"},
      {replaced(kMesh22, "5 3 2 3 1 2 5 6 3", "5 9 2 3 1 2 5 6 3 1 2"),
       "physical group 'sheet' has elements of gmsh type 9"},
      {replaced(kMesh41, "$EndNodeData", ""), "unexpected end of file"},
      {replaced(kMesh41, "1 0 0 0.5", "9 0 0 0.5"), "node 9 is not in $Nodes"},
      {replaced(kMesh41, "\"corner\"", "\"corner"), "unterminated string"},
      {replaced(kMesh41, "$Elements\n",
                "$PartitionedEntities\n1\n$EndPartitionedEntities\n$Elements\n"),
       "partitioned meshes are not supported"},
      {std::string(kMesh41).substr(0, std::string(kMesh41).find("$EndNodes")),
       "$EndNodes: unexpected end of file"},
  };
  for (const auto& r : rows) {
    const std::string m = errorOf(r.text);
    std::printf("  %s\n", m.c_str());
    EXPECT_NE(m.find(r.expect), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
  // A second-order triangle outside every physical group is not read (as through gmsh).
  const std::string outside =
      replaced(kMesh22, "$Elements\n5\n", "$Elements\n6\n7 9 2 0 7 1 2 3 1 2 4\n");
  EXPECT_EQ(errorOf(outside), "");
}

TEST(MshReader, TruncatedAndMutatedFilesAreMeshesOrMeshErrors) {
  // Every cut of a binary and an ASCII mesh, and random byte changes: each is read or refused
  // with a MeshError; nothing else may escape (crashes and sanitizer reports fail the test).
  const std::string dir =
      chute::testing::freshTempDir("chute_", "msh_reader_mutated", true).string();
  const std::string base = dir + "/c9.msh";
  resave(CHUTE_SOURCE_DIR "/cases/c9_payload.msh", base, 4.1, true);
  resave(CHUTE_SOURCE_DIR "/cases/c9_payload.msh", dir + "/c9_22.msh", 2.2, true);
  std::mt19937 rng(20);
  int read = 0, refused = 0;
  for (const std::string& text :
       {slurp(base), slurp(dir + "/c9_22.msh"), std::string(kMesh41), std::string(kMesh22)}) {
    const size_t stride = std::max<size_t>(1, text.size() / 300);
    for (size_t cut = 0; cut < text.size(); cut += stride) {
      try {
        parseMsh(text.substr(0, cut), "cut.msh");
        ++read;
      } catch (const MeshError&) {
        ++refused;
      }
    }
    for (int k = 0; k < 300; ++k) {
      std::string t = text;
      for (int j = 0; j < 4; ++j) {
        const size_t at = rng() % t.size();
        const char choices[] = {'\0', '\xff', '9', '-', ' ', '\n', '$', static_cast<char>(rng())};
        t[at] = choices[rng() % sizeof choices];
      }
      try {
        parseMsh(t, "mutated.msh");
        ++read;
      } catch (const MeshError&) {
        ++refused;
      }
    }
  }
  std::printf("cut or mutated: %d read, %d refused with a MeshError, 0 other outcomes\n", read,
              refused);
  EXPECT_GT(refused, 1000);
}

TEST(MshReader, FilesThatAreNotRegularOrNotMshAreRefusedAtOnce) {
  const std::string dir =
      chute::testing::freshTempDir("chute_", "msh_reader_special", true).string();
  const std::string fifo = dir + "/fifo.msh";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  for (const std::string& path : {fifo, std::string("/dev/zero"), dir}) {
    const auto t0 = std::chrono::steady_clock::now();
    std::string m;
    try {
      readMsh(path);
    } catch (const MeshError& e) {
      m = e.what();
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("  %.4f s: %s\n", s, m.c_str());
    EXPECT_NE(m.find(path + ": cannot open: "), std::string::npos) << m;
    EXPECT_LT(s, 5.0);
  }
  std::ofstream(dir + "/script.geo")
      << "System \"touch " << dir << "/MARKER\";\nPoint(1) = {0,0,0};\n";
  std::ofstream(dir + "/mesh.unv") << "    -1\n  2411\n";
  const std::vector<std::pair<std::string, std::string>> refused = {
      {dir + "/script.geo", "chute mesh geo"}, {dir + "/mesh.unv", "not a .msh file"}};
  for (const auto& [path, expect] : refused) {
    std::string m;
    try {
      readMesh(path);
    } catch (const MeshError& e) {
      m = e.what();
    }
    std::printf("  %s\n", m.c_str());
    EXPECT_NE(m.find(expect), std::string::npos) << m;
  }
  EXPECT_FALSE(fs::exists(dir + "/MARKER"));
}

namespace {

// A small mesh to damage: the unit square of two triangles beside a quadrangle (nodes 1-6), a
// line and a point, written as format 2.2 or 4.1 ASCII (tags are positions + 1).
struct SmallMesh {
  std::vector<std::array<double, 3>> nodes = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0},
                                              {0, 1, 0}, {2, 0, 0}, {2, 1, 0}};
  std::vector<std::vector<std::size_t>> lines = {{1, 2}}, triangles = {{1, 2, 3}, {1, 3, 4}},
                                        quads = {{2, 5, 6, 3}};
  bool quadsInOwnGroup = false;  // the quadrangles in a surface of their own, group tag 4
  std::string quadGroupName = "flap";

  std::string text(bool v4) const {
    std::ostringstream s;
    s << "$MeshFormat\n"
      << (v4 ? "4.1" : "2.2") << " 0 8\n$EndMeshFormat\n$PhysicalNames\n"
      << (quadsInOwnGroup ? 4 : 3) << "\n0 1 \"corner\"\n1 2 \"edge\"\n2 3 \"sheet\"\n";
    if (quadsInOwnGroup) s << "2 4 \"" << quadGroupName << "\"\n";
    s << "$EndPhysicalNames\n";
    const int quadEntity = quadsInOwnGroup ? 2 : 1;
    // Each element: (dim, entity, physical, gmsh type, nodes).
    struct E {
      int dim, entity, physical, type;
      std::vector<std::size_t> nodes;
    };
    std::vector<E> elements = {{0, 1, 1, 15, {1}}};
    for (const auto& l : lines) elements.push_back({1, 1, 2, 1, l});
    for (const auto& t : triangles) elements.push_back({2, 1, 3, 2, t});
    for (const auto& q : quads) elements.push_back({2, quadEntity, quadsInOwnGroup ? 4 : 3, 3, q});
    if (v4) {
      s << "$Entities\n1 1 " << (quadsInOwnGroup ? 2 : 1) << " 0\n1 0 0 0 1 1\n"
        << "1 0 0 0 1 0 0 1 2 0\n1 0 0 0 2 1 0 1 3 0\n";
      if (quadsInOwnGroup) s << "2 0 0 0 2 1 0 1 4 0\n";
      s << "$EndEntities\n$Nodes\n1 " << nodes.size() << " 1 " << nodes.size() << "\n2 1 0 "
        << nodes.size() << "\n";
      for (size_t i = 0; i < nodes.size(); ++i) s << i + 1 << "\n";
      for (const auto& x : nodes) s << x[0] << " " << x[1] << " " << x[2] << "\n";
      s << "$EndNodes\n$Elements\n";
      // One block per (dim, entity, type), in this order.
      std::vector<std::tuple<int, int, int>> blocks;
      for (const auto& e : elements)
        if (std::find(blocks.begin(), blocks.end(), std::tuple{e.dim, e.entity, e.type}) ==
            blocks.end())
          blocks.emplace_back(e.dim, e.entity, e.type);
      s << blocks.size() << " " << elements.size() << " 1 " << elements.size() << "\n";
      size_t tag = 0;
      for (const auto& [dim, entity, type] : blocks) {
        size_t count = 0;
        for (const auto& e : elements)
          count += e.dim == dim && e.entity == entity && e.type == type;
        s << dim << " " << entity << " " << type << " " << count << "\n";
        for (const auto& e : elements) {
          if (e.dim != dim || e.entity != entity || e.type != type) continue;
          s << ++tag;
          for (auto n : e.nodes) s << " " << n;
          s << "\n";
        }
      }
      s << "$EndElements\n";
    } else {
      s << "$Nodes\n" << nodes.size() << "\n";
      for (size_t i = 0; i < nodes.size(); ++i)
        s << i + 1 << " " << nodes[i][0] << " " << nodes[i][1] << " " << nodes[i][2] << "\n";
      s << "$EndNodes\n$Elements\n" << elements.size() << "\n";
      size_t tag = 0;
      for (const auto& e : elements) {
        s << ++tag << " " << e.type << " 2 " << e.physical << " " << e.entity;
        for (auto n : e.nodes) s << " " << n;
        s << "\n";
      }
      s << "$EndElements\n";
    }
    return s.str();
  }
};

}  // namespace

// Every element of every physical group is checked on import, in all four formats: a repeated
// node, a zero length or area, collinear nodes, a bow-tie or non-convex quadrangle, an element
// turned over against its neighbours, two elements on one set of nodes, and two groups of one
// dimension with one name are refused with one line
// naming the file, the line of the element (ASCII), the element, its group and the reason.
// Before, such meshes ran to "non-finite residual" (exit 3, output written) or, non-convex
// quadrangles, to exit 0; a second surface named 'canopy' silently dropped half the canopy.
TEST(MshReader, DegenerateElementsAndRepeatedGroupNamesAreRefusedInFourFormats) {
  const std::string dir =
      chute::testing::freshTempDir("chute_", "msh_reader_shapes", true).string();
  struct Case {
    const char* what;
    std::function<void(SmallMesh&)> damage;
    std::string expect;   // in the message
    std::string element;  // the element line's text (ASCII 2.2: tag, type; checked for its line)
    // gmsh's save of the ASCII 2.2 file still has the damage (gmsh's 2.2 reader merges groups
    // of one name into one: its binary save of that file has none left to refuse).
    bool binary22 = true;
  };
  const std::vector<Case> cases = {
      {"triangle with a repeated node",
       [](SmallMesh& m) {
         m.triangles[1] = {1, 3, 3};
       },
       "element 4 (triangle) of physical group 'sheet': node 3 appears twice", "4 2 2 3 1 1 3 3"},
      {"triangle of zero area",
       [](SmallMesh& m) {
         m.nodes[3] = {2, 2, 0};
       },
       "element 4 (triangle) of physical group 'sheet': zero area (its nodes are collinear)",
       "4 2 2 3 1 1 3 4"},
      {"bow-tie quadrangle",
       [](SmallMesh& m) {
         m.quads[0] = {2, 5, 3, 6};
       },
       "element 5 (quadrangle) of physical group 'sheet': zero area", "5 3 2 3 1 2 5 3 6"},
      {"twisted bow-tie quadrangle",
       [](SmallMesh& m) {
         m.quads[0] = {2, 5, 3, 6};
         m.nodes[5] = {2.2, 1, 0};
       },
       "element 5 (quadrangle) of physical group 'sheet': not convex at node", "5 3 2 3 1 2 5 3 6"},
      {"quadrangle with three collinear nodes",
       [](SmallMesh& m) {
         m.nodes[4] = {1.5, 0.5, 0};
       },
       "not convex at node 5 (a straight corner", "5 3 2 3 1 2 5 6 3"},
      {"non-convex quadrangle (a dart)",
       [](SmallMesh& m) {
         m.nodes[4] = {1.2, 0.8, 0};
       },
       "not convex at node 5 (nodes must go round", "5 3 2 3 1 2 5 6 3"},
      {"triangle turned over",
       [](SmallMesh& m) {
         m.triangles[1] = {1, 4, 3};
       },
       "element 4 (triangle) of physical group 'sheet': turned over against element 3",
       "4 2 2 3 1 1 4 3"},
      {"inverted quadrangle",
       [](SmallMesh& m) {
         m.quads[0] = {3, 6, 5, 2};
       },
       "element 5 (quadrangle) of physical group 'sheet': turned over against element 3",
       "5 3 2 3 1 3 6 5 2"},
      {"line of zero length",
       [](SmallMesh& m) {
         m.nodes.push_back({0, 0, 0});
         m.lines[0] = {1, 7};
       },
       "element 2 (line) of physical group 'edge': zero size", "2 1 2 2 1 1 7"},
      {"two triangles on the same nodes",
       [](SmallMesh& m) {
         m.triangles[1] = {3, 1, 2};
       },
       "element 4 (triangle) of physical group 'sheet': the same nodes as element 3",
       "4 2 2 3 1 3 1 2"},
      {"two surfaces named 'sheet'",
       [](SmallMesh& m) {
         m.quadsInOwnGroup = true;
         m.quadGroupName = "sheet";
       },
       "physical groups 3 and 4 (2-D) are both named 'sheet'", "", false}};
  int refused = 0;
  for (const auto& c : cases) {
    SmallMesh m;
    c.damage(m);
    for (const bool v4 : {false, true}) {
      const std::string ascii = dir + "/bad" + (v4 ? "41" : "22") + "a.msh";
      std::ofstream(ascii) << m.text(v4);
      std::vector<std::string> files = {ascii};
      // The binary twin, saved by gmsh from the ASCII file.
      const std::string binary = dir + "/bad" + (v4 ? "41" : "22") + "b.msh";
      resave(ascii, binary, v4 ? 4.1 : 2.2, true);
      if (v4 || c.binary22) files.push_back(binary);
      for (const auto& file : files) {
        std::string message;
        try {
          readMsh(file);
        } catch (const MeshError& e) {
          message = e.what();
        }
        std::printf("  %-40s %s\n", c.what, message.c_str());
        EXPECT_NE(message.find(c.expect), std::string::npos) << c.what << ": " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos);
        EXPECT_EQ(message.rfind(file + ":", 0), 0u) << message;
        refused += !message.empty();
        // The ASCII 2.2 file: the line of the damaged element.
        if (!v4 && file == ascii && !c.element.empty()) {
          const int line = lineOf(slurp(file), c.element + "\n");
          EXPECT_EQ(message.rfind(file + ":" + std::to_string(line) + ": ", 0), 0u)
              << message << " (element on line " << line << ")";
        }
      }
    }
  }
  std::printf("%zu kinds of damage in 4 formats: %d files refused\n", cases.size(), refused);
  // And the undamaged mesh reads in all four.
  for (const bool v4 : {false, true}) {
    const std::string ascii = dir + "/good.msh";
    std::ofstream(ascii) << SmallMesh().text(v4);
    EXPECT_EQ(readMsh(ascii).groups.size(), 3u);
  }
}
