// The documentation holds together: every page under docs/ is linked from the README, every
// relative link in the README and the pages points at a file of the repository, no file cites
// the design notes that lived outside it, and every equation tag and section of
// docs/formulation.md / docs/friction.md the code cites exists there.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {
const fs::path kRoot = CHUTE_SOURCE_DIR;

std::string readAll(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<fs::path> docPages() {
  std::vector<fs::path> pages;
  for (const auto& e : fs::recursive_directory_iterator(kRoot / "docs"))
    if (e.path().extension() == ".md") pages.push_back(e.path());
  return pages;
}

// Relative link targets of a Markdown file ("](target)" and "](target#anchor)"), web links left
// out.
std::vector<std::string> links(const std::string& text) {
  static const std::regex link(R"(\]\(([^)#\s]+)(#[^)]*)?\))");
  std::vector<std::string> out;
  for (std::sregex_iterator it(text.begin(), text.end(), link), end; it != end; ++it) {
    const std::string target = (*it)[1];
    if (target.find("://") == std::string::npos && target.rfind("mailto:", 0) != 0)
      out.push_back(target);
  }
  return out;
}
}  // namespace

TEST(Docs, EveryPageIsLinkedFromTheReadme) {
  std::set<fs::path> linked;
  for (const auto& l : links(readAll(kRoot / "README.md")))
    linked.insert(fs::weakly_canonical(kRoot / l));
  const auto pages = docPages();
  for (const auto& page : pages)
    EXPECT_TRUE(linked.count(fs::weakly_canonical(page)))
        << fs::relative(page, kRoot) << " is not linked from README.md";
  std::printf("%zu pages under docs/, all checked against the README's links\n", pages.size());
  EXPECT_GE(pages.size(), 10u);
}

TEST(Docs, EveryRelativeLinkPointsAtAFileOfTheRepository) {
  auto files = docPages();
  files.push_back(kRoot / "README.md");
  int checked = 0;
  for (const auto& f : files)
    for (const auto& l : links(readAll(f))) {
      const fs::path target = fs::weakly_canonical(f.parent_path() / l);
      EXPECT_TRUE(fs::exists(target)) << fs::relative(f, kRoot) << ": link to " << l;
      const auto rel = fs::relative(target, fs::weakly_canonical(kRoot)).string();
      EXPECT_FALSE(rel.rfind("..", 0) == 0)
          << fs::relative(f, kRoot) << ": " << l << " leaves the repository";
      ++checked;
    }
  std::printf("%d relative links checked\n", checked);
  EXPECT_GT(checked, 20);
}

TEST(Docs, NoFileCitesDesignNotesOutsideTheRepository) {
  int scanned = 0;
  for (auto it = fs::recursive_directory_iterator(kRoot); it != fs::recursive_directory_iterator();
       ++it) {
    const auto name = it->path().filename().string();
    if (it->is_directory() && (name == ".git" || name == "out" || name.rfind("build", 0) == 0)) {
      it.disable_recursion_pending();
      continue;
    }
    if (!it->is_regular_file() || it->file_size() > 2'000'000) continue;
    const std::string text = readAll(it->path());
    if (text.find('\0') != std::string::npos) continue;  // binary (meshes are text, PNGs not)
    ++scanned;
    EXPECT_EQ(text.find("shared/"
                        "design"),
              std::string::npos)
        << fs::relative(it->path(), kRoot);
  }
  std::printf("%d text files scanned\n", scanned);
}

TEST(Docs, EveryEquationTagAndSectionTheCodeCitesExists) {
  const std::string formulation = readAll(kRoot / "docs/formulation.md");
  const std::string friction = readAll(kRoot / "docs/friction.md");
  const std::string contact = readAll(kRoot / "docs/contact.md");
  // A tag is defined where it heads a table row ("| F12 |") or stands in parentheses ("(FR3)").
  auto defined = [](const std::string& page, const std::string& tag) {
    return page.find("| " + tag + " |") != std::string::npos ||
           page.find("(" + tag + ")") != std::string::npos;
  };
  static const std::regex tag(
      R"(\b(F[0-9]{1,2}|FR[0-9]{1,2}|FD[0-9]|RG[0-9]|WR[0-9]|TI[0-9]|FL[0-9]{1,2}|CT[0-9]{1,2})\b)");
  static const std::regex section(R"(formulation\.md sections? ([0-9])(?:-([0-9]))?)");
  std::set<std::string> tags;
  int sections = 0;
  for (const char* dir : {"structural", "output", "mesh", "cases", "tests", "bench"})
    for (const auto& e : fs::recursive_directory_iterator(kRoot / dir)) {
      const auto ext = e.path().extension();
      if (ext != ".cpp" && ext != ".hpp" && ext != ".h" && ext != ".toml" && ext != ".py") continue;
      const std::string text = readAll(e.path());
      for (std::sregex_iterator it(text.begin(), text.end(), tag), end; it != end; ++it)
        tags.insert((*it)[1]);
      for (std::sregex_iterator it(text.begin(), text.end(), section), end; it != end; ++it)
        for (int g : {1, 2}) {
          if (!(*it)[g].matched) continue;
          ++sections;
          EXPECT_NE(formulation.find("\n## " + (*it)[g].str() + ". "), std::string::npos)
              << fs::relative(e.path(), kRoot) << " cites formulation.md section " << (*it)[g];
        }
    }
  for (const auto& t : tags) {
    const bool fr = t.rfind("FR", 0) == 0, ct = t.rfind("CT", 0) == 0;
    EXPECT_TRUE(defined(fr   ? friction
                        : ct ? contact
                             : formulation,
                        t))
        << t << " is cited in the code but not defined in docs/"
        << (fr   ? "friction"
            : ct ? "contact"
                 : "formulation")
        << ".md";
  }
  std::printf("%zu distinct tags and %d section citations checked\n", tags.size(), sections);
  EXPECT_GT(tags.size(), 20u);
}
