#include "terms/CanopyFlowTerm.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>
#include <type_traits>

#include "kernels/MembraneTriangleBatch.hpp"
#include "terms/FaceLoadFusion.hpp"

namespace chute {

using Vec3 = Eigen::Vector3d;

namespace {

Vec3 at(const Eigen::VectorXd& x, int n) {
  return x.segment<3>(3 * n);
}

// The triangles of a face: itself, or a quad's two halves (0, 1, 2), (0, 2, 3).
template <class F>
void forTriangles(const MembraneElement& e, F&& f) {
  f(e.nodes[0], e.nodes[1], e.nodes[2]);
  if (e.numNodes == 4) f(e.nodes[0], e.nodes[2], e.nodes[3]);
}

// The boundary of a set of faces as closed loops of nodes (edges used by one face only).
std::vector<std::vector<int>> boundaryLoops(const Model& m, const std::vector<int>& faces) {
  std::map<std::pair<int, int>, int> uses;
  for (int k : faces) {
    const auto& e = m.membranes[k];
    for (int i = 0; i < e.numNodes; ++i) {
      const int a = e.nodes[i], b = e.nodes[(i + 1) % e.numNodes];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  }
  std::map<int, std::vector<int>> next;
  for (const auto& [edge, count] : uses)
    if (count == 1) {
      next[edge.first].push_back(edge.second);
      next[edge.second].push_back(edge.first);
    }
  std::vector<std::vector<int>> loops;
  std::map<int, bool> seen;
  for (const auto& [start, ns] : next) {
    if (seen[start]) continue;
    if (ns.size() != 2)
      throw std::invalid_argument("its boundary is not a set of closed loops (node " +
                                  std::to_string(start + 1) + " has " + std::to_string(ns.size()) +
                                  " boundary edges)");
    std::vector<int> loop{start};
    seen[start] = true;
    int prev = start, cur = ns[0];
    while (cur != start) {
      if (next[cur].size() != 2)
        throw std::invalid_argument("its boundary is not a set of closed loops (node " +
                                    std::to_string(cur + 1) + ")");
      loop.push_back(cur);
      seen[cur] = true;
      const int nxt = next[cur][0] == prev ? next[cur][1] : next[cur][0];
      prev = cur, cur = nxt;
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

double perimeter(const Model& m, const std::vector<int>& loop) {
  double p = 0.0;
  for (size_t i = 0; i < loop.size(); ++i)
    p += (m.X[loop[(i + 1) % loop.size()]] - m.X[loop[i]]).norm();
  return p;
}

}  // namespace

CanopyFlowTerm::CanopyFlowTerm(const Model& m, int flow) : m_(&m), def_(&m.canopyFlows[flow]) {
  for (size_t k = 0; k < m.membranes.size(); ++k)
    if (m.membranes[k].set == def_->set) faces_.push_back(static_cast<int>(k));
  if (faces_.empty()) throw std::invalid_argument("the membrane set has no elements");
  slot_.assign(m.numNodes(), -1);
  for (int k : faces_)
    for (int i = 0; i < m.membranes[k].numNodes; ++i) {
      const int n = m.membranes[k].nodes[i];
      if (slot_[n] < 0) slot_[n] = static_cast<int>(nodes_.size()), nodes_.push_back(n);
    }
  // Each face's nodes and their slots side by side, read in order by every pass over the faces.
  faceNodes_.resize(faces_.size());
  for (size_t i = 0; i < faces_.size(); ++i) {
    const auto& e = m.membranes[faces_[i]];
    FaceNodes& f = faceNodes_[i];
    f.size = e.numNodes;
    for (int k = 0; k < e.numNodes; ++k) f.node[k] = e.nodes[k], f.slot[k] = slot_[e.nodes[k]];
  }
  // FL2: the openings, oriented on the reference (the cut pattern, where the canopy's area
  // vector S is clear): the mouth's outward normal against S, a vent's along it. The mouth is the
  // longest boundary loop.
  auto loops = boundaryLoops(m, faces_);
  if (loops.empty()) throw std::invalid_argument("it has no opening (a closed surface)");
  std::sort(loops.begin(), loops.end(),
            [&](const auto& a, const auto& b) { return perimeter(m, a) > perimeter(m, b); });
  Eigen::VectorXd X(3 * m.numNodes());
  for (int n = 0; n < m.numNodes(); ++n) X.segment<3>(3 * n) = m.X[n];
  Vec3 S = Vec3::Zero();
  double areaRef = 0.0;
  for (int k : faces_)
    forTriangles(m.membranes[k], [&](int a, int b, int c) {
      const Vec3 A = 0.5 * (at(X, b) - at(X, a)).cross(at(X, c) - at(X, a));
      S += A;
      areaRef += A.norm();
    });
  for (size_t l = 0; l < loops.size(); ++l) {
    Loop loop{loops[l], 1.0};
    const double along = loopArea(loop, X).dot(S);
    if (!(std::abs(along) > 1e-9 * areaRef * areaRef))
      throw std::invalid_argument(
          "its openings cannot be oriented on the reference (its area vector vanishes)");
    loop.sign = (l == 0) == (along > 0.0) ? -1.0 : 1.0;
    (l == 0 ? mouth_ : vents_.emplace_back()) = loop;
  }
  {
    Vec3 c = Vec3::Zero();
    for (int n : mouth_.nodes) c += m.X[n];
    c /= static_cast<double>(mouth_.nodes.size());
    for (int n : mouth_.nodes)
      nominalDiameter_ = std::max(nominalDiameter_, 2.0 * (m.X[n] - c).norm());
  }
  // The gas law's least volume: a fraction of the hemisphere on the pattern's radius.
  const double R = std::sqrt(areaRef / std::numbers::pi);
  volumeFloor_ = def_->volumeFloor * (2.0 / 3.0) * std::numbers::pi * R * R * R;
  // The start holds air at the ambient pressure plus the case's initial gauge (FL3, isentropic).
  Eigen::VectorXd x0(3 * m.numNodes());
  for (int n = 0; n < m.numNodes(); ++n) x0.segment<3>(3 * n) = m.X[n] + m.u0[n];
  const Geometry g = geometry(x0);
  captured_ = m.air.density * (std::max(g.volume, 0.0) + volumeFloor_) *
              std::pow(1.0 + def_->initialInsideGauge / m.air.pressure, 1.0 / def_->gamma);
  inertiaMass_ = apparentMass(x0) + captured_;  // FL11: the air around it and the air inside
  committedShares_ = areaShares(x0);
  formNodeMass();
  committedVolume_ = g.volume;
}

double CanopyFlowTerm::reach(const Eigen::VectorXd& x) const {
  // The largest distance of a canopy node from the axis through the mouth's centroid along the
  // mouth's normal (the canopy's projected radius).
  const Vec3 A = loopArea(mouth_, x);
  const double area = A.norm();
  if (!(area > 0.0)) return 0.0;
  const Vec3 axis = A / area;
  Vec3 c = Vec3::Zero();
  for (int n : mouth_.nodes) c += at(x, n);
  c /= static_cast<double>(mouth_.nodes.size());
  double r = 0.0;
  for (int n : nodes_) {
    const Vec3 d = at(x, n) - c;
    r = std::max(r, (d - d.dot(axis) * axis).norm());
  }
  return r;
}

double CanopyFlowTerm::apparentMass(const Eigen::VectorXd& x) const {
  // FL11: k_a rho R^3 with R the radius of the hemisphere that holds the canopy's volume
  // (R^3 = 3 V / (2 pi)). The volume, an integral over the surface, changes smoothly with the
  // positions; the canopy's largest radius (its reach) jumps as one node swings out, and the
  // growth force of FL10 took such a jump as a burst of air (a folded C-9 went unstable).
  return apparentMassOfVolume(geometry(x).volume);
}

double CanopyFlowTerm::apparentMassOfVolume(double volume) const {
  const double radiusCubed = 1.5 * std::max(volume, 0.0) / std::numbers::pi;
  return def_->apparentMass * m_->air.density * radiusCubed;
}

double CanopyFlowTerm::nominalArea() const {
  return 0.25 * std::numbers::pi * nominalDiameter_ * nominalDiameter_;
}

Vec3 CanopyFlowTerm::loopArea(const Loop& l, const Eigen::VectorXd& x) const {
  Vec3 c = Vec3::Zero();
  for (int n : l.nodes) c += at(x, n);
  c /= static_cast<double>(l.nodes.size());
  Vec3 A = Vec3::Zero();
  for (size_t i = 0; i < l.nodes.size(); ++i)
    A += 0.5 * (at(x, l.nodes[i]) - c).cross(at(x, l.nodes[(i + 1) % l.nodes.size()]) - c);
  return l.sign * A;
}

CanopyFlowTerm::Geometry CanopyFlowTerm::geometry(const Eigen::VectorXd& x) const {
  // The evaluations' pass over the faces in still air, its sums alone (start-up and commits that
  // follow no explicit step's evaluation).
  const FaceSums sums =
      facePass<false>(x, Eigen::VectorXd::Zero(x.size()), kernels::CanopyFlowState{}, 0.0, false);
  Geometry g;
  g.volume = sums.volume, g.area = sums.area;
  closeOpenings(x, g);
  return g;
}

void CanopyFlowTerm::closeOpenings(const Eigen::VectorXd& x, Geometry& g) const {
  // The openings close the surface with fans from their centroids (FL2).
  auto close = [&](const Loop& l) {
    const double n = static_cast<double>(l.nodes.size());
    Vec3 c = Vec3::Zero();
    for (int node : l.nodes) c += at(x, node);
    c /= n;
    // The fan's tetrahedra with the origin, c . (x_a x x_b) / 6 each, sum to c . A / 3: with
    // d = x - c, c . (x_a x x_b) = c . (d_a x d_b), the other products being normal to c.
    Vec3 A = Vec3::Zero();
    const size_t count = l.nodes.size();
    for (size_t i = 0; i < count; ++i) {
      int a = l.nodes[i], b = l.nodes[i + 1 < count ? i + 1 : 0];
      if (l.sign < 0.0) std::swap(a, b);
      A += (at(x, a) - c).cross(at(x, b) - c);
    }
    A *= 0.5;
    g.volume += c.dot(A) * (1.0 / 3.0);
    return A;
  };
  g.mouth = close(mouth_);
  g.vents.clear();
  for (const auto& vent : vents_) g.vents.push_back(close(vent));
}

template <bool Keep>
CanopyFlowTerm::FaceSums CanopyFlowTerm::facePass(const Eigen::VectorXd& x,
                                                  const Eigen::VectorXd& v,
                                                  const kernels::CanopyFlowState& s,
                                                  double clothGauge, bool permeable) const {
  // One pass over the faces for everything an evaluation needs of them: the faces' area vectors
  // and mean velocities are made once and used at once (two passes, the second reading them
  // back from memory, had cost twice as much: the flow state they need, FL1, is known before
  // the pass, from the nodes' shares at the step's start).
  if constexpr (Keep)
    nodeSums_.assign(nodes_.size(), NodeSums{Vec3::Zero(), 0.0, Vec3::Zero(), 0.0});
  // The sums are held in locals (the compiler cannot tell a member from the arrays stored to).
  double volume = 0.0, area = 0.0, cloth = 0.0, dCloth = 0.0;
  const kernels::ClothPermeability& law = def_->cloth;
  // One face with its node count known to the compiler (its loops over its nodes unrolled).
  // Divisions by the node count and by 9 are multiplications by their reciprocals.
  auto face = [&](const FaceNodes& fn, auto nodesTag) {
    constexpr int N = decltype(nodesTag)::value;
    constexpr double perNode = 1.0 / N;
    const Vec3 x0 = at(x, fn.node[0]), x1 = at(x, fn.node[1]), x2 = at(x, fn.node[2]);
    Vec3 vf = at(v, fn.node[0]) + at(v, fn.node[1]) + at(v, fn.node[2]);
    Vec3 A;
    if constexpr (N == 3) {
      A = 0.5 * (x1 - x0).cross(x2 - x0);
      volume += (x0 + x1 + x2).dot(A) * (1.0 / 9.0);  // tetraVolume(x0, x1, x2): centroid . A / 3
    } else {
      const Vec3 x3 = at(x, fn.node[3]);
      vf += at(v, fn.node[3]);
      A = 0.5 * (x2 - x0).cross(x3 - x1);  // the exact area vector of a bilinear quad
      volume += kernels::tetraVolume(x0, x1, x2) + kernels::tetraVolume(x0, x2, x3);
    }
    vf *= perNode;
    const double faceArea = A.norm();
    area += faceArea;
    if (!(faceArea > 0.0)) return;  // no normal: no load, no share, no cloth
    // FL7-FL8 at the ambient inside pressure; the unit normal by one division.
    const kernels::FacePressure fp = kernels::facePressure(A * (1.0 / faceArea), vf, s);
    if (permeable) {
      // FL6's pressure difference: inside (at the linearisation's gauge) minus outside.
      const double dp = clothGauge + fp.staticDifference;
      cloth += faceArea * law.velocity(dp);
      dCloth += faceArea * law.dVelocity(dp);
    }
    if constexpr (Keep) {
      const Vec3 aN = A * perNode;
      const Vec3 force = fp.netPressure * aN;
      const double shareN = faceArea * perNode;
      for (int k = 0; k < N; ++k) {
        NodeSums& n = nodeSums_[fn.slot[k]];
        n.force += force;
        n.area += aN;
        n.share += shareN;
      }
    }
  };
  for (const FaceNodes& fn : faceNodes_) {
    if (fn.size == 3)
      face(fn, std::integral_constant<int, 3>{});
    else
      face(fn, std::integral_constant<int, 4>{});
  }
  if constexpr (Keep)
    if (area > 0.0)
      for (NodeSums& n : nodeSums_) n.share /= area;
  return {volume, area, cloth, dCloth};
}

std::vector<double> CanopyFlowTerm::areaShares(const Eigen::VectorXd& x) const {
  // Each face's area in equal parts to its nodes, over the canopy's area (as geometry keeps).
  std::vector<double> share(nodes_.size(), 0.0);
  double total = 0.0;
  for (int k : faces_) {
    const auto& e = m_->membranes[k];
    const Vec3 x0 = at(x, e.nodes[0]), x2 = at(x, e.nodes[2]);
    const double area = e.numNodes == 3
                            ? 0.5 * (at(x, e.nodes[1]) - x0).cross(x2 - x0).norm()
                            : 0.5 * (x2 - x0).cross(at(x, e.nodes[3]) - at(x, e.nodes[1])).norm();
    for (int i = 0; i < e.numNodes; ++i) share[slot_[e.nodes[i]]] += area / e.numNodes;
    total += area;
  }
  if (total > 0.0)
    for (double& sh : share) sh /= total;
  return share;
}

void CanopyFlowTerm::addCouplings(std::vector<std::vector<int>>& cliques) const {
  for (int k : faces_) {
    const auto& e = m_->membranes[k];
    cliques.emplace_back(e.nodes.begin(), e.nodes.begin() + e.numNodes);
  }
}

void CanopyFlowTerm::assemble(const EvalPoint& p, SystemAssembler& out) {
  if (!p.inertia || p.inertiaOnly) return;  // a load of motion: dynamics only; its mass below
  // Loads, not stiffness: at the step's own positions whatever stiffness damping shifts (EX7).
  // An explicit step's forces take the captured air at the step's end (FL9): its update is made
  // here, on trial, and committed with the step.
  // Taken, the membranes' pass made them (finishTakenPass).
  if (taken_ && fusedFaceLoads(p, out)) return;
  keepStepEvaluation(p, evaluate(p.stepPositions(), p.v, &out, p.loadFactor, p.explicitStep));
}

const double* CanopyFlowTerm::committedNodalMass() const {
  // FL11: the captured air moves with the canopy, each node carrying its area's share, both as
  // committed (lagged one step; the explicit step forms it alongside its assembly).
  return nodeMass_.data();
}

void CanopyFlowTerm::formNodeMass() {
  nodeMass_.resize(nodes_.size());
  for (size_t i = 0; i < nodes_.size(); ++i) nodeMass_[i] = inertiaMass_ * committedShares_[i];
}

void CanopyFlowTerm::keepStepEvaluation(const EvalPoint& p, const Evaluation& e) {
  if (p.explicitStep > 0.0) trialMass_ = e.capturedMass, trialTime_ = p.t;
  // The face data just made are those of the state at p.t (an explicit step's end).
  scratchTime_ = p.explicitStep > 0.0 ? p.t : std::numeric_limits<double>::quiet_NaN();
  scratchVolume_ = e.figures.volume;
}

bool CanopyFlowTerm::trianglesOnly() const {
  for (const FaceNodes& fn : faceNodes_)
    if (fn.size != 3) return false;
  return true;
}

kernels::TriangleFlowParameters CanopyFlowTerm::takenParameters(const EvalPoint& p) {
  pass_.state = flowState(p.v, p.inHalves);
  pass_.gauge = startGauge();
  const kernels::CanopyFlowState& s = pass_.state;
  kernels::TriangleFlowParameters q;
  for (int c = 0; c < 3; ++c)
    q.flowDirection[c] = s.flowDirection[c], q.canopyVelocity[c] = s.canopyVelocity[c];
  q.dynamicPressure = s.dynamicPressure;
  q.baseCoefficient = s.baseCoefficient;
  q.normalDrag = s.normalDrag;
  q.clothGauge = pass_.gauge;
  const kernels::ClothPermeability& law = def_->cloth;
  q.permeable = law.permeable();
  q.viscous = law.viscous, q.inertial = law.inertial, q.perViscous = law.perViscous;
  q.loadFactor = p.loadFactor;
  q.dampingShift = p.undamped ? p.dampingShift : 0.0;
  return q;
}

void CanopyFlowTerm::takeFaces(const std::vector<std::array<int, 3>>& triangleSlots) {
  // Each node's triangles, in the triangles' order: where it gathers its records (FL13).
  const size_t n = nodes_.size();
  std::vector<int> count(n + 1, 0);
  for (const auto& slots : triangleSlots)
    if (slots[0] >= 0)
      for (int s : slots) ++count[s + 1];
  for (size_t i = 0; i < n; ++i) count[i + 1] += count[i];
  nodeRecordsStart_ = count;
  nodeRecords_.assign(count[n], 0);
  for (size_t k = 0; k < triangleSlots.size(); ++k)
    if (triangleSlots[k][0] >= 0)
      for (int s : triangleSlots[k]) nodeRecords_[count[s]++] = 4 * static_cast<int>(k);
  // Every lane of every batch writes its record, the missing lanes of the last one too.
  faceRecords_.assign(4 * ((triangleSlots.size() + 3) / 4 * 4), 0.0);
  nodeSums_.resize(n);
  taken_ = true;
}

void CanopyFlowTerm::finishTakenPass(const EvalPoint& p, const FaceSums& sums,
                                     SystemAssembler& out) {
  finishTakenSums(p, sums);
  finishTakenNodesOver(out, 0, nodes_.size());
}

void CanopyFlowTerm::finishTakenSums(const EvalPoint& p, const FaceSums& sums) {
  const Evaluation e = complete(p.stepPositions(), sums, pass_.state, pass_.gauge, nullptr,
                                p.loadFactor, p.explicitStep, true, true);
  keepStepEvaluation(p, e);
  halves_ = {e.figures.insideGauge, p.loadFactor, sums.area, pass_.state.canopyVelocity};
}

template <class Record>
void CanopyFlowTerm::addNodeLoadsOf(SystemAssembler& out, size_t begin, size_t end, double p,
                                    double loadFactor, const Vec3& canopyVelocity, bool facesTaken,
                                    Record record) const {
  // FL8's inside pressure, and FL10: air newly set moving with the canopy is brought from rest
  // (in the air) to the canopy's velocity: the force -dm_a/dt (v_c - w) while the apparent mass
  // grows (air shed as it shrinks leaves with the canopy's velocity), shared as the inertia is.
  // record(i) is called once per node.
  if (facesTaken && !(massRate_ > 0.0)) {
    // The membranes' pass made the faces' loads (FL13), and no air is being entrained: the inside
    // pressure's part alone (the same values as the general loop's with no push and no force).
    out.addPerNode(nodes_.data(), begin, end,
                   [&](size_t i) { return Vec3(loadFactor * -(p * record(i).area)); });
    return;
  }
  const Vec3 push =
      massRate_ > 0.0 ? Vec3(massRate_ * (canopyVelocity - m_->air.wind)) : Vec3::Zero();
  // With the faces taken, the records hold no force (the same values as subtracting a zero one).
  if (facesTaken) {
    out.addPerNode(nodes_.data(), begin, end, [&](size_t i) {
      const NodeSums& n = record(i);
      return Vec3(loadFactor * (n.share * push - p * n.area));
    });
    return;
  }
  out.addPerNode(nodes_.data(), begin, end, [&](size_t i) {
    const NodeSums& n = record(i);
    return Vec3(loadFactor * (n.share * push - p * n.area - n.force));
  });
}

void CanopyFlowTerm::addNodeLoads(SystemAssembler& out, size_t begin, size_t end, double p,
                                  double loadFactor, const Vec3& canopyVelocity,
                                  bool facesTaken) const {
  const NodeSums* sums = nodeSums_.data();
  addNodeLoadsOf(out, begin, end, p, loadFactor, canopyVelocity, facesTaken,
                 [=](size_t i) -> const NodeSums& { return sums[i]; });
}

void CanopyFlowTerm::finishTakenNodes(SystemAssembler& out, int half) {
  const auto [begin, end] = halfOf(nodes_.size(), half);
  finishTakenNodesOver(out, begin, end);
}

void CanopyFlowTerm::finishTakenNodesOver(SystemAssembler& out, size_t begin, size_t end) {
  // Each node's records gathered from its triangles' (in their order), its share over the whole
  // area, its loads, in one pass; kept in nodeSums_ (the commit's shares, FL12's area vectors).
  // A node's area and share are its record's first four doubles (NodeSums).
  static_assert(offsetof(NodeSums, share) == 3 * sizeof(double));
  const double perArea = halves_.area > 0.0 ? 1.0 / halves_.area : 1.0;
  kernels::gatherTriangleRecords(faceRecords_.data(), nodeRecordsStart_.data(), nodeRecords_.data(),
                                 begin, end, perArea, nodeSums_.data()->area.data(),
                                 sizeof(NodeSums) / sizeof(double));
  const NodeSums* sums = nodeSums_.data();
  addNodeLoadsOf(out, begin, end, halves_.insideGauge, halves_.loadFactor, halves_.canopyVelocity,
                 true, [=](size_t i) -> const NodeSums& { return sums[i]; });
}

CanopyFlowTerm::Figures CanopyFlowTerm::figuresAt(const Eigen::VectorXd& x,
                                                  const Eigen::VectorXd& v) const {
  scratchTime_ = std::numeric_limits<double>::quiet_NaN();
  return evaluate(x, v, nullptr, 1.0, 0.0).figures;
}

double CanopyFlowTerm::AirBudget::rate(double M, const CanopyFlowTerm& term) const {
  const Model& m = *term.m_;
  const double rho = m.air.density, cd = term.def_->discharge;
  const double p = kernels::capturedAirPressure(M, volume, m.air.pressure, rho, term.def_->gamma) -
                   m.air.pressure;
  double q = kernels::orificeFlow(ram - p, mouthArea, cd, rho, dpLinear);
  for (const auto& [area, outside] : vents)
    q -= kernels::orificeFlow(p - outside, area, cd, rho, dpLinear);
  q -= cloth + dCloth * (p - insideGauge);
  return rho * q;
}

double CanopyFlowTerm::AirBudget::massAfter(double Mn, double dt,
                                            const CanopyFlowTerm& term) const {
  // FL9: implicit Euler, M = M_n + dt rate(M), solved exactly: the rate falls as M (and with it
  // the inside pressure) rises, so the residual is monotone and a bracket holds its one root
  // however stiff the orifice and cloth laws are (a linearised step overshoots an orifice's
  // square root by its whole distance). Inside the bracket, regula falsi with the Illinois
  // modification: the end that stays twice has its residual halved, so both ends close in
  // (bisection alone took about 50 evaluations of the rate, one pow each, a step; this 5 to 10,
  // the same root to 1e-15).
  auto residual = [&](double M) { return M - Mn - dt * rate(M, term); };
  double lo = Mn, hi = Mn, rlo = residual(lo), rhi = rlo;
  for (int i = 0; i < 200 && rlo > 0.0; ++i) rhi = rlo, hi = lo, lo *= 0.5, rlo = residual(lo);
  for (int i = 0; i < 200 && rhi < 0.0; ++i) rlo = rhi, lo = hi, hi *= 2.0, rhi = residual(hi);
  if (rlo == 0.0) return lo;
  if (rhi == 0.0) return hi;
  int kept = 0;  // the end that stayed at the last point: -1 lo, +1 hi
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    double mid = lo + (hi - lo) * (rlo / (rlo - rhi));
    if (!(mid > lo && mid < hi)) mid = 0.5 * (lo + hi);  // round-off at the ends
    const double r = residual(mid);
    if (r == 0.0) return mid;
    if (r < 0.0) {
      lo = mid, rlo = r;
      if (kept == 1) rhi *= 0.5;
      kept = 1;
    } else {
      hi = mid, rhi = r;
      if (kept == -1) rlo *= 0.5;
      kept = -1;
    }
  }
  return 0.5 * (lo + hi);
}

kernels::CanopyFlowState CanopyFlowTerm::flowState(const Eigen::VectorXd& v,
                                                   const InHalves* inHalves) const {
  const double rho = m_->air.density;
  // FL1: the relative flow of the canopy as a whole; the canopy's velocity the mean of its
  // nodes' by their shares of its area at the step's start: over two halves of the nodes (at
  // once where the system has two threads), their sums added in order.
  // By component in locals (an Eigen 3-vector accumulated through the loop was stored and
  // reloaded at every node).
  double part[2][3] = {};
  forBothHalves(inHalves, [&](int half) {
    const auto [begin, end] = halfOf(nodes_.size(), half);
    double cv[3] = {0.0, 0.0, 0.0};
    const double* vd = v.data();
    const double* share = committedShares_.data();
    const int* node = nodes_.data();
    for (size_t i = begin; i < end; ++i)
      for (int c = 0; c < 3; ++c) cv[c] += share[i] * vd[3 * node[i] + c];
    for (int c = 0; c < 3; ++c) part[half][c] = cv[c];
  });
  const Vec3 canopyVelocity(part[0][0] + part[1][0], part[0][1] + part[1][1],
                            part[0][2] + part[1][2]);
  const Vec3 U = m_->air.wind - canopyVelocity;
  const double speed = U.norm();
  kernels::CanopyFlowState s;
  s.canopyVelocity = canopyVelocity;
  s.flowDirection = speed > 0.0 ? Vec3(U / speed) : Vec3::Zero();
  s.dynamicPressure = 0.5 * rho * speed * speed;
  s.baseCoefficient = def_->baseCoefficient;
  s.normalDrag = 0.5 * rho * def_->normalDrag;
  return s;
}

double CanopyFlowTerm::startGauge() const {
  // FL6, FL9: the cloth's outflow linearised in the inside pressure about the step's start (its
  // mass in its volume).
  const Model& m = *m_;
  return kernels::capturedAirPressure(captured_, std::max(committedVolume_, 0.0) + volumeFloor_,
                                      m.air.pressure, m.air.density, def_->gamma) -
         m.air.pressure;
}

CanopyFlowTerm::Evaluation CanopyFlowTerm::evaluate(const Eigen::VectorXd& x,
                                                    const Eigen::VectorXd& v, SystemAssembler* out,
                                                    double loadFactor, double stepDt) const {
  const kernels::CanopyFlowState s = flowState(v);
  const double gauge = startGauge();
  // One pass over the faces for the volume, the cloth's outflow (FL6) and the loads that do not
  // depend on the inside pressure (FL8 is linear in it: its part, p_in a_i with a_i the share of
  // the area vectors at node i, is added per node once the captured air's update has found p_in).
  const bool permeable = def_->cloth.permeable();
  const FaceSums sums =
      out ? facePass<true>(x, v, s, gauge, permeable) : facePass<false>(x, v, s, gauge, permeable);
  return complete(x, sums, s, gauge, out, loadFactor, stepDt, out != nullptr, false);
}

CanopyFlowTerm::Evaluation CanopyFlowTerm::complete(const Eigen::VectorXd& x, const FaceSums& sums,
                                                    kernels::CanopyFlowState s, double gauge,
                                                    SystemAssembler* out, double loadFactor,
                                                    double stepDt, bool loads,
                                                    bool facesTaken) const {
  const Model& m = *m_;
  const double rho = m.air.density;
  const Vec3 canopyVelocity = s.canopyVelocity;
  Geometry g;
  g.volume = sums.volume, g.area = sums.area;
  closeOpenings(x, g);
  // FL2: the volume the gas law sees, with its floor.
  const double volume = std::max(g.volume, 0.0) + volumeFloor_;
  // FL4-FL5: the openings: the flow's ram pressure into the mouth, the vents' outside pressure.
  const double mouthArea = g.mouth.norm();
  const Vec3 axis = mouthArea > 0.0 ? Vec3(-g.mouth / mouthArea) : Vec3::Zero();
  const double into = std::max(0.0, s.flowDirection.dot(axis));
  Evaluation e;
  AirBudget& b = e.budget;
  b.volume = volume;
  b.ram = s.dynamicPressure * into * into;
  b.mouthArea = mouthArea;
  b.dpLinear = 1e-4 * s.dynamicPressure + 1e-12 * m.air.pressure;
  for (const Vec3& A : g.vents) {
    const double area = A.norm();
    if (!(area > 0.0)) continue;
    const double c = (A / area).dot(s.flowDirection);
    b.vents.emplace_back(
        area, s.dynamicPressure * kernels::outsidePressureCoefficient(c, s.baseCoefficient));
  }
  b.insideGauge = gauge;
  b.cloth = sums.cloth, b.dCloth = sums.dCloth;
  // FL3, FL9: the captured air at the end of a step (its update solved here), or as committed.
  e.capturedMass = stepDt > 0.0 ? b.massAfter(captured_, stepDt, *this) : captured_;
  s.insideGauge =
      kernels::capturedAirPressure(e.capturedMass, volume, m.air.pressure, rho, def_->gamma) -
      m.air.pressure;
  // FL8's inside pressure, and FL10, per node: here, or by the caller (finishTakenNodes).
  if (out)
    addNodeLoads(*out, 0, nodes_.size(), s.insideGauge, loadFactor, canopyVelocity, facesTaken);
  // What probes and the summary report of this evaluation.
  Figures& fig = e.figures;
  const double p = s.insideGauge;
  fig.volume = g.volume;
  fig.mouthArea = mouthArea;
  fig.insideGauge = p;
  fig.dynamicPressure = s.dynamicPressure;
  fig.inflow = kernels::orificeFlow(b.ram - p, mouthArea, def_->discharge, rho, b.dpLinear);
  for (const auto& [area, outside] : b.vents)
    fig.ventOutflow += kernels::orificeFlow(p - outside, area, def_->discharge, rho, b.dpLinear);
  fig.clothOutflow = b.cloth + b.dCloth * (p - b.insideGauge);
  fig.capturedMass = e.capturedMass;
  fig.flowDirection = s.flowDirection;
  fig.axis = axis;
  if (!loads) {  // the figures only (the reach is a pass over the nodes no load needs)
    const double r = reach(x);
    fig.projectedArea = std::numbers::pi * r * r;
  }
  return e;
}

void CanopyFlowTerm::addEnergy(const Eigen::VectorXd& /*x*/, const Eigen::VectorXd& v, double /*t*/,
                               EnergyBreakdown& e) const {
  for (size_t i = 0; i < nodes_.size(); ++i)
    e.kinetic += 0.5 * inertiaMass_ * committedShares_[i] * at(v, nodes_[i]).squaredNorm();
  e.supplied += supplied_;
}

double CanopyFlowTerm::frequencySquaredBound(const Eigen::VectorXd& x, double t,
                                             const std::vector<double>& nodalMass) const {
  // FL12: the gas spring K = (dp/dV) a a^T, a_i = the share of the area vectors at node i (the
  // force the pressure puts there), dp/dV = gamma p / V: its one nonzero frequency
  // omega^2 = (gamma p / V) sum_i |a_i|^2 / m_i. The faces of the step that ended at t serve
  // (the same positions); otherwise they are made here.
  const Model& m = *m_;
  double volume = scratchVolume_;
  if (!(scratchTime_ == t)) {
    // The per-node sums at x (in still air: no loads wanted, only the area vectors' shares).
    const FaceSums sums =
        facePass<true>(x, Eigen::VectorXd::Zero(x.size()), kernels::CanopyFlowState{}, 0.0, false);
    Geometry g;
    g.volume = sums.volume;
    closeOpenings(x, g);
    volume = g.volume;
    scratchTime_ = std::numeric_limits<double>::quiet_NaN();  // made without velocities
  }
  volume = std::max(volume, 0.0) + volumeFloor_;
  const double pAbs =
      kernels::capturedAirPressure(captured_, volume, m.air.pressure, m.air.density, def_->gamma);
  double sum = 0.0;
  for (size_t i = 0; i < nodes_.size(); ++i)
    if (nodalMass[nodes_[i]] > 0.0) sum += nodeSums_[i].area.squaredNorm() / nodalMass[nodes_[i]];
  return def_->gamma * pAbs / volume * sum;
}

void CanopyFlowTerm::commit(const CommitPoint& c) {
  // FL11-FL12: the next step's inertia is the air moving with the canopy at the step's end (the
  // apparent mass around it and the captured air inside); the kinetic energy the air it gained
  // has at the nodes' velocities came with it, not from a force's work.
  // The step's own evaluation was at c.x: its volume and shares serve.
  const bool evaluatedHere = c.dt > 0.0 && trialTime_ == c.t && scratchTime_ == c.t;
  // FL9: the captured air as the step's evaluation found it at the step's end.
  if (c.dt > 0.0 && trialTime_ == c.t) captured_ = trialMass_;
  const double before = inertiaMass_;
  const double volume = evaluatedHere ? scratchVolume_ : geometry(c.x).volume;
  inertiaMass_ = apparentMassOfVolume(volume) + captured_;
  massRate_ = c.dt > 0.0 ? (inertiaMass_ - before) / c.dt : 0.0;
  // The new shares committed, and the kinetic energy the nodes' apparent masses gain in changing
  // from m_a s_i to m_a' s_i' at the velocities they have, in one pass (in two halves, at once
  // where the system has two threads; their sums added in order).
  std::vector<double> made;
  if (!evaluatedHere) made = areaShares(c.x);
  const double* madeShares = evaluatedHere ? nullptr : made.data();
  double gained[2] = {0.0, 0.0};
  forBothHalves(c.inHalves, [&](int half) {
    const auto [begin, end] = halfOf(nodes_.size(), half);
    const double inertia = inertiaMass_;
    const NodeSums* sums = nodeSums_.data();
    double* nodeMass = nodeMass_.data();
    double* committed = committedShares_.data();
    double g = 0.0;
    for (size_t i = begin; i < end; ++i) {
      const double s = madeShares ? madeShares[i] : sums[i].share, m = inertia * s;
      if (c.v) g += (m - before * committed[i]) * at(*c.v, nodes_[i]).squaredNorm();
      committed[i] = s;
      nodeMass[i] = m;
    }
    gained[half] = g;
  });
  if (c.v) supplied_ += 0.5 * (gained[0] + gained[1]);
  committedVolume_ = volume;
}

void CanopyFlowTerm::save(History& h) const {
  h.put(captured_);
  h.put(inertiaMass_);
  h.put(massRate_);
  h.put(supplied_);
  h.put(committedShares_);
  h.put(committedVolume_);
}

void CanopyFlowTerm::load(HistoryReader& h) {
  const double captured = h.finiteReal(), inertia = h.finiteReal(), rate = h.finiteReal(),
               supplied = h.finiteReal();
  if (!(captured > 0.0)) h.fail("captured air mass not positive");
  if (!(inertia >= 0.0)) h.fail("apparent mass negative");
  std::vector<double> shares = h.reals(nodes_.size());
  for (double sh : shares)
    if (!(sh >= 0.0 && sh <= 1.0)) h.fail("a node's share of the canopy's area outside [0, 1]");
  const double volume = h.finiteReal();
  captured_ = captured, inertiaMass_ = inertia, massRate_ = rate, supplied_ = supplied;
  committedShares_ = std::move(shares);
  formNodeMass();
  committedVolume_ = volume;
}

}  // namespace chute
