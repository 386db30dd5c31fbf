// Runs a case (with --set overrides) and counts interpenetrations in its states every --every
// steps with the independent segment-triangle count of tests/support/Intersections.hpp: pairs of
// triangles without a common node that intersect, and line segments (cables; sliding-chain
// elements bent at their sliders) crossing a triangle they share no node with. One CSV row per
// state checked (t, triangle_pairs, line_crossings), a summary line at the end.
//
//   build/bin/bench_contact_intersections cases/crumple_square.toml --every 500
//   build/bin/bench_contact_intersections cases/crumple_square.toml --set contact.enabled=false
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "case/CaseSpec.hpp"
#include "support/Intersections.hpp"
#include "support/VisitRun.hpp"
#include "terms/sliding/SlidingGroupState.hpp"
#include "terms/sliding/SlidingGroupTerm.hpp"

using namespace chute;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s CASE [--set key=value]... [--every N] [--csv FILE]\n", argv[0]);
    return 2;
  }
  std::vector<std::string> sets;
  long every = 500;
  std::string csv;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--set" && i + 1 < argc)
      sets.push_back(argv[++i]);
    else if (a == "--every" && i + 1 < argc)
      every = std::atol(argv[++i]);
    else if (a == "--csv" && i + 1 < argc)
      csv = argv[++i];
    else {
      std::fprintf(stderr, "unknown argument %s\n", a.c_str());
      return 2;
    }
  }
  const CaseSpec spec = readCase(argv[1], sets);
  const Model& m = spec.model;
  const auto tris = testing::modelTriangles(m);
  FILE* out = csv.empty() ? stdout : std::fopen(csv.c_str(), "w");
  std::fprintf(out, "t,triangle_pairs,line_crossings\n");
  long states = 0, worstTri = 0, worstLine = 0, withAny = 0;
  const auto r =
      testing::visitRun(spec, every, [&](const StructuralState& s, const StructuralSystem& sys) {
        std::vector<testing::Seg> segs;
        for (const auto& c : m.cables)
          if (!m.lineSets[c.set].goneAt(s.t)) segs.push_back({c.a, c.b});
        for (const auto* g : sys.termList().slidingGroups()) {
          const auto& st = g->state();
          const auto& def = st.def();
          for (int k = 0; k < def.numElements(); ++k) {
            const int sl = st.sliderOfElement(k);
            if (sl < 0) {
              segs.push_back({def.chain[k], def.chain[k + 1]});
            } else {
              segs.push_back({def.chain[k], def.sliders[sl]});
              segs.push_back({def.sliders[sl], def.chain[k + 1]});
            }
          }
        }
        const auto n = testing::countIntersections(s.x, tris, segs);
        ++states;
        worstTri = std::max(worstTri, n.trianglePairs);
        worstLine = std::max(worstLine, n.segmentTriangles);
        withAny += (n.trianglePairs + n.segmentTriangles) > 0;
        std::fprintf(out, "%.6g,%ld,%ld\n", s.t, n.trianglePairs, n.segmentTriangles);
        std::fflush(out);
      });
  std::printf(
      "%s: %s to t = %.4g in %ld steps; %ld states checked, %ld with an intersection; at "
      "most %ld intersecting triangle pairs and %ld line crossings in one state\n",
      argv[1], r.reached ? "ran" : "STOPPED", r.finalTime, r.steps, states, withAny, worstTri,
      worstLine);
  if (out != stdout) std::fclose(out);
  return r.reached ? 0 : 3;
}
