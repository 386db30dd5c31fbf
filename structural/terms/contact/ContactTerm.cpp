#include "terms/contact/ContactTerm.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "kernels/StiffnessBound.hpp"
#include "terms/sliding/SlidingGroupState.hpp"

namespace chute {

using contact::BroadPhase;
using contact::ContactMesh;
using kernels::ContactPairKind;
using kernels::Vec3;

namespace {

// CT14: the share of a node's mass over the explicit step that the contact viscosities at the
// node may reach in all (damping and friction each).
constexpr double kExplicitViscosity = 0.05;

std::array<Vec3, 4> gather(const Eigen::VectorXd& x, const std::array<int, 4>& n) {
  return {x.segment<3>(3 * n[0]), x.segment<3>(3 * n[1]), x.segment<3>(3 * n[2]),
          x.segment<3>(3 * n[3])};
}

// Lumped mass of every node from what carries mass: membranes (rho t A0 / n), line elements
// (rho A L / 2 per end) and point masses. For CT6's damping coefficient and CT13's record only.
std::vector<double> lumpedNodeMass(const Model& m) {
  std::vector<double> mass(m.numNodes(), 0.0);
  for (const auto& e : m.membranes) {
    const auto& mat = m.membraneMaterials[e.material];
    const auto X = [&](int i) { return m.X[e.nodes[i]]; };
    const double area = e.numNodes == 3 ? 0.5 * (X(1) - X(0)).cross(X(2) - X(0)).norm()
                                        : 0.5 * (X(2) - X(0)).cross(X(3) - X(1)).norm();
    for (int i = 0; i < e.numNodes; ++i)
      mass[e.nodes[i]] += mat.density * mat.thickness * area / e.numNodes;
  }
  for (const auto& c : m.cables) {
    const auto& mat = m.materials[c.material];
    for (int n : {c.a, c.b}) mass[n] += 0.5 * mat.density * mat.area * c.L;
  }
  for (const auto& g : m.groups) {
    const auto& mat = m.materials[g.material];
    for (int k = 0; k < g.numElements(); ++k)
      for (int n : {g.chain[k], g.chain[k + 1]})
        mass[n] += 0.5 * mat.density * mat.area * g.refLength[k];
  }
  for (int n = 0; n < m.numNodes(); ++n) mass[n] += m.pointMass[n];
  return mass;
}

// The nodal stiffness bound of EX5-EX6 on the reference geometry, every node counted free: the
// membranes' (EX6m at unit stretch), the cables' and the sliding chains' elements (E A / L, a
// slider's element as a whole).
std::vector<double> referenceStiffnessBound(const Model& m) {
  std::vector<double> S(m.numNodes(), 0.0);
  const std::vector<char> free(m.numNodes(), 1);
  for (const auto& e : m.membranes) {
    const double shrink = 1.0 / (1.0 + m.membraneSets[e.set].prestrain);
    std::array<Vec3, 4> X;
    X.fill(Vec3::Zero());
    for (int i = 0; i < e.numNodes; ++i) X[i] = shrink * m.X[e.nodes[i]];
    const auto ref =
        kernels::membraneBoundReference(X, e.numNodes, m.membraneMaterials[e.material]);
    for (int i = 0; i < e.numNodes; ++i) S[e.nodes[i]] += ref.perNode;
  }
  for (const auto& c : m.cables)
    kernels::addLineBound(c.a, c.b, kernels::lineStiffness(m.materials[c.material], c.L), free, S);
  for (const auto& g : m.groups)
    for (int k = 0; k < g.numElements(); ++k)
      kernels::addLineBound(g.chain[k], g.chain[k + 1],
                            kernels::lineStiffness(m.materials[g.material], g.refLength[k]), free,
                            S);
  return S;
}

}  // namespace

ContactTerm::ContactTerm(const Model& m, std::vector<const SlidingGroupState*> groups)
    : m_(&m), groups_(std::move(groups)) {
  const ContactDef& def = m.contact;
  mesh_ = std::make_unique<ContactMesh>(m, def);
  broadPhase_ = std::make_unique<BroadPhase>(*mesh_, def.thickness, def.skin);
  // CT9: k_i = kappa m_i / dt_i^2 with dt_i = 2 sqrt(m_i / S_i) the node's own stable step (EX5),
  // that is kappa S_i / 4, from the reference geometry.
  const std::vector<double> S = referenceStiffnessBound(m);
  nodeStiffness_.assign(m.numNodes(), 0.0);
  for (int n : mesh_->nodes()) nodeStiffness_[n] = 0.25 * def.stiffnessScale * S[n];
  nodeMass_ = lumpedNodeMass(m);
  moved_.assign(m.numNodes(), 0.0);
  Eigen::VectorXd x0(3 * m.numNodes());
  for (int n = 0; n < m.numNodes(); ++n) x0.segment<3>(3 * n) = m.X[n] + m.u0[n];
  startGapsAt(x0);
}

ContactTerm::~ContactTerm() = default;

void ContactTerm::slidersNow(std::vector<int>& s) const {
  mesh_->slidersOn(groups_, s);
}

// CT10: the near list's skin, a share of the candidate lists'.
constexpr double kNearSkinShare = 0.25;

double ContactTerm::nearSkin() const {
  return kNearSkinShare * m_->contact.skin;
}

// How far each node of the mesh has moved since the near list was made, less the mesh's common
// shift since (CT10; into `moved`), and whether both lists still cover x: no node farther than
// the near skin's half from where the near list saw it, nor than the skin's half from the
// candidate lists' build (its motion since that build, less the shift since, is at most its
// motion up to the near list's less that shift plus since), the same sliders.
bool ContactTerm::covered(const Eigen::VectorXd& x, const std::vector<int>& sliders,
                          std::vector<double>& moved) const {
  if (!broadPhase_->built() || sliders != broadPhase_->state().sliders || nearAt_.size() == 0)
    return false;
  const auto& nodes = mesh_->nodes();
  const Vec3 shift = contact::commonShift(nodes, x, nearAt_);
  double near = 0.0, build = 0.0;
  for (size_t i = 0; i < nodes.size(); ++i) {
    const double d = (x.segment<3>(3 * nodes[i]) - nearAt_.segment<3>(3 * i) - shift).norm();
    moved[nodes[i]] = d;
    near = std::max(near, d);
    build = std::max(build, d + nearFromBuild_[i]);
  }
  return near <= 0.5 * nearSkin() && build <= 0.5 * m_->contact.skin;
}

void ContactTerm::refresh(const Eigen::VectorXd& x) {
  std::vector<int>& sliders = slidersScratch_;
  slidersNow(sliders);
  if (covered(x, sliders, moved_)) return;
  if (!broadPhase_->covers(x, sliders)) {
    broadPhase_->build(x, sliders);
    couplingsChanged_ = true;
  }
  nearList(x);
}

// CT10: the candidates of the last build with their distance at it, less those farther than
// dHat + skin there: while no node moves more than skin/2 from the build (less the common
// shift), those cannot come within dHat. Depends on the build's positions alone.
void ContactTerm::candidatesAtBuild() {
  const Eigen::VectorXd xb = unpacked(broadPhase_->state().positions);
  const double reach = m_->contact.thickness + m_->contact.skin;
  candidates_.clear();
  forEachPair(*broadPhase_, [&](const Pair& pair) {
    const auto xs = gather(xb, pair.nodes);
    if (kernels::boxesApart(pair.kind == ContactPairKind::PointTriangle, xs, reach)) return;
    const double d2 = kernels::pairSquaredDistance(pair.kind, xs);
    if (d2 <= reach * reach)
      candidates_.push_back({pair, std::sqrt(d2), m_->contact.thickness, 0.0});
  });
  candidatesBuild_ = broadPhase_->builds();
}

// CT10: the candidates within dHat + the near skin at positions x, with their distance there.
// While no node has moved more than half the near skin since, no other candidate can come
// within dHat; each evaluation takes the near pairs' nodes' motion since x off their distance.
// A candidate whose distance at the build, less its nodes' motion since, is beyond reach is
// left without computing its distance at x.
void ContactTerm::nearList(const Eigen::VectorXd& x) {
  ++nearLists_;
  if (candidatesBuild_ != broadPhase_->builds()) candidatesAtBuild();
  const auto& nodes = mesh_->nodes();
  const auto& xb = broadPhase_->state().positions;
  // Each node's motion from the build to here less the mesh's common shift between them (CT10).
  const Vec3 shift = contact::commonShift(nodes, x, xb);
  nearAt_.resize(3 * static_cast<long>(nodes.size()));
  nearFromBuild_.resize(nodes.size());
  for (size_t i = 0; i < nodes.size(); ++i) {
    nearAt_.segment<3>(3 * i) = x.segment<3>(3 * nodes[i]);
    nearFromBuild_[i] = (nearAt_.segment<3>(3 * i) - xb.segment<3>(3 * i) - shift).norm();
    moved_[nodes[i]] = nearFromBuild_[i];  // for the filter below, then 0
  }
  const double reach = m_->contact.thickness + nearSkin();
  near_.clear();
  forEachNearOf(candidates_, moved_, reach, [&](const Pair& pair, double, double) {
    const auto xs = gather(x, pair.nodes);
    if (kernels::boxesApart(pair.kind == ContactPairKind::PointTriangle, xs, reach)) return;
    const double d2 = kernels::pairSquaredDistance(pair.kind, xs);
    if (d2 <= reach * reach)
      near_.push_back(
          {pair, std::sqrt(d2), m_->contact.thickness, mollifierThreshold(pair.kind, xs)});
  });
  for (int n : nodes) moved_[n] = 0.0;
  nearThicknesses();
}

// CT15: each near pair's own thickness, from the sorted table (both lists in key order).
void ContactTerm::nearThicknesses() {
  auto g = startGaps_.begin();
  for (auto& n : near_) {
    const std::int64_t k = n.pair.key();
    while (g != startGaps_.end() && g->first < k) ++g;
    n.thickness = g != startGaps_.end() && g->first == k ? g->second : m_->contact.thickness;
  }
}

void ContactTerm::raiseStartGap(const Pair& p, double d) {
  const auto it =
      std::lower_bound(trialStartGaps_.begin(), trialStartGaps_.end(), Thickness{p.key(), -1.0});
  if (it == trialStartGaps_.end() || it->first != p.key()) return;
  it->second = std::max(it->second, std::min(d, m_->contact.thickness));
}

double ContactTerm::thicknessOf(const Pair& p) const {
  const auto it = std::lower_bound(startGaps_.begin(), startGaps_.end(), Thickness{p.key(), -1.0});
  return it != startGaps_.end() && it->first == p.key() ? it->second : m_->contact.thickness;
}

// CT15: the pairs within dHat at the start positions x0 (a packed or folded start whose layers
// are closer than the thickness) start with their distance as their thickness: no force at the
// start, a contact that resists any further approach.
void ContactTerm::startGapsAt(const Eigen::VectorXd& x0) {
  startGaps_.clear();
  std::vector<int> sliders;
  slidersNow(sliders);
  BroadPhase own(*mesh_, m_->contact.thickness, 0.0);
  own.build(x0, sliders);
  const double dHat = m_->contact.thickness;
  forEachPair(own, [&](const Pair& pair) {
    const auto xs = gather(x0, pair.nodes);
    if (kernels::boxesApart(pair.kind == ContactPairKind::PointTriangle, xs, dHat)) return;
    const double d2 = kernels::pairSquaredDistance(pair.kind, xs);
    if (d2 < dHat * dHat) startGaps_.push_back({pair.key(), std::sqrt(d2)});
  });
  std::sort(startGaps_.begin(), startGaps_.end());
  trialStartGaps_ = startGaps_;
}

template <class F>
void ContactTerm::forEachNear(const std::vector<double>& moved, double reach, F&& f) const {
  forEachNearOf(near_, moved, reach, std::forward<F>(f));
}

// f(pair, thickness, CT5 threshold) for the pairs of `list` whose distance there, less the motion
// of their nodes since (`moved`, per node of the model), is below reach.
template <class F>
void ContactTerm::forEachNearOf(const std::vector<Near>& list, const std::vector<double>& moved,
                                double reach, F&& f) const {
  for (const auto& n : list) {
    const auto& k = n.pair.nodes;
    double first = moved[k[0]], second;
    if (n.pair.kind == ContactPairKind::PointTriangle) {
      second = std::max({moved[k[1]], moved[k[2]], moved[k[3]]});
    } else {
      first = std::max(first, moved[k[1]]);
      second = std::max(moved[k[2]], moved[k[3]]);
    }
    if (n.distance - first - second < reach) f(n.pair, n.thickness, n.mollifier);
  }
}

template <class F>
void ContactTerm::forEachPair(const BroadPhase& bp, F&& f) const {
  const ContactMesh& m = *mesh_;
  for (const auto& c : bp.pointTriangle()) {
    const auto& t = m.triangles()[c.triangle];
    f(Pair{ContactPairKind::PointTriangle,
           {m.points()[c.point], t[0], t[1], t[2]},
           0,
           c.point,
           c.triangle});
  }
  for (const auto& c : bp.edgeEdge()) {
    const auto& a = m.edges()[c.first];
    const auto& b = m.edges()[c.second];
    f(Pair{ContactPairKind::EdgeEdge, {a[0], a[1], b[0], b[1]}, 1, c.first, c.second});
  }
  const auto& sliders = bp.state().sliders;
  for (const auto& c : bp.lineEdge()) {
    const auto& l = m.lines()[c.first];
    const auto& e = m.edges()[c.second];
    const int s = sliders[c.first];
    if (s < 0) {
      f(Pair{ContactPairKind::EdgeEdge, {l.a, l.b, e[0], e[1]}, 2, c.first, c.second});
      continue;
    }
    // Bent at its slider: two segments, each excluded on its own when it shares a node (CT11).
    if (!ContactMesh::adjacent({l.a, s}, e))
      f(Pair{ContactPairKind::EdgeEdge, {l.a, s, e[0], e[1]}, 2, c.first, c.second, 1});
    if (!ContactMesh::adjacent({s, l.b}, e))
      f(Pair{ContactPairKind::EdgeEdge, {s, l.b, e[0], e[1]}, 2, c.first, c.second, 2});
  }
}

// CT9: the softest free node of the pair sets its stiffness (a fixed node's does not matter).
double ContactTerm::pairStiffness(const std::array<int, 4>& n) const {
  double k = std::numeric_limits<double>::infinity();
  for (int i : n)
    if (mesh_->free(i) && nodeStiffness_[i] > 0.0) k = std::min(k, nodeStiffness_[i]);
  return std::isfinite(k) ? k : 0.0;
}

// The effective mass of the pair's relative motion: each primitive's mean nodal mass (the point's,
// the edge's or the triangle's), in series; a primitive that cannot move (all its nodes fixed)
// does not count. Independent of the positions, so that CT6's damping coefficient has no position
// derivative of its own.
double ContactTerm::pairMass(ContactPairKind kind, const std::array<int, 4>& n) const {
  const int firstSide = kind == ContactPairKind::PointTriangle ? 1 : 2;
  double side[2] = {0.0, 0.0};
  bool moves[2] = {false, false};
  for (int i = 0; i < 4; ++i) {
    const int s = i < firstSide ? 0 : 1;
    side[s] += nodeMass_[n[i]] / (s == 0 ? firstSide : 4 - firstSide);
    moves[s] = moves[s] || mesh_->free(n[i]);
  }
  if (!moves[0]) return side[1];
  if (!moves[1]) return side[0];
  const double sum = side[0] + side[1];
  return sum > 0.0 ? side[0] * side[1] / sum : 0.0;
}

// CT5: the mollifier's threshold on the edges as they are at xs (the near list's positions).
double ContactTerm::mollifierThreshold(ContactPairKind kind, const std::array<Vec3, 4>& xs) {
  if (kind != ContactPairKind::EdgeEdge) return 0.0;
  return kernels::mollifierThreshold(xs[1] - xs[0], xs[3] - xs[2]);
}

void ContactTerm::addCouplings(std::vector<std::vector<int>>& cliques) const {
  if (!broadPhase_->built()) return;
  const ContactMesh& m = *mesh_;
  for (const auto& c : broadPhase_->pointTriangle()) {
    const auto& t = m.triangles()[c.triangle];
    cliques.push_back({m.points()[c.point], t[0], t[1], t[2]});
  }
  for (const auto& c : broadPhase_->edgeEdge()) {
    const auto& a = m.edges()[c.first];
    const auto& b = m.edges()[c.second];
    cliques.push_back({a[0], a[1], b[0], b[1]});
  }
  const auto& sliders = broadPhase_->state().sliders;
  for (const auto& c : broadPhase_->lineEdge()) {
    const auto& l = m.lines()[c.first];
    const auto& e = m.edges()[c.second];
    std::vector<int> clique{l.a, l.b, e[0], e[1]};
    if (sliders[c.first] >= 0) clique.push_back(sliders[c.first]);
    cliques.push_back(clique);
  }
  for (const auto& l : lag_) cliques.emplace_back(l.nodes.begin(), l.nodes.end());
}

bool ContactTerm::updateCouplings(const Eigen::VectorXd& x) {
  refresh(x);
  const bool changed = couplingsChanged_;
  couplingsChanged_ = false;
  return changed;
}

// Whether every lagged pair is among the current candidates (its couplings are then in the
// pattern already).
bool ContactTerm::lagCovered(const std::vector<Lag>& lag) const {
  const BroadPhase& bp = *broadPhase_;
  for (const auto& l : lag) {
    bool found = false;
    if (l.list == 0)
      found = std::binary_search(bp.pointTriangle().begin(), bp.pointTriangle().end(),
                                 contact::PointTrianglePair{l.first, l.second});
    else
      found = std::binary_search(l.list == 1 ? bp.edgeEdge().begin() : bp.lineEdge().begin(),
                                 l.list == 1 ? bp.edgeEdge().end() : bp.lineEdge().end(),
                                 contact::EdgePair{l.first, l.second});
    if (!found) return false;
  }
  return true;
}

void ContactTerm::assemble(const EvalPoint& p, SystemAssembler& out) {
  if (p.xStart) throw std::logic_error("contact: the energy-momentum integrator is not supported");
  if (p.inertiaOnly) return;  // no mass
  if (!p.couplingsUpdated) refresh(p.x);
  // The builds are counted on an evaluation of the forces (load factor > 0), not on the lumped
  // mass's (EvalPoint::inertiaOf), whose assembler's counters are not the run's.
  if (p.loadFactor > 0.0 && broadPhase_->builds() != buildsSeen_) {
    out.work().contactLists += broadPhase_->builds() - buildsSeen_;
    buildsSeen_ = broadPhase_->builds();
  }
  const ContactDef& def = m_->contact;
  const bool wantJ = out.wantMatrix();
  // A step's evaluation (not output's, the mass's or the energy balance's): it sets the lag of
  // the friction of the next step and the record.
  const bool stepEvaluation = p.dt > 0.0 && p.inertia;
  if (stepEvaluation) trialLag_.clear();
  long active = 0;
  const double dHat = def.thickness;
  // CT14: an explicit step integrates a viscosity c at a node of mass m stably while c dt / m is
  // well below 1, and it uses up the stable step's margin as it grows: the viscosities of the
  // pairs at a node (damping, friction's stick) are kept to kExplicitViscosity m / dt in all,
  // shared over the pairs in contact there at the step's start (their lag).
  if (p.explicitStep > 0.0) {
    lagShare_.assign(m_->numNodes(), 0.0);
    for (const auto& l : lag_)
      for (int i = 0; i < 4; ++i) lagShare_[l.nodes[i]] += std::abs(l.lag.weight[i]);
  }
  const auto share = [&](const std::array<int, 4>& nodes) {
    double most = 1.0;
    for (int n : nodes) most = std::max(most, lagShare_[n]);
    return most;
  };
  forEachNear(moved_, dHat, [&](const Pair& pair, double own, double epsX) {
    const auto x = gather(p.x, pair.nodes);
    ++out.work().contact;
    const double d2 = kernels::pairSquaredDistance(pair.kind, x);
    if (!(d2 < dHat * dHat)) return;
    if (!(d2 < own * own)) {
      // CT15: a pair that started closer than dHat and is now farther than its own thickness:
      // its thickness follows it back towards dHat (it has no energy now, nor after).
      if (stepEvaluation && own < dHat) raiseStartGap(pair, std::sqrt(d2));
      return;
    }
    const double k = pairStiffness(pair.nodes);
    if (!(k > 0.0)) return;
    ++active;
    const auto v = gather(p.v, pair.nodes);
    const double mass = pairMass(pair.kind, pair.nodes);
    kernels::ContactLaw law{k, own, 0.0};
    if (def.dampingRatio > 0.0 && p.inertia) {
      law.damping = 2.0 * def.dampingRatio * std::sqrt(k * mass);  // CT6
      if (p.explicitStep > 0.0)
        law.damping =
            std::min(law.damping, kExplicitViscosity * mass / (p.explicitStep * share(pair.nodes)));
    }
    const auto r = kernels::contactPair(pair.kind, x, v, law, epsX, wantJ);
    if (stepEvaluation && r.active) {
      // CT13: how far the pair closes in one step, and its approach's energy against CT4's.
      const kernels::Distance& d = r.distance;
      double ddot = 0.0;
      for (int i = 0; i < 4; ++i) ddot += d.weight[i] * d.normal.dot(v[i]);
      if (ddot < 0.0) {
        record_.largestApproachPerStep =
            std::max(record_.largestApproachPerStep, -ddot * p.dt / dHat);
        record_.largestApproachEnergy =
            std::max(record_.largestApproachEnergy, mass * ddot * ddot / (k * own * own));
      }
    }
    if (!r.active) return;
    if (stepEvaluation) {
      record_.closest = std::min(record_.closest, r.distance.value / dHat);
      if (def.friction > 0.0 || def.dampingRatio > 0.0)
        trialLag_.push_back(
            {pair.kind, pair.nodes, pair.list, pair.first, pair.second,
             kernels::FrictionLag{r.distance.weight, r.distance.normal, r.normalForce}});
    }
    if (!wantJ) {
      out.add<4>(pair.nodes, r.residual, nullptr);
      return;
    }
    const kernels::Mat12 J = p.cx * r.dPosition + p.cv * r.dVelocity;
    out.add<4>(pair.nodes, r.residual, &J);
  });
  if (stepEvaluation) record_.largestActive = std::max(record_.largestActive, active);
  // CT7: friction of the pairs in contact at the step's start, with their lagged normal force,
  // normal and weights. In an explicit step eps_v is raised so that the stick's viscosity
  // 2 mu lambda / eps_v is within CT14's share.
  if (def.friction > 0.0 && p.inertia) {
    for (const auto& l : lag_) {
      const auto v = gather(p.v, l.nodes);
      double epsV = def.slipSpeed;
      if (p.explicitStep > 0.0) {
        const double mass = pairMass(l.kind, l.nodes);
        if (mass > 0.0)
          epsV = std::max(epsV, 2.0 * def.friction * l.lag.normalForce * p.explicitStep *
                                    share(l.nodes) / (kExplicitViscosity * mass));
      }
      const auto f = kernels::contactFriction(l.lag, v, def.friction, epsV, wantJ);
      if (!wantJ) {
        out.add<4>(l.nodes, f.residual, nullptr);
        continue;
      }
      const kernels::Mat12 J = p.cv * f.dVelocity;
      out.add<4>(l.nodes, f.residual, &J);
    }
  }
}

// f(pair, thickness, CT5 threshold) for every pair that may be within `reach` at x: the near
// list's, less those its motion since the build cannot have brought that close; at positions the
// build does not cover (a state never assembled), every candidate of a build of their own.
template <class F>
void ContactTerm::forEachPairWithin(const Eigen::VectorXd& x, double reach, F&& f) const {
  std::vector<int> sliders;
  slidersNow(sliders);
  std::vector<double> moved(m_->numNodes(), 0.0);
  if (covered(x, sliders, moved)) {
    forEachNear(moved, reach, f);
    return;
  }
  BroadPhase own(*mesh_, m_->contact.thickness, m_->contact.skin);
  own.build(x, sliders);
  forEachPair(own, [&](const Pair& pair) {
    f(pair, thicknessOf(pair), mollifierThreshold(pair.kind, gather(x, pair.nodes)));
  });
}

void ContactTerm::addEnergy(const Eigen::VectorXd& x, const Eigen::VectorXd&, double,
                            EnergyBreakdown& e) const {
  const double dHat = m_->contact.thickness;
  const std::array<Vec3, 4> still{Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  forEachPairWithin(x, dHat, [&](const Pair& pair, double own, double epsX) {
    const auto xs = gather(x, pair.nodes);
    if (kernels::boxesApart(pair.kind == ContactPairKind::PointTriangle, xs, own)) return;
    if (!(kernels::pairSquaredDistance(pair.kind, xs) < own * own)) return;
    const double k = pairStiffness(pair.nodes);
    if (!(k > 0.0)) return;
    const auto r = kernels::contactPair(pair.kind, xs, still, {k, own, 0.0}, epsX, false);
    if (r.active) e.strain += r.energy;
  });
}

void ContactTerm::addStiffnessBound(const Eigen::VectorXd& x, double, const std::vector<char>&,
                                    std::vector<double>& S) const {
  const double reach = m_->contact.thickness;
  forEachPairWithin(x, reach, [&](const Pair& pair, double own, double) {
    const auto xs = gather(x, pair.nodes);
    if (kernels::boxesApart(pair.kind == ContactPairKind::PointTriangle, xs, own)) return;
    if (!(kernels::pairSquaredDistance(pair.kind, xs) < own * own)) return;
    const double k = pairStiffness(pair.nodes);
    if (!(k > 0.0)) return;
    const auto d = kernels::pairDistance(pair.kind, xs, false);
    // K = k grad d grad d^T with grad d = (w_i n)_i: row sums k |w_i| sum_j |w_j| = 2 k |w_i|.
    for (int i = 0; i < 4; ++i) S[pair.nodes[i]] += 2.0 * k * std::abs(d.weight[i]);
  });
}

void ContactTerm::commit(const CommitPoint&) {
  lag_ = trialLag_;
  if (trialStartGaps_ != startGaps_) {
    startGaps_ = trialStartGaps_;
    nearThicknesses();
  }
  if (!lagCovered(lag_)) couplingsChanged_ = true;
  // The lists as this step left them (copied only when a near list was made since).
  if (nearLists_ != committedNearLists_) {
    committedBuild_ = broadPhase_->state();
    committedNearAt_ = nearAt_;
    committedNearLists_ = nearLists_;
  }
  record_.builds = broadPhase_->builds();
  record_.treeBuilds = broadPhase_->treeBuilds();
  record_.candidates =
      static_cast<long>(broadPhase_->pointTriangle().size() + broadPhase_->edgeEdge().size() +
                        broadPhase_->lineEdge().size());
}

void ContactTerm::revert() {
  trialLag_ = lag_;
  trialStartGaps_ = startGaps_;
  if (committedBuild_.positions.size() == 0) return;  // nothing committed yet: keep the lists
  if (nearLists_ == committedNearLists_) return;      // the lists are the committed ones
  const auto& trial = broadPhase_->state();
  const bool sameBuild = trial.sliders == committedBuild_.sliders &&
                         trial.positions.size() == committedBuild_.positions.size() &&
                         trial.positions == committedBuild_.positions;
  if (!sameBuild) {
    broadPhase_->build(committedBuild_);
    couplingsChanged_ = true;
  }
  nearList(unpacked(committedNearAt_));
  committedNearLists_ = nearLists_;
}

// Positions over all nodes of the model from the mesh's nodes' (zero elsewhere).
Eigen::VectorXd ContactTerm::unpacked(const Eigen::VectorXd& packed) const {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(3 * static_cast<long>(m_->numNodes()));
  const auto& nodes = mesh_->nodes();
  for (size_t i = 0; i < nodes.size(); ++i) x.segment<3>(3 * nodes[i]) = packed.segment<3>(3 * i);
  return x;
}

// History: the build the candidate lists come from (its positions and sliders) and the lagged
// friction of the pairs in contact at the last commit.
void ContactTerm::save(History& h) const {
  h.put(committedBuild_.positions);
  h.put(committedBuild_.sliders);
  h.put(committedNearAt_);
  h.put(static_cast<int>(lag_.size()));
  std::vector<int> ints;
  std::vector<double> reals;
  for (const auto& l : lag_) {
    ints.insert(ints.end(), l.nodes.begin(), l.nodes.end());
    ints.insert(ints.end(), {l.list, l.first, l.second});
    reals.insert(reals.end(), l.lag.weight.begin(), l.lag.weight.end());
    reals.insert(reals.end(), l.lag.normal.data(), l.lag.normal.data() + 3);
    reals.push_back(l.lag.normalForce);
  }
  h.put(ints);
  h.put(reals);
  // CT15: the pairs' own thicknesses.
  h.put(static_cast<int>(startGaps_.size()));
  for (const auto& [key, thickness] : startGaps_) {
    h.put(static_cast<std::int64_t>(key));
    h.put(thickness);
  }
}

void ContactTerm::load(HistoryReader& h) {
  const long nodes = static_cast<long>(mesh_->nodes().size());
  const Eigen::VectorXd positions = h.vector(-1);
  if (positions.size() != 0 && positions.size() != 3 * nodes)
    h.fail("contact build positions for " + std::to_string(positions.size() / 3) + " nodes, " +
           std::to_string(nodes) + " take part");
  if (!positions.allFinite()) h.fail("contact build positions not finite");
  const int numNodes = m_->numNodes();
  const auto sliders = h.ints(positions.size() ? mesh_->lines().size() : 0, -1, numNodes - 1);
  const Eigen::VectorXd nearAt = h.vector(positions.size());
  if (!nearAt.allFinite()) h.fail("contact near-list positions not finite");
  const int count = static_cast<int>(h.integer(0, 1L << 30));
  const auto ints = h.ints(7 * static_cast<size_t>(count), 0, 1 << 30);
  const auto reals = h.reals(8 * static_cast<size_t>(count));
  const int listSize[3] = {static_cast<int>(mesh_->points().size()),
                           static_cast<int>(mesh_->edges().size()),
                           static_cast<int>(mesh_->lines().size())};
  const int secondSize[3] = {static_cast<int>(mesh_->triangles().size()),
                             static_cast<int>(mesh_->edges().size()),
                             static_cast<int>(mesh_->edges().size())};
  std::vector<Lag> lag(count);
  for (int k = 0; k < count; ++k) {
    Lag& l = lag[k];
    for (int i = 0; i < 4; ++i) {
      l.nodes[i] = ints[7 * k + i];
      if (l.nodes[i] >= numNodes) h.fail("contact: a lagged pair's node is out of range");
      l.lag.weight[i] = reals[8 * k + i];
    }
    l.list = ints[7 * k + 4], l.first = ints[7 * k + 5], l.second = ints[7 * k + 6];
    if (l.list > 2 || l.first >= listSize[l.list] || l.second >= secondSize[l.list])
      h.fail("contact: a lagged pair's candidate is out of range");
    l.kind = l.list == 0 ? ContactPairKind::PointTriangle : ContactPairKind::EdgeEdge;
    l.lag.normal = Vec3(reals[8 * k + 4], reals[8 * k + 5], reals[8 * k + 6]);
    l.lag.normalForce = reals[8 * k + 7];
    const double wsum = std::abs(l.lag.weight[0]) + std::abs(l.lag.weight[1]) +
                        std::abs(l.lag.weight[2]) + std::abs(l.lag.weight[3]);
    if (!std::isfinite(l.lag.normalForce) || l.lag.normalForce < 0.0 || !l.lag.normal.allFinite() ||
        !(wsum <= 2.0 + 1e-9))
      h.fail("contact: a lagged pair's weights, normal or normal force are out of range");
  }
  const int gaps = static_cast<int>(h.integer(0, 1L << 30));
  std::vector<Thickness> startGaps(gaps);
  for (auto& [key, thickness] : startGaps) {
    key = h.integer(0, std::numeric_limits<std::int64_t>::max());
    thickness = h.real();
    if (!(thickness >= 0.0 && thickness <= m_->contact.thickness))
      h.fail("contact: a pair's own thickness is outside [0, thickness]");
  }
  if (!std::is_sorted(startGaps.begin(), startGaps.end()))
    h.fail("contact: the pairs' own thicknesses are not in order");
  committedBuild_.positions = positions;
  committedBuild_.sliders.assign(sliders.begin(), sliders.end());
  committedNearAt_ = nearAt;
  startGaps_ = trialStartGaps_ = startGaps;
  lag_ = trialLag_ = lag;
  if (positions.size() != 0) {
    broadPhase_->build(committedBuild_);
    nearList(unpacked(committedNearAt_));
  }
  committedNearLists_ = nearLists_;
  couplingsChanged_ = true;
}

}  // namespace chute
