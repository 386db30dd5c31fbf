// [[events]] cut = "<cable set>", at = t: the set carries load up to t and is gone after it.
// A mass hangs at rest from a prestrained cable (tension = its weight) and from a slack sliding
// cable; the first is cut at t_c. Before t_c nothing moves; after it the mass falls freely:
// z = z0 - g (t - t_c)^2 / 2, which the trapezoidal rule (rho_inf = 1) integrates exactly when
// the acceleration just after the cut is the consistent one (-g). A step lands on t_c although
// it is no multiple of dt.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "app/RunCase.hpp"
#include "case/CaseError.hpp"
#include "case/CaseSpec.hpp"

using namespace chute;

namespace {

constexpr double kG = 10.0, kMass = 2.0, kEA = 1.0e6;

std::string writeCase(const std::string& name, double cutAt, const std::string& cutSet) {
  const std::string path = ::testing::TempDir() + name + ".toml";
  std::ofstream f(path);
  // Prestrain mg / EA: at its start length the holding cable carries exactly the weight.
  f << "name = \"" << name << "\"\n"
    << "[nodes]\nanchor = [0.0, 0.0, 0.0]\nspare = [3.0, 0.0, 0.0]\nmass = [0.0, 0.0, -1.0]\n"
    << "[materials.rope]\nkind = \"cable\"\nE = " << kEA << "\narea = 1.0\n"
    << "[[cables]]\nname = \"holder\"\nmaterial = \"rope\"\npath = [\"anchor\", \"mass\"]\n"
    << "prestrain = " << kMass * kG / kEA << "\n"
    << "[[sliding_groups]]\nname = \"rope\"\nmaterial = \"rope\"\n"
    << "path = [\"anchor\", \"spare\", \"mass\"]\nsliders = [\"spare\"]\nelements = 1\n"
    << "prestrain = -0.5\n"
    << "[[events]]\ncut = \"" << cutSet << "\"\nat = " << cutAt << "\n"
    << "[[point_masses]]\nnode = \"mass\"\nmass = " << kMass << "\n"
    << "[boundary]\nfixed = [\"anchor\", \"spare\"]\n"
    << "[loads]\ngravity = [0.0, 0.0, " << -kG << "]\n"
    << "[solver]\ndt = 0.003\nt_end = 0.3\nrho_inf = 1.0\nnewton_tolerance = 1e-13\n"
    << "[output]\nevery = 1\n"
    << "[[output.probes]]\nname = \"mass\"\nkind = \"node_position\"\n"
    << "[[output.probes]]\nname = \"holder\"\nkind = \"line_force\"\nset = \"holder\"\n";
  return path;
}

}  // namespace

TEST(CutEvent, SetHoldsUntilItsTimeThenTheMassFallsFreely) {
  for (double tc : {0.0, 0.1}) {
    const CaseSpec spec = readCase(writeCase("cut_event", tc, "holder"));
    const RunResult r = runCase(spec, RunOptions{});
    ASSERT_EQ(r.status, RunStatus::Completed);
    double before = 0.0, after = 0.0, forceBefore = 0.0, forceAfter = 0.0;
    bool landed = false;
    for (size_t k = 0; k < r.times.size(); ++k) {
      const double t = r.times[k], z = r.rows[k][2], N = r.rows[k][3];
      landed |= t == tc;
      if (t <= tc) {
        before = std::max(before, std::abs(z + 1.0));
        forceBefore = std::max(forceBefore, std::abs(N - kMass * kG));
      } else {
        const double exact = -1.0 - 0.5 * kG * (t - tc) * (t - tc);
        after = std::max(after, std::abs(z - exact));
        forceAfter = std::max(forceAfter, std::abs(N));
      }
    }
    std::printf(
        "cut at %.1f s: step on t_c %s; before: |z - z0| <= %.2e ft, |N - mg| <= %.2e lbf; after: "
        "|z - free fall| <= %.2e ft (fell %.3f ft), N = %.1e\n",
        tc, landed ? "yes" : "no", before, forceBefore, after, 0.5 * kG * (0.3 - tc) * (0.3 - tc),
        forceAfter);
    EXPECT_TRUE(landed);
    // The start is the equilibrium up to the strain measure's O(eps^2) (eps = mg/EA = 2e-5), so
    // the mass trembles by ~1e-9 ft before the cut and keeps that ~1e-6 ft/s after it. An
    // acceleration left at its pre-cut value (0) would be off by g h^2/4 = 2e-5 ft after the
    // first step and by g h/2 = 0.015 ft/s from then on (3e-3 ft at 0.3 s).
    EXPECT_LT(before, 1e-8);
    EXPECT_LT(forceBefore, 1e-4 * kMass * kG);
    EXPECT_LT(after, 1e-6);
    EXPECT_EQ(forceAfter, 0.0);
  }
}

TEST(CutEvent, BadEventsNameFileLineAndKey) {
  for (const char* set : {"nothing", "rope"}) {
    try {
      readCase(writeCase("cut_bad", 0.1, set));
      ADD_FAILURE() << "cut of '" << set << "' accepted";
    } catch (const CaseError& e) {
      const std::string what = e.what();
      std::printf("%s\n", what.c_str());
      EXPECT_NE(what.find("cut_bad.toml:"), std::string::npos);
      EXPECT_NE(what.find("events[0].cut"), std::string::npos);
    }
  }
}
