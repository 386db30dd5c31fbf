#pragma once
// The broad phase of fabric contact with a skin (docs/contact.md CT10, the Verlet-list idea):
// the candidate pairs are every pair of primitives whose bounding boxes, grown by (dHat + skin)/2
// each, overlap at the positions of the last build, less the pairs topology excludes (CT11).
// Every pair within dHat + skin at the build is a candidate, and while no node has moved more
// than skin/2 since, no pair can have come within dHat without being one: the list stands, and a
// step evaluates only the narrow phase over it. It is built again when a node has moved further
// or a slider has moved to another element. Two trees (BoundingVolumeHierarchy) over the
// triangles and the fabric edges are refitted at each build and built afresh when a refit has
// made them loose; the points', edges' and line elements' boxes are queried against them.
//
// The candidate lists are sorted, so that they depend on the build positions alone (not on the
// trees' shape): what a build depends on (its positions and sliders) is the history a restart
// needs to carry on bit for bit.
#include <Eigen/Core>
#include <vector>

#include "terms/contact/BoundingVolumeHierarchy.hpp"
#include "terms/contact/ContactMesh.hpp"

namespace chute::contact {

struct PointTrianglePair {
  int point = -1, triangle = -1;  // indices into ContactMesh::points() and triangles()
  bool operator<(const PointTrianglePair& o) const {
    return point < o.point || (point == o.point && triangle < o.triangle);
  }
  bool operator==(const PointTrianglePair& o) const {
    return point == o.point && triangle == o.triangle;
  }
};
// Two fabric edges (first < second), or a line element and a fabric edge.
struct EdgePair {
  int first = -1, second = -1;
  bool operator<(const EdgePair& o) const {
    return first < o.first || (first == o.first && second < o.second);
  }
  bool operator==(const EdgePair& o) const { return first == o.first && second == o.second; }
};

// What a build depends on: the positions of the mesh's nodes (ContactMesh::nodes(), in order)
// and the slider node on each line element (-1: none).
struct BuildState {
  Eigen::VectorXd positions;
  std::vector<int> sliders;
};

// CT10: the mesh's common translation from `packed` (its nodes' positions in ContactMesh::nodes()
// order) to x (all dofs of the model): the mean displacement of a sample of its nodes. Distances
// between primitives do not change under a common translation, so the lists' skins count each
// node's motion less this shift: a canopy carried along as a whole does not wear them out.
Eigen::Vector3d commonShift(const std::vector<int>& nodes, const Eigen::VectorXd& x,
                            const Eigen::VectorXd& packed);

class BroadPhase {
 public:
  BroadPhase(const ContactMesh& mesh, double thickness, double skin);

  // Whether the last build still covers positions x with these sliders on the line elements: no
  // node has moved more than skin/2 since, less the common shift (CT10).
  bool covers(const Eigen::VectorXd& x, const std::vector<int>& sliders) const;
  // The positions of the last build, over all nodes of the model (zero at nodes not in the mesh).
  Eigen::VectorXd buildPositions(int numNodes) const;
  // Builds the candidate lists at x (all dofs of the model).
  void build(const Eigen::VectorXd& x, const std::vector<int>& sliders);
  // The same from a saved build state (a restart, a reverted step).
  void build(const BuildState& s);
  bool built() const { return built_; }
  const BuildState& state() const { return state_; }

  const std::vector<PointTrianglePair>& pointTriangle() const { return pt_; }
  const std::vector<EdgePair>& edgeEdge() const { return ee_; }
  const std::vector<EdgePair>& lineEdge() const { return le_; }
  long builds() const { return builds_; }
  long treeBuilds() const { return treeBuilds_; }

  // Every candidate by testing every pair's boxes, O(n^2): the reference the trees must match.
  void buildByBruteForce(const Eigen::VectorXd& x, const std::vector<int>& sliders);

 private:
  void boxes(const Eigen::VectorXd& x, const std::vector<int>& sliders);
  bool anyFree(std::initializer_list<int> nodes) const;
  bool lineExcluded(int line, int edge, const std::vector<int>& sliders) const;
  void finish(const Eigen::VectorXd& x, const std::vector<int>& sliders);

  const ContactMesh* mesh_;
  double radius_;  // (dHat + skin) / 2: each box's growth
  double skin_;
  bool built_ = false;
  BuildState state_;
  std::vector<Aabb> pointBoxes_, triangleBoxes_, edgeBoxes_, lineBoxes_;
  BoundingVolumeHierarchy triangles_, edges_;
  std::vector<PointTrianglePair> pt_;
  std::vector<EdgePair> ee_, le_;
  long builds_ = 0, treeBuilds_ = 0;
};

}  // namespace chute::contact
