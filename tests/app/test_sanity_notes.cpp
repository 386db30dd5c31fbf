// Sanity notes (docs/sanity.md): every shipped case reads without one (its values are physical),
// and each slip the notes are for gives exactly one, naming the key: a fabric thickness or E off
// by 1e3 / 1e6, a line's E A, an air density, in SI and in ft-slug cases; and the note on an
// implicit integrator set on the command line for a case set up for central differences.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "app/SanityNotes.hpp"
#include "case/CaseSpec.hpp"

using namespace chute;
namespace fs = std::filesystem;

namespace {
std::vector<std::string> notesOf(const std::string& name, const std::vector<std::string>& sets) {
  return sanityNotes(readCase(CHUTE_SOURCE_DIR "/cases/" + name + ".toml", sets));
}
}  // namespace

TEST(SanityNotes, UnitSystemsAreReadFromTheUnitsString) {
  EXPECT_EQ(unitSystemOf("m, kg, s, N"), UnitSystem::SI);
  EXPECT_EQ(unitSystemOf("m, kg, s, N, Pa"), UnitSystem::SI);
  EXPECT_EQ(unitSystemOf("ft, slug, s, lbf"), UnitSystem::FootSlug);
  EXPECT_EQ(unitSystemOf(""), UnitSystem::Unknown);
  EXPECT_EQ(unitSystemOf("mm, t, s, N"), UnitSystem::Unknown);
}

TEST(SanityNotes, ShippedCasesGiveNone) {
  int cases = 0;
  for (const auto& e : fs::directory_iterator(CHUTE_SOURCE_DIR "/cases")) {
    if (e.path().extension() != ".toml") continue;
    const auto notes = sanityNotes(readCase(e.path().string()));
    ++cases;
    for (const auto& n : notes) ADD_FAILURE() << e.path().filename() << ": " << n;
  }
  std::printf("%d shipped cases read, no sanity note\n", cases);
  EXPECT_GT(cases, 20);
}

TEST(SanityNotes, EachSlipGivesOneNoteNamingTheKey) {
  struct Slip {
    const char* what;
    std::string caseName;
    std::vector<std::string> sets;
    std::string key;
  };
  // airbag: SI fabric (0.6 mm, 588 MPa); c9_slider: ft-slug fabric and lines; pulley: ft-slug
  // rope; c9_no_slider: line drag with air density.
  const std::vector<Slip> slips = {
      {"fabric thickness in mm given as m (SI)",
       "airbag",
       {"materials.fabric.thickness=0.6"},
       "materials.fabric.thickness"},
      {"fabric E in MPa given as Pa (SI)",
       "airbag",
       {"materials.fabric.E=588"},
       "materials.fabric.E"},
      {"fabric density 1e3 too high (ft-slug)",
       "c9_slider",
       {"materials.canopy_fabric.density=600.0"},
       "materials.canopy_fabric.density"},
      {"line E 1e8 too low (ft-slug)", "pulley", {"materials.rope.E=5.0"}, "materials.rope.E"},
      {"air density in g/m^3 (ft-slug)",
       "c9_no_slider",
       {"loads.drag.0.air_density=2.3769"},
       "loads.drag.0.air_density"},
  };
  for (const auto& s : slips) {
    const auto notes = notesOf(s.caseName, s.sets);
    std::printf("%s: %s\n", s.what, notes.empty() ? "(none)" : notes.front().c_str());
    ASSERT_EQ(notes.size(), s.key == "materials.fabric.thickness" ? 2u : 1u) << s.what;
    EXPECT_NE(notes.front().find(s.key), std::string::npos) << notes.front();
    EXPECT_EQ(notes.front().rfind("--set ", 0), 0u) << "named by the --set that gave it";
  }
}

TEST(SanityNotes, AnImplicitIntegratorOnACaseSetUpForCentralDifferencesIsNoted) {
  const auto none = notesOf("c9_slider", {});
  EXPECT_TRUE(none.empty());
  const auto notes = notesOf("c9_slider", {"solver.integrator=\"bossak\""});
  ASSERT_EQ(notes.size(), 1u);
  std::printf("%s\n", notes.front().c_str());
  EXPECT_NE(notes.front().find("8.0x"), std::string::npos);
  // The same integrator given in a case file that is set up for it: no note.
  EXPECT_TRUE(notesOf("pulley", {"solver.integrator=\"bossak\""}).empty());
}
