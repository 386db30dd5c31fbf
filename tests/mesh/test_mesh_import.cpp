// Case files over gmsh meshes ([mesh] and group = "..."): the shipped example runs, groups
// map to the right elements, and a missing or mis-dimensioned group is an error naming the file,
// line, key and group.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>

#include "app/RunCase.hpp"
#include "case/CaseError.hpp"
#include "case/CaseSpec.hpp"

using namespace chute;

namespace {

const std::string kExample = CHUTE_SOURCE_DIR "/mesh/examples/flat_canopy.toml";

// The example case with one line replaced, written next to the example (relative mesh path).
std::string variant(const std::string& name, const std::string& from, const std::string& to) {
  std::ifstream in(kExample);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  const std::string path = ::testing::TempDir() + name + ".toml";
  std::ofstream(path) << text;
  return path;
}

std::string errorOf(const std::string& file) {
  try {
    readCase(file);
  } catch (const CaseError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(MeshImport, ShippedExampleMapsItsGroupsAndRunsAFewSteps) {
  const CaseSpec c = readCase(kExample, {"solver.t_end=0.003"});
  const Model& m = c.model;
  long lineElements = 0, skirt = 0;
  for (const auto& e : m.cables) {
    lineElements += m.lineSets[e.set].name == "lines";
    skirt += m.lineSets[e.set].name == "skirt";
  }
  std::printf("flat_canopy.msh: %d nodes, %zu membranes, %ld line elements, %ld skirt elements\n",
              m.numNodes(), m.membranes.size(), lineElements, skirt);
  EXPECT_EQ(lineElements, 8 * 6);
  EXPECT_GE(skirt, 8 * 4);
  EXPECT_GT(m.membranes.size(), 200u);
  EXPECT_EQ(m.drags.size(), 1u);
  EXPECT_EQ(m.drags[0].edges.size(), 48u);
  const int confluence = m.nodeId("confluence");
  EXPECT_TRUE(m.constraint[confluence].fixed[2]);
  // The arc centre is not in any group: not a node of the model.
  for (int n = 0; n < m.numNodes(); ++n)
    EXPECT_GT((m.X[n] - Vec3(0, 0, std::sqrt(3.0))).norm(), 1e-9) << m.nodeName[n];
  const auto r = runCase(c, RunOptions{});
  std::printf("flat_canopy: %s, %ld steps, %.2f Newton iterations/step\n",
              std::string(runStatusName(r.status)).c_str(), r.steps, r.newtonPerStep());
  EXPECT_EQ(r.status, RunStatus::Completed);
}

TEST(MeshImport, MissingOrMisdimensionedGroupsAreErrorsNamingThem) {
  struct Case {
    std::string from, to, expect;
  };
  const std::vector<Case> cases = {
      {"group = \"canopy\"", "group = \"canopee\"",
       R"(:\d+: membranes\[0\]\.group: no physical group 'canopee' in .*flat_canopy\.msh)"},
      {"group = \"canopy\"", "group = \"lines\"",
       R"(:\d+: membranes\[0\]\.group: physical group 'lines' in .* is a curve \(1-D\); this needs a surface \(2-D\))"},
      {"group = \"lines\"                 # a 1-D", "group = \"canopy\" #",
       R"(:\d+: cables\[0\]\.group: physical group 'canopy' .* is a surface \(2-D\); this needs a curve \(1-D\))"},
      {"file = \"flat_canopy.msh\"", "file = \"nowhere.msh\"",
       R"(:\d+: mesh\.file: .*nowhere\.msh: no such mesh file)"},
      {"file = \"flat_canopy.msh\"", "file = \"flat_canopy.msh\"\ninitial_displacement = \"u0\"",
       R"(:\d+: mesh\.initial_displacement: no 3-component NodeData view 'u0')"},
      {"fixed = [\"confluence\"]", "fixed = [\"confluense\"]",
       R"(:\d+: boundary\.fixed: unknown node 'confluense')"},
  };
  int i = 0;
  for (const auto& c : cases) {
    // Keep the mesh path valid from the temporary folder.
    std::string file = variant("bad" + std::to_string(i++), c.from, c.to);
    {
      std::ifstream in(file);
      std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      const std::string rel = "file = \"flat_canopy.msh\"";
      if (auto at = text.find(rel); at != std::string::npos)
        text.replace(at, rel.size(),
                     "file = \"" CHUTE_SOURCE_DIR "/mesh/examples/flat_canopy.msh\"");
      std::ofstream(file) << text;
    }
    const std::string e = errorOf(file);
    std::printf("  %s\n", e.c_str());
    EXPECT_TRUE(std::regex_search(e, std::regex(c.expect))) << e;
    EXPECT_NE(e.find(file), std::string::npos) << e;
  }
}

namespace {
std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}
}  // namespace

// The start view must give every node of the mesh (a node it left out started at its reference
// point, torn from its neighbours, and the case was accepted), and a scale must keep coordinates
// within +-1e100 (mesh.scale took them past it).
TEST(MeshImport, AStartViewThatOmitsNodesOrAScaleBeyondTheLimitIsRefused) {
  const std::string c9 = CHUTE_SOURCE_DIR "/cases/c9_slider.toml";
  std::string text = slurp(CHUTE_SOURCE_DIR "/cases/c9_slider.msh");
  // The view's count 817 -> 816 and its line for node 500 gone.
  const auto head = text.find("\"initial_displacement\"");
  ASSERT_NE(head, std::string::npos);
  const auto count = text.find("\n817\n", head);
  ASSERT_NE(count, std::string::npos);
  text.replace(count, 5, "\n816\n");
  const auto line = text.find("\n500 ", count);
  ASSERT_NE(line, std::string::npos);
  text.erase(line, text.find('\n', line + 1) - line);
  const std::string msh = ::testing::TempDir() + "c9_view_short.msh";
  std::ofstream(msh) << text;
  std::string message;
  try {
    readCase(c9, {"mesh.file=\"" + msh + "\""});
  } catch (const CaseError& e) {
    message = e.what();
  }
  std::printf("%s\n", message.c_str());
  EXPECT_NE(message.find("mesh.initial_displacement: view 'initial_displacement' of " + msh +
                         " has no value at node 500 (1 of the mesh's 817 nodes missing)"),
            std::string::npos)
      << message;

  message.clear();
  try {
    readCase(c9, {"mesh.scale=1e100"});  // the canopy is 7 ft from the axis
  } catch (const CaseError& e) {
    message = e.what();
  }
  std::printf("%s\n", message.c_str());
  EXPECT_NE(message.find("mesh.scale: node "), std::string::npos) << message;
  EXPECT_NE(message.find("is beyond +-1e100 once scaled by 1e+100"), std::string::npos) << message;
  EXPECT_NO_THROW(readCase(c9, {"mesh.scale=1e98"}));
}
