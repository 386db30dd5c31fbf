// The broad phase's cost against mesh size (docs/contact.md, "What it costs"): the candidate lists
// of fabric contact (BroadPhase::build: boxes, tree refit, queries, sorted lists) built at the
// start positions of each case given (every membrane and line set taking part) and of crumpled,
// folded sheets of n x n x 2 triangles generated here, timed over repeated builds (the median of
// five batches). One CSV row per mesh: name, triangles, edges, line elements, candidates, build
// (ms).
//
//   build/bin/bench_contact_broad_phase --thickness 0.01 --skin 0.03 a.toml b.toml ...
//   build/bin/bench_contact_broad_phase --sheets 16,32,64,128
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "case/CaseSpec.hpp"
#include "terms/contact/BroadPhase.hpp"
#include "terms/sliding/SlidingGroupState.hpp"

using namespace chute;

namespace {

// n x n x 2 triangles on the unit square folded twice (into four layers 1 / (2n) apart) and
// crumpled by a random motion of a third of an element.
Model foldedSheet(int n) {
  std::mt19937 rng(7);
  std::normal_distribution<double> nd(0, 1);
  Model m;
  const double h = 1.0 / n, gap = 0.5 * h;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      double u = i * h, z = 0.0;
      int layer = static_cast<int>(std::min(3.0, std::floor(4.0 * u)));
      const double w = 4.0 * u - layer;  // position within the layer, 0..1
      u = (layer % 2 == 0 ? w : 1.0 - w) * 0.25;
      z = layer * gap;
      m.addNode(Vec3(u, j * h, z) + 0.3 * h * Vec3(nd(rng), nd(rng), 0.3 * nd(rng)));
    }
  m.membraneSets.push_back({"sheet", true, 0.0});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      for (const auto& t : {std::array<int, 3>{a, b, c}, std::array<int, 3>{a, c, d}}) {
        MembraneElement e;
        e.nodes = {t[0], t[1], t[2], -1};
        e.set = 0, e.material = 0;
        m.membranes.push_back(e);
      }
    }
  m.constraint.assign(m.numNodes(), NodeConstraint{});
  m.u0.assign(m.numNodes(), Vec3::Zero());
  return m;
}

struct Row {
  std::string name;
  size_t triangles = 0, edges = 0, lines = 0, candidates = 0;
  double ms = 0.0;
};

Row measure(const std::string& name, Model& m, double thickness, double skin) {
  ContactDef& d = m.contact;
  d.enabled = true;
  d.membraneSets.clear(), d.lineSets.clear();
  for (int s = 0; s < static_cast<int>(m.membraneSets.size()); ++s) d.membraneSets.push_back(s);
  for (int s = 0; s < static_cast<int>(m.lineSets.size()); ++s) d.lineSets.push_back(s);
  const contact::ContactMesh mesh(m, d);
  std::vector<SlidingGroupState> states;
  states.reserve(m.groups.size());
  for (const auto& g : m.groups) states.emplace_back(g);
  std::vector<const SlidingGroupState*> ptrs;
  for (const auto& s : states) ptrs.push_back(&s);
  std::vector<int> sliders;
  mesh.slidersOn(ptrs, sliders);
  Eigen::VectorXd x(3 * m.numNodes());
  for (int k = 0; k < m.numNodes(); ++k) x.segment<3>(3 * k) = m.X[k] + m.u0[k];
  contact::BroadPhase bp(mesh, thickness, skin);
  bp.build(x, sliders);  // the trees built once; the builds timed refit them, as in a run
  const long per = std::max(3L, 2000000L / static_cast<long>(mesh.edges().size() + 1) / 20);
  std::vector<double> batches;
  for (int b = 0; b < 5; ++b) {
    const auto t0 = std::chrono::steady_clock::now();
    for (long k = 0; k < per; ++k) bp.build(x, sliders);
    batches.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() /
                      per);
  }
  std::sort(batches.begin(), batches.end());
  Row r{name,
        mesh.triangles().size(),
        mesh.edges().size(),
        mesh.lines().size(),
        bp.pointTriangle().size() + bp.edgeEdge().size() + bp.lineEdge().size(),
        1e3 * batches[2]};
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  double thickness = 0.01, skin = 0.03;
  std::vector<std::string> cases;
  std::vector<int> sheets;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--thickness" && i + 1 < argc)
      thickness = std::atof(argv[++i]);
    else if (a == "--skin" && i + 1 < argc)
      skin = std::atof(argv[++i]);
    else if (a == "--sheets" && i + 1 < argc) {
      std::stringstream ss(argv[++i]);
      for (std::string t; std::getline(ss, t, ',');) sheets.push_back(std::atoi(t.c_str()));
    } else
      cases.push_back(a);
  }
  std::printf("mesh,triangles,edges,line_elements,candidates,build_ms\n");
  for (const auto& file : cases) {
    CaseSpec c = readCase(file);
    const Row r = measure(file, c.model, thickness, skin);
    std::printf("%s,%zu,%zu,%zu,%zu,%.4f\n", r.name.c_str(), r.triangles, r.edges, r.lines,
                r.candidates, r.ms);
    std::fflush(stdout);
  }
  for (int n : sheets) {
    Model m = foldedSheet(n);
    // Thickness and skin relative to the element: a fifth of an element and three thicknesses.
    const double h = 1.0 / n;
    const Row r = measure("folded_sheet_" + std::to_string(n), m, 0.05 * h, 0.15 * h);
    std::printf("%s,%zu,%zu,%zu,%zu,%.4f\n", r.name.c_str(), r.triangles, r.edges, r.lines,
                r.candidates, r.ms);
    std::fflush(stdout);
  }
  return 0;
}
