#include "terms/contact/BroadPhase.hpp"

#include <algorithm>

namespace chute::contact {

namespace {
// A refit tree is built afresh when it has grown this much looser than at its build (CT10).
constexpr double kLooserThanBuilt = 1.5;

int firstOf(const PointTrianglePair& p) {
  return p.point;
}
int firstOf(const EdgePair& p) {
  return p.first;
}

Eigen::Vector3d at(const Eigen::VectorXd& x, int n) {
  return x.segment<3>(3 * n);
}
// The pairs in order (first, then second): counted into one bucket per first index, each
// bucket (a few pairs) then sorted; O(n + firsts), where a comparison sort of the whole list
// took a third of a build on the C-9.
template <class Pair>
void sortByFirst(std::vector<Pair>& pairs, size_t firsts) {
  static thread_local std::vector<int> start;
  static thread_local std::vector<Pair> sorted;
  start.assign(firsts + 1, 0);
  for (const Pair& p : pairs) ++start[static_cast<size_t>(firstOf(p)) + 1];
  for (size_t k = 0; k < firsts; ++k) start[k + 1] += start[k];
  sorted.resize(pairs.size());
  for (const Pair& p : pairs) sorted[start[static_cast<size_t>(firstOf(p))]++] = p;
  // start[k] is now the end of bucket k (the start of bucket k + 1).
  for (size_t k = 0, begin = 0; k < firsts; begin = start[k], ++k)
    std::sort(sorted.begin() + static_cast<long>(begin), sorted.begin() + start[k]);
  pairs.swap(sorted);
}

}  // namespace

// Any shift keeps the lists' bounds exact (CT10); the mean over a sample of about 256 nodes
// is close enough to the mean over all, for a sixteenth of the pass on the C-9.
Eigen::Vector3d commonShift(const std::vector<int>& nodes, const Eigen::VectorXd& x,
                            const Eigen::VectorXd& packed) {
  const size_t stride = std::max<size_t>(1, nodes.size() / 256);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  size_t count = 0;
  for (size_t i = 0; i < nodes.size(); i += stride, ++count)
    sum += at(x, nodes[i]) - packed.segment<3>(3 * i);
  return count == 0 ? sum : Eigen::Vector3d(sum / static_cast<double>(count));
}

BroadPhase::BroadPhase(const ContactMesh& mesh, double thickness, double skin)
    : mesh_(&mesh), radius_(0.5 * (thickness + skin)), skin_(skin) {}

bool BroadPhase::covers(const Eigen::VectorXd& x, const std::vector<int>& sliders) const {
  if (!built_ || sliders != state_.sliders) return false;
  const double limit = 0.25 * skin_ * skin_;  // (skin / 2)^2
  const auto& nodes = mesh_->nodes();
  const Eigen::Vector3d shift = commonShift(nodes, x, state_.positions);
  for (size_t i = 0; i < nodes.size(); ++i)
    if ((at(x, nodes[i]) - state_.positions.segment<3>(3 * i) - shift).squaredNorm() > limit)
      return false;
  return true;
}

Eigen::VectorXd BroadPhase::buildPositions(int numNodes) const {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(3 * static_cast<long>(numNodes));
  const auto& nodes = mesh_->nodes();
  for (size_t i = 0; i < nodes.size(); ++i)
    x.segment<3>(3 * nodes[i]) = state_.positions.segment<3>(3 * i);
  return x;
}

void BroadPhase::boxes(const Eigen::VectorXd& x, const std::vector<int>& sliders) {
  const ContactMesh& m = *mesh_;
  auto grown = [&](std::initializer_list<int> nodes) {
    Aabb b;
    for (int n : nodes)
      if (n >= 0) b.add(at(x, n));
    b.inflate(radius_);
    return b;
  };
  pointBoxes_.resize(m.points().size());
  for (size_t i = 0; i < m.points().size(); ++i) pointBoxes_[i] = grown({m.points()[i]});
  triangleBoxes_.resize(m.triangles().size());
  for (size_t i = 0; i < m.triangles().size(); ++i) {
    const auto& t = m.triangles()[i];
    triangleBoxes_[i] = grown({t[0], t[1], t[2]});
  }
  edgeBoxes_.resize(m.edges().size());
  for (size_t i = 0; i < m.edges().size(); ++i)
    edgeBoxes_[i] = grown({m.edges()[i][0], m.edges()[i][1]});
  lineBoxes_.resize(m.lines().size());
  for (size_t i = 0; i < m.lines().size(); ++i)
    lineBoxes_[i] = grown({m.lines()[i].a, m.lines()[i].b, sliders[i]});
}

bool BroadPhase::anyFree(std::initializer_list<int> nodes) const {
  for (int n : nodes)
    if (n >= 0 && mesh_->free(n)) return true;
  return false;
}

// A line element bent at a slider is two segments: the pair is excluded when both are.
bool BroadPhase::lineExcluded(int line, int edge, const std::vector<int>& sliders) const {
  const auto& l = mesh_->lines()[line];
  const auto& e = mesh_->edges()[edge];
  const int s = sliders[line];
  if (s < 0) return ContactMesh::adjacent({l.a, l.b}, e);
  return ContactMesh::adjacent({l.a, s}, e) && ContactMesh::adjacent({s, l.b}, e);
}

void BroadPhase::build(const Eigen::VectorXd& x, const std::vector<int>& sliders) {
  const ContactMesh& m = *mesh_;
  boxes(x, sliders);
  // Refit, or build afresh the first time and when the refit has made a tree loose.
  for (auto [tree, list] : {std::pair{&triangles_, &triangleBoxes_}, {&edges_, &edgeBoxes_}}) {
    if (list->empty()) continue;
    if (!tree->empty()) tree->refit(*list);
    if (tree->empty() || tree->looseness() > kLooserThanBuilt * tree->loosenessAtBuild()) {
      tree->build(*list);
      ++treeBuilds_;
    }
  }
  pt_.clear(), ee_.clear(), le_.clear();
  // Each point's box against the triangles' tree; the edges' tree against itself, a traversal
  // per leaf of four edges, each pair met once (per edge, each pair twice, was measured twice as
  // slow on the C-9's canopy); line elements' boxes against the edges' tree. finish() sorts.
  for (int p = 0; p < static_cast<int>(m.points().size()); ++p) {
    const int node = m.points()[p];
    triangles_.query(pointBoxes_[p], [&](int t) {
      const auto& tri = m.triangles()[t];
      if (!ContactMesh::incident(node, tri) && anyFree({node, tri[0], tri[1], tri[2]}))
        pt_.push_back({p, t});
    });
  }
  edges_.selfPairs([&](int e, int f) {
    const auto& a = m.edges()[e];
    const auto& b = m.edges()[f];
    if (!ContactMesh::adjacent(a, b) && anyFree({a[0], a[1], b[0], b[1]}))
      ee_.push_back({std::min(e, f), std::max(e, f)});
  });
  for (int l = 0; l < static_cast<int>(m.lines().size()); ++l) {
    const auto& line = m.lines()[l];
    edges_.query(lineBoxes_[l], [&](int f) {
      const auto& b = m.edges()[f];
      if (!lineExcluded(l, f, sliders) && anyFree({line.a, line.b, sliders[l], b[0], b[1]}))
        le_.push_back({l, f});
    });
  }
  finish(x, sliders);
}

void BroadPhase::buildByBruteForce(const Eigen::VectorXd& x, const std::vector<int>& sliders) {
  const ContactMesh& m = *mesh_;
  boxes(x, sliders);
  pt_.clear(), ee_.clear(), le_.clear();
  for (int p = 0; p < static_cast<int>(m.points().size()); ++p)
    for (int t = 0; t < static_cast<int>(m.triangles().size()); ++t) {
      const auto& tri = m.triangles()[t];
      const int node = m.points()[p];
      if (pointBoxes_[p].overlaps(triangleBoxes_[t]) && !ContactMesh::incident(node, tri) &&
          anyFree({node, tri[0], tri[1], tri[2]}))
        pt_.push_back({p, t});
    }
  for (int e = 0; e < static_cast<int>(m.edges().size()); ++e)
    for (int f = e + 1; f < static_cast<int>(m.edges().size()); ++f) {
      const auto& a = m.edges()[e];
      const auto& b = m.edges()[f];
      if (edgeBoxes_[e].overlaps(edgeBoxes_[f]) && !ContactMesh::adjacent(a, b) &&
          anyFree({a[0], a[1], b[0], b[1]}))
        ee_.push_back({e, f});
    }
  for (int l = 0; l < static_cast<int>(m.lines().size()); ++l)
    for (int f = 0; f < static_cast<int>(m.edges().size()); ++f) {
      const auto& line = m.lines()[l];
      const auto& b = m.edges()[f];
      if (lineBoxes_[l].overlaps(edgeBoxes_[f]) && !lineExcluded(l, f, sliders) &&
          anyFree({line.a, line.b, sliders[l], b[0], b[1]}))
        le_.push_back({l, f});
    }
  finish(x, sliders);
}

void BroadPhase::finish(const Eigen::VectorXd& x, const std::vector<int>& sliders) {
  sortByFirst(pt_, mesh_->points().size());
  sortByFirst(ee_, mesh_->edges().size());
  sortByFirst(le_, mesh_->lines().size());
  const auto& nodes = mesh_->nodes();
  state_.positions.resize(3 * static_cast<long>(nodes.size()));
  for (size_t i = 0; i < nodes.size(); ++i) state_.positions.segment<3>(3 * i) = at(x, nodes[i]);
  state_.sliders = sliders;
  built_ = true;
  ++builds_;
}

void BroadPhase::build(const BuildState& s) {
  // The model's positions with the mesh's nodes where the build had them (only those are read).
  int size = 0;
  for (int n : mesh_->nodes()) size = std::max(size, n + 1);
  state_ = s;
  build(buildPositions(size), s.sliders);
}

}  // namespace chute::contact
