// The broad phase of fabric contact (docs/contact.md CT10-CT11): its candidate lists equal a
// brute-force test of every pair's boxes, on crumpled random sheets with lines and on the
// half-scale C-9's canopy, slider and lines; they hold every pair within dHat + skin by exact
// distance; and while no node has moved more than skin/2 they still hold every pair within dHat.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>

#include "case/CaseSpec.hpp"
#include "kernels/ContactPotential.hpp"
#include "terms/contact/BroadPhase.hpp"
#include "terms/sliding/SlidingGroupState.hpp"

using namespace chute;
using namespace chute::contact;
using chute::kernels::ContactPairKind;

namespace {

// An n x n sheet of triangles on the unit square, crumpled: every node moved by a random vector
// of `noise` times the element size, and folded over itself once about x = 0.5 with the layers
// `gap` apart, plus `lines` cables between random nodes and free line nodes.
Model crumpledSheet(int n, double noise, double gap, int lines, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> nd(0, 1);
  Model m;
  const double h = 1.0 / n;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double u = i * h, v = j * h;
      // Fold: the part beyond u = 0.5 comes back over the first, gap above it.
      const Vec3 X = u <= 0.5 ? Vec3(u, v, 0.0) : Vec3(1.0 - u, v, gap);
      m.addNode(X + noise * h * Vec3(nd(rng), nd(rng), nd(rng)));
    }
  m.membraneSets.push_back({"sheet", true, 0.0});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      for (const auto& t : {std::array<int, 3>{a, b, c}, std::array<int, 3>{a, c, d}}) {
        MembraneElement e;
        e.nodes = {t[0], t[1], t[2], -1};
        e.numNodes = 3;
        e.set = 0;
        e.material = 0;
        m.membranes.push_back(e);
      }
    }
  m.lineSets.push_back({"lines", false});
  std::uniform_int_distribution<int> node(0, m.numNodes() - 1);
  for (int k = 0; k < lines; ++k) {
    const int a = node(rng);
    const int b = m.addNode(m.X[a] + 0.2 * Vec3(nd(rng), nd(rng), nd(rng)));
    m.cables.push_back({a, b, 0.1, 0, 0});
  }
  m.constraint.assign(m.numNodes(), NodeConstraint{});
  return m;
}

ContactDef allSets(const Model& m) {
  ContactDef d;
  d.enabled = true;
  for (int s = 0; s < static_cast<int>(m.membraneSets.size()); ++s) d.membraneSets.push_back(s);
  for (int s = 0; s < static_cast<int>(m.lineSets.size()); ++s) d.lineSets.push_back(s);
  return d;
}

Eigen::VectorXd positions(const Model& m) {
  Eigen::VectorXd x(3 * m.numNodes());
  for (int n = 0; n < m.numNodes(); ++n)
    x.segment<3>(3 * n) = m.X[n] + (m.u0.empty() ? Vec3::Zero() : m.u0[n]);
  return x;
}

std::array<Vec3, 4> gather(const Eigen::VectorXd& x, std::array<int, 4> n) {
  return {x.segment<3>(3 * n[0]), x.segment<3>(3 * n[1]), x.segment<3>(3 * n[2]),
          x.segment<3>(3 * n[3])};
}

// Every pair topology allows whose exact distance is at most `within` (cables only: no sliders).
struct Exact {
  std::vector<PointTrianglePair> pt;
  std::vector<EdgePair> ee, le;
};
Exact pairsWithin(const ContactMesh& mesh, const Eigen::VectorXd& x, double within) {
  Exact out;
  for (int p = 0; p < static_cast<int>(mesh.points().size()); ++p)
    for (int t = 0; t < static_cast<int>(mesh.triangles().size()); ++t) {
      const auto& tri = mesh.triangles()[t];
      const int node = mesh.points()[p];
      if (ContactMesh::incident(node, tri)) continue;
      const auto d = kernels::pairDistance(ContactPairKind::PointTriangle,
                                           gather(x, {node, tri[0], tri[1], tri[2]}), false);
      if (d.value <= within) out.pt.push_back({p, t});
    }
  for (int e = 0; e < static_cast<int>(mesh.edges().size()); ++e)
    for (int f = e + 1; f < static_cast<int>(mesh.edges().size()); ++f) {
      const auto& a = mesh.edges()[e];
      const auto& b = mesh.edges()[f];
      if (ContactMesh::adjacent(a, b)) continue;
      const auto d = kernels::pairDistance(ContactPairKind::EdgeEdge,
                                           gather(x, {a[0], a[1], b[0], b[1]}), false);
      if (d.value <= within) out.ee.push_back({e, f});
    }
  for (int l = 0; l < static_cast<int>(mesh.lines().size()); ++l)
    for (int f = 0; f < static_cast<int>(mesh.edges().size()); ++f) {
      const auto& line = mesh.lines()[l];
      const auto& b = mesh.edges()[f];
      if (ContactMesh::adjacent({line.a, line.b}, b)) continue;
      const auto d = kernels::pairDistance(ContactPairKind::EdgeEdge,
                                           gather(x, {line.a, line.b, b[0], b[1]}), false);
      if (d.value <= within) out.le.push_back({l, f});
    }
  return out;
}

template <class T>
bool includes(const std::vector<T>& sorted, const std::vector<T>& items) {
  return std::all_of(items.begin(), items.end(), [&](const T& t) {
    return std::binary_search(sorted.begin(), sorted.end(), t);
  });
}

}  // namespace

TEST(ContactBroadPhase, TreesMatchBruteForceOnCrumpledSheets) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const Model m = crumpledSheet(12, 0.3, 0.02, 20, seed);
    const ContactMesh mesh(m, allSets(m));
    const std::vector<int> noSliders(mesh.lines().size(), -1);
    const Eigen::VectorXd x = positions(m);
    for (double dHat : {0.005, 0.02, 0.08}) {
      BroadPhase tree(mesh, dHat, dHat), brute(mesh, dHat, dHat);
      tree.build(x, noSliders);
      brute.buildByBruteForce(x, noSliders);
      EXPECT_EQ(tree.pointTriangle(), brute.pointTriangle()) << seed << " " << dHat;
      EXPECT_EQ(tree.edgeEdge(), brute.edgeEdge()) << seed << " " << dHat;
      EXPECT_EQ(tree.lineEdge(), brute.lineEdge()) << seed << " " << dHat;
      // Every pair within dHat + skin by exact distance is a candidate.
      const Exact exact = pairsWithin(mesh, x, 2 * dHat);
      EXPECT_TRUE(includes(tree.pointTriangle(), exact.pt));
      EXPECT_TRUE(includes(tree.edgeEdge(), exact.ee));
      EXPECT_TRUE(includes(tree.lineEdge(), exact.le));
      std::printf(
          "seed %u, dHat %.3f: %zu point-triangle, %zu edge-edge, %zu line-edge "
          "candidates (brute force the same); within dHat + skin: %zu, %zu, %zu\n",
          seed, dHat, tree.pointTriangle().size(), tree.edgeEdge().size(), tree.lineEdge().size(),
          exact.pt.size(), exact.ee.size(), exact.le.size());
      EXPECT_GT(exact.pt.size() + exact.ee.size(), 0u);
    }
  }
}

TEST(ContactBroadPhase, TheSkinCoversEveryMotionBelowHalfOfItLessTheCommonShift) {
  const double dHat = 0.02, skin = 0.03;
  const Model m = crumpledSheet(10, 0.3, 0.03, 10, 7);
  const ContactMesh mesh(m, allSets(m));
  const std::vector<int> noSliders(mesh.lines().size(), -1);
  BroadPhase bp(mesh, dHat, skin);
  Eigen::VectorXd x = positions(m);
  bp.build(x, noSliders);
  std::mt19937 rng(4);
  std::normal_distribution<double> nd(0, 1);
  size_t checked = 0;
  for (int trial = 0; trial < 5; ++trial) {
    // The whole mesh carried 10 skins along (trials 1-4) and each node moved by under skin / 2
    // besides (0.4 skin in a random direction, under 0.5 once the mean of its sample is taken off):
    // covered, and every pair now within dHat was a candidate.
    Eigen::VectorXd y = x;
    const Vec3 carried = trial == 0
                             ? Vec3::Zero()
                             : Vec3(10.0 * skin * Vec3(nd(rng), nd(rng), nd(rng)).normalized());
    for (int n : mesh.nodes())
      y.segment<3>(3 * n) += carried + 0.4 * skin * Vec3(nd(rng), nd(rng), nd(rng)).normalized();
    EXPECT_TRUE(bp.covers(y, noSliders));
    const Exact near = pairsWithin(mesh, y, dHat);
    EXPECT_TRUE(includes(bp.pointTriangle(), near.pt));
    EXPECT_TRUE(includes(bp.edgeEdge(), near.ee));
    EXPECT_TRUE(includes(bp.lineEdge(), near.le));
    checked += near.pt.size() + near.ee.size() + near.le.size();
  }
  std::printf(
      "%zu pairs within dHat after moves of 10 skins together and under skin/2 apart: all "
      "candidates of the old list\n",
      checked);
  EXPECT_GT(checked, 100u);
  // A node moved by more than skin / 2: not covered any more.
  Eigen::VectorXd z = x;
  z[3 * mesh.nodes()[5]] += 0.51 * skin;
  EXPECT_FALSE(bp.covers(z, noSliders));
}

TEST(ContactBroadPhase, TreesMatchBruteForceOnTheC9WithSlider) {
  CaseSpec c = readCase(std::string(CHUTE_SOURCE_DIR) + "/cases/c9_slider.toml");
  Model& m = c.model;
  m.contact = allSets(m);
  const ContactMesh mesh(m, m.contact);
  std::vector<SlidingGroupState> states;
  std::vector<const SlidingGroupState*> ptrs;
  states.reserve(m.groups.size());
  for (const auto& g : m.groups) states.emplace_back(g);
  for (const auto& s : states) ptrs.push_back(&s);
  std::vector<int> sliders;
  mesh.slidersOn(ptrs, sliders);
  const long bent = std::count_if(sliders.begin(), sliders.end(), [](int s) { return s >= 0; });
  EXPECT_EQ(bent, 28);  // every line through its grommet
  const Eigen::VectorXd x = positions(m);
  for (double dHat : {0.01, 0.05}) {
    BroadPhase tree(mesh, dHat, dHat), brute(mesh, dHat, dHat);
    tree.build(x, sliders);
    brute.buildByBruteForce(x, sliders);
    EXPECT_EQ(tree.pointTriangle(), brute.pointTriangle());
    EXPECT_EQ(tree.edgeEdge(), brute.edgeEdge());
    EXPECT_EQ(tree.lineEdge(), brute.lineEdge());
    std::printf(
        "C-9 with slider (%zu triangles, %zu edges, %zu line elements), dHat %.2f ft: "
        "%zu + %zu + %zu candidates, brute force the same\n",
        mesh.triangles().size(), mesh.edges().size(), mesh.lines().size(), dHat,
        tree.pointTriangle().size(), tree.edgeEdge().size(), tree.lineEdge().size());
    EXPECT_GT(tree.pointTriangle().size(), 0u);
  }
}
