#include "terms/sliding/SlidingGroupTerm.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <stdexcept>

#include "kernels/CableKernel.hpp"
#include "kernels/PolylineDiscreteGradient.hpp"
#include "kernels/SliderFriction.hpp"
#include "kernels/SliderWhirlDamping.hpp"
#include "kernels/SlidingCableKernel.hpp"
#include "kernels/SlidingDiscreteGradient.hpp"
#include "kernels/StiffnessBound.hpp"
#include "terms/LineDragFusion.hpp"
#include "terms/LineElementAssembly.hpp"

namespace chute {

using kernels::Mat9;
using kernels::Vec9;
using line_assembly::addCableInertia;
using line_assembly::addSlackTangent;
using line_assembly::assembleCable;
using line_assembly::cableEnergy;
using line_assembly::gather3;
using line_assembly::pos;

// ---- SlidingGroupTerm ------------------------------------------------------------------------
SlidingGroupTerm::SlidingGroupTerm(const Model& m, int group, SliderSearch search)
    : m_(&m), state_(m.groups[group]), search_(search) {
  lanes_ = kernels::useAvx2();  // the baseline copy of the lanes is slower than one by one
  const auto& sliders = m.groups[group].sliders;
  for (size_t s = 0; s < sliders.size(); ++s) {
    const auto& c = m.constraint[sliders[s]];
    const bool moves =
        c.velocity.squaredNorm() > 0.0 || (c.amplitude.squaredNorm() > 0.0 && c.frequency > 0.0);
    state_.setDriven(static_cast<int>(s), c.fixed[0] && c.fixed[1] && c.fixed[2] && moves);
  }
  // EM12's conditions: massless, frictionless, more than one element, and inner chain nodes that
  // are free, without mass and in no other element or load.
  const auto& g = m.groups[group];
  condensable_ = m.materials[g.material].density == 0.0 && g.numElements() > 1;
  for (size_t s = 0; s < g.sliders.size(); ++s)
    condensable_ = condensable_ && !g.frictionOf(static_cast<int>(s));
  if (condensable_) {
    std::vector<int> uses(m.numNodes(), 0);
    for (const auto& c : m.cables) ++uses[c.a], ++uses[c.b];
    for (const auto& e : m.membranes)
      for (int i = 0; i < e.numNodes; ++i) ++uses[e.nodes[i]];
    for (const auto& other : m.groups) {
      for (int n : other.chain) ++uses[n];
      for (int n : other.sliders) ++uses[n];
    }
    for (const auto& d : m.drags)
      if (d.lineSet == g.set)
        condensable_ = false;
      else
        for (const auto& e : d.edges) ++uses[e[0]], ++uses[e[1]];
    for (int k = 1; k < g.numElements() && condensable_; ++k) {
      const int n = g.chain[k];
      const auto& c = m.constraint[n];
      condensable_ =
          uses[n] == 1 && !(m.pointMass[n] > 0.0) && !c.fixed[0] && !c.fixed[1] && !c.fixed[2];
    }
  }
}

void SlidingGroupTerm::addCouplings(std::vector<std::vector<int>>& cliques) const {
  const auto& g = state_.def();
  // Any element may become active for any slider: cover slider x every chain node up front so a
  // change of active element never needs a new symbolic analysis.
  for (int k = 0; k < g.numElements(); ++k) cliques.push_back({g.chain[k], g.chain[k + 1]});
  for (int s : g.sliders)
    for (int k = 0; k < g.numElements(); ++k) cliques.push_back({g.chain[k], g.chain[k + 1], s});
  if (condensable_) {
    // EM12: the ends and the sliders all couple, and every inner node to them.
    std::vector<int> path = {g.chain.front(), g.chain.back()};
    path.insert(path.end(), g.sliders.begin(), g.sliders.end());
    cliques.push_back(path);
    for (int k = 1; k < g.numElements(); ++k) {
      auto with = path;
      with.push_back(g.chain[k]);
      cliques.push_back(with);
    }
  }
}

std::vector<int> SlidingGroupTerm::chainPath(const Eigen::VectorXd& x) const {
  const auto& g = state_.def();
  std::vector<std::pair<double, int>> order;
  for (size_t s = 0; s < g.sliders.size(); ++s)
    order.emplace_back(state_.materialCoordinate(static_cast<int>(s), x), g.sliders[s]);
  std::stable_sort(order.begin(), order.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<int> path = {g.chain.front()};
  for (const auto& o : order) path.push_back(o.second);
  path.push_back(g.chain.back());
  return path;
}

double SlidingGroupTerm::chainLength() const {
  double L = 0.0;
  for (int k = 0; k < state_.def().numElements(); ++k) L += state_.refLength(k);
  return L;
}

namespace {
// Scatter of a condensed chain's rows: nodes `ids`, residual r and matrix J (3 per node), through
// the one assembly path with a fixed size.
template <int N>
void addFixed(SystemAssembler& out, const std::vector<int>& ids, const Eigen::VectorXd& r,
              const Eigen::MatrixXd* J) {
  std::array<int, N> a;
  std::copy(ids.begin(), ids.end(), a.begin());
  const Eigen::Matrix<double, 3 * N, 1> rf = r;
  if (!J) return out.add<N>(a, rf, nullptr);
  const Eigen::Matrix<double, 3 * N, 3 * N> Jf = *J;
  out.add<N>(a, rf, &Jf);
}
void addChainRows(SystemAssembler& out, const std::vector<int>& ids, const Eigen::VectorXd& r,
                  const Eigen::MatrixXd* J) {
  switch (ids.size()) {
    case 2:
      return addFixed<2>(out, ids, r, J);
    case 3:
      return addFixed<3>(out, ids, r, J);
    case 4:
      return addFixed<4>(out, ids, r, J);
    case 5:
      return addFixed<5>(out, ids, r, J);
    case 6:
      return addFixed<6>(out, ids, r, J);
    case 7:
      return addFixed<7>(out, ids, r, J);
    case 8:
      return addFixed<8>(out, ids, r, J);
    default:
      throw std::logic_error(
          "condensed chain with more than 5 sliders (the case reader refuses it)");
  }
}
}  // namespace

void SlidingGroupTerm::assembleCondensed(const EvalPoint& p, SystemAssembler& out) {
  // EM12: the chain is one uniform-strain polyline from end to end through its sliders in their
  // order at the step's start; its discrete gradient between x_n and x_{n+1} = 2 x_mid - x_n.
  const auto& g = state_.def();
  const auto& mat = m_->materials[g.material];
  const bool wantJ = out.wantMatrix();
  const Eigen::VectorXd& x0 = *p.xStart;
  const std::vector<int> path = chainPath(x0);
  const int n = static_cast<int>(path.size());
  std::vector<Vec3> P0(n), P1(n);
  for (int i = 0; i < n; ++i) {
    P0[i] = pos(x0, path[i]);
    P1[i] = 2.0 * pos(p.x, path[i]) - P0[i];
  }
  const double L = chainLength();
  ++out.work().sliding;
  const auto dg = kernels::polylineDiscreteGradient(P0, P1, L, mat, p.emDissipation, wantJ);
  Eigen::MatrixXd J;
  if (wantJ) J = (2.0 * p.cx) * dg.dForce;  // d x_{n+1} / d x_mid = 2
  addChainRows(out, path, dg.force, wantJ ? &J : nullptr);
  // Inner nodes on the path at x_{n+1}, at their material coordinates: r = k (x - X(P)), a
  // stiffness k = E A / L to scale the rows like the chain's own.
  const double k = mat.E * mat.area / L;
  double S = 0.0;
  for (int j = 1; j < g.numElements(); ++j) {
    S += state_.refLength(j - 1);
    Eigen::MatrixXd dX;
    const Vec3 X = kernels::polylinePoint(P1, S / L, wantJ ? &dX : nullptr);
    std::vector<int> ids = path;
    ids.push_back(g.chain[j]);
    Eigen::VectorXd r = Eigen::VectorXd::Zero(3 * (n + 1));
    r.segment<3>(3 * n) = k * (2.0 * pos(p.x, g.chain[j]) - pos(x0, g.chain[j]) - X);
    Eigen::MatrixXd Jj;
    if (wantJ) {
      Jj = Eigen::MatrixXd::Zero(3 * (n + 1), 3 * (n + 1));
      Jj.block<3, 3>(3 * n, 3 * n) = k * (2.0 * p.cx) * Eigen::Matrix3d::Identity();
      Jj.block(3 * n, 0, 3, 3 * n) = -k * (2.0 * p.cx) * dX;
    }
    addChainRows(out, ids, r, wantJ ? &Jj : nullptr);
  }
}

void SlidingGroupTerm::placeSlidersOnChain(const Eigen::VectorXd& x) {
  // The sliders' material coordinates on the condensed chain (uniform strain: arc length along
  // the path over its length, times L) give their active elements.
  const auto& g = state_.def();
  const std::vector<int> path = chainPath(x);
  double total = 0.0;
  std::vector<double> arc = {0.0};
  for (size_t i = 0; i + 1 < path.size(); ++i)
    arc.push_back(total += (pos(x, path[i + 1]) - pos(x, path[i])).norm());
  const double L = chainLength();
  for (size_t i = 1; i + 1 < path.size(); ++i) {
    const int s = static_cast<int>(std::find(g.sliders.begin(), g.sliders.end(), path[i]) -
                                   g.sliders.begin());
    const double S = total > 0.0 ? L * arc[i] / total : 0.0;
    int k = 0;
    double at = state_.refLength(0);
    while (k + 1 < g.numElements() && at <= S) at += state_.refLength(++k);
    state_.moveTo(s, k);
  }
}

bool SlidingGroupTerm::symmetricJacobian() const {
  const auto& g = state_.def();
  const auto& mat = m_->materials[g.material];
  // Friction's algorithmic tangent is not symmetric (non-associated slip, docs/friction.md FR10).
  for (size_t s = 0; s < g.sliders.size(); ++s)
    if (g.frictionOf(static_cast<int>(s))) return false;
  return mat.density == 0.0;
}

namespace {
// The friction element at positions x for slider s of group state st (docs/friction.md).
kernels::FrictionSlidingResult frictionElement(
    const Model& m, const SlidingGroupState& st, int s, const Eigen::VectorXd& x, double t,
    double dt, bool withTangent, kernels::SliderStick startSlip = kernels::SliderStick::Stick) {
  const auto& g = st.def();
  const int k = st.activeElement(s);
  const auto* law = g.frictionOf(s);
  return kernels::frictionSlidingForce(pos(x, g.chain[k]), pos(x, g.chain[k + 1]),
                                       pos(x, g.sliders[s]), st.refLength(k), st.splitStart(s),
                                       m.materials[g.material], *law, dt, t >= law->lockAt,
                                       withTangent, startSlip);
}

// Whether nodes a, b, c of x are where they were committed (to round-off of a blend of equal
// positions, as generalized-alpha's x_{n+1-alpha_f} at the predictor x_{n+1} = x_n).
bool atCommitted(const Eigen::VectorXd& x, const Eigen::VectorXd& committed,
                 std::initializer_list<int> nodes) {
  if (committed.size() != x.size()) return false;
  for (int n : nodes)
    for (int c = 0; c < 3; ++c) {
      const double a = x[3 * n + c], b = committed[3 * n + c];
      if (std::abs(a - b) > 4.0 * std::numeric_limits<double>::epsilon() * std::abs(b))
        return false;
    }
  return true;
}

// Slack parts of the friction element: the Jacobian-only spring of addSlackTangent (RG5), per
// part.
void addSlackPartTangents(const kernels::FrictionSlidingResult& res,
                          const kernels::LineMaterial& mat, double L, double cx, Mat9& J) {
  if (!mat.tensionOnly || mat.compressionStiffnessRatio > 0.0) return;
  const Eigen::Matrix3d k =
      cx * kernels::kCableSlackTangent * mat.E * mat.area / L * Eigen::Matrix3d::Identity();
  const double strain[2] = {res.strain1, res.strain2};
  for (int part = 0; part < 2; ++part) {
    if (strain[part] > 0.0) continue;
    const int a = part, b = 2;  // end node, slider
    J.block<3, 3>(3 * a, 3 * a) += k;
    J.block<3, 3>(3 * b, 3 * b) += k;
    J.block<3, 3>(3 * a, 3 * b) -= k;
    J.block<3, 3>(3 * b, 3 * a) -= k;
  }
}
}  // namespace

void SlidingGroupTerm::commit(const CommitPoint& c) {
  const Eigen::VectorXd& x = c.x;
  state_.ensureSplits(x);
  if (condensed_) placeSlidersOnChain(x);  // EM12: no hand-over events, the path says where
  const auto& g = state_.def();
  for (size_t s = 0; s < g.sliders.size(); ++s) {
    const int si = static_cast<int>(s);
    if (!g.frictionOf(si)) continue;
    const auto res = frictionElement(*m_, state_, si, x, c.tForces, c.dt, false);
    SlidingGroupState::FrictionState f;
    f.s = res.s;
    f.state = res.state;
    f.slipRate = c.dt > 0.0 ? (res.s - state_.splitStart(si)) / c.dt : 0.0;
    f.N1 = res.N1;
    f.N2 = res.N2;
    f.wrapAngle = res.wrapAngle;
    state_.setConvergedFriction(si, f);
  }
  state_.commit(x);
  // The committed positions serve the friction predictor only (FR15): a group without friction
  // keeps its first copy (saved and loaded as it is) rather than copying every dof each step.
  bool friction = false;
  for (size_t s = 0; s < g.sliders.size(); ++s)
    friction = friction || g.frictionOf(static_cast<int>(s)) != nullptr;
  if (friction || committedX_.size() != x.size()) committedX_ = x;
  committedT_ = c.tForces;
}

void SlidingGroupTerm::save(History& h) const {
  state_.save(h);
  h.put(committedT_);
  h.put(committedX_);
}

void SlidingGroupTerm::load(HistoryReader& h) {
  state_.load(h);
  committedT_ = h.finiteReal();
  committedX_ = h.vector(3 * m_->numNodes());
  if (!committedX_.allFinite()) h.fail("committed positions not finite");
}

SlidingGroupTerm::ActiveParts SlidingGroupTerm::activeParts(int element,
                                                            const Eigen::VectorXd& x) const {
  const auto& g = state_.def();
  const int s = state_.sliderOfElement(element);
  if (s >= 0 && g.frictionOf(s)) {
    const auto r = frictionElement(*m_, state_, s, x, committedT_, 0.0, false);
    return {r.N1, r.strain1, r.N2, r.strain2};
  }
  const auto& mat = m_->materials[g.material];
  const Vec3 x1 = pos(x, g.chain[element]), x2 = pos(x, g.chain[element + 1]);
  if (s < 0) {
    const auto c = kernels::cableForce(x1, x2, state_.refLength(element), mat, false);
    return {c.axialForce, c.strain, c.axialForce, c.strain};
  }
  const auto r =
      kernels::slidingForce(x1, x2, pos(x, g.sliders[s]), state_.refLength(element), mat, false);
  return {r.axialForce, r.strain, r.axialForce, r.strain};
}

void SlidingGroupTerm::assembleInertia(const EvalPoint& p, SystemAssembler& out) const {
  const auto& g = state_.def();
  const auto& mat = m_->materials[g.material];
  for (int k = 0; k < g.numElements(); ++k) {
    const int n1 = g.chain[k], n2 = g.chain[k + 1];
    const int s = state_.sliderOfElement(k);
    if (s < 0) {  // inactive: a plain two-node cable's M a
      addCableInertia(*m_, n1, n2, state_.refLength(k), mat, p, out);
      continue;
    }
    if (mat.density <= 0.0) continue;
    const int n3 = g.sliders[s];
    ++out.work().lineMass;
    const Vec9 r = kernels::slidingInertiaForce(pos(p.x, n1), pos(p.x, n2), pos(p.x, n3),
                                                gather3(p.a, n1, n2, n3), state_.refLength(k), mat,
                                                m_->massKind);
    out.add<3>({n1, n2, n3}, r, nullptr);
  }
}

void SlidingGroupTerm::addStiffnessBound(const Eigen::VectorXd& x, double /*t*/,
                                         const std::vector<char>& free,
                                         std::vector<double>& S) const {
  const auto& g = state_.def();
  const auto& mat = m_->materials[g.material];
  for (int k = 0; k < g.numElements(); ++k) {
    const int n1 = g.chain[k], n2 = g.chain[k + 1];
    const double L = state_.refLength(k);
    const int s = state_.sliderOfElement(k);
    if (s < 0) {
      kernels::addLineBound(n1, n2, kernels::lineStiffness(mat, L), free, S);
      continue;
    }
    // Uniform strain over the whole element (F9): K = k g g^T with g the gradient of l1 + l2,
    // |g| = 1 at the end nodes and |t1 - t2| <= 2 at the slider. The stiffness is that of the
    // whole reference length L however close the slider is to a node: a slider approaching a
    // node does not shrink the step (EX6).
    const int n3 = g.sliders[s];
    if (g.frictionOf(s)) {
      // Capstan friction: each part has its own strain over its own reference length (FR2); a
      // sticking slider next to a node makes a short, stiff part, and the step shrinks with it
      // (EX6).
      const double s1 = std::clamp(state_.splitStart(s), 1e-9 * L, L * (1.0 - 1e-9));
      kernels::addLineBound(n1, n3, mat.E * mat.area / s1, free, S);
      kernels::addLineBound(n3, n2, mat.E * mat.area / (L - s1), free, S);
      continue;
    }
    const Vec3 d1 = pos(x, n3) - pos(x, n1), d2 = pos(x, n2) - pos(x, n3);
    const double l1 = d1.norm(), l2 = d2.norm();
    const double gs = (l1 > 0.0 && l2 > 0.0) ? (d1 / l1 - d2 / l2).norm() : 2.0;
    const double kk = kernels::lineStiffness(mat, L);
    const double g1 = free[n1] ? 1.0 : 0.0, g2 = free[n2] ? 1.0 : 0.0, g3 = free[n3] ? gs : 0.0;
    const double sum = g1 + g2 + g3;
    S[n1] += kk * 1.0 * sum;
    S[n2] += kk * 1.0 * sum;
    S[n3] += kk * gs * sum;
  }
}

bool SlidingGroupTerm::takeLineDrag() {
  if (!lanes_) return false;
  const DragLoadDef* only = nullptr;
  int loads = 0;
  for (const auto& d : m_->drags)
    if (d.lineSet >= 0 && d.lineSet == state_.def().set) only = &d, ++loads;
  if (loads != 1) return false;  // none, or several: the line-drag term adds them
  drag_ = only;
  return true;
}

void SlidingGroupTerm::assembleInactiveLanes(const EvalPoint& p, SystemAssembler& out,
                                             bool withDrag) {
  const auto& g = state_.def();
  const auto& mat = m_->materials[g.material];
  // The lanes as they are, unless an element changed since they were made.
  bool same = laneDrag_ == (withDrag ? 1 : 0);
  size_t next = 0;
  for (int k = 0; k < g.numElements() && same; ++k) {
    if (state_.sliderOfElement(k) >= 0) continue;
    same = next < laneElements_.size() && laneElements_[next] == k &&
           laneLengths_[next] == state_.refLength(k);
    ++next;
  }
  if (!same || next != laneElements_.size()) {
    const double coefficient = withDrag ? drag_->coefficient : 0.0;
    const Vec3 wind = withDrag ? drag_->wind : Vec3::Zero();
    laneElements_.clear();
    laneLengths_.clear();
    for (int k = 0; k < g.numElements(); ++k)
      if (state_.sliderOfElement(k) < 0) {
        laneElements_.push_back(k);
        laneLengths_.push_back(state_.refLength(k));
      }
    const size_t n = laneElements_.size();
    inactiveLanes_.resize((n + kernels::kCableLanes - 1) / kernels::kCableLanes);
    for (size_t slot = 0; slot < inactiveLanes_.size() * kernels::kCableLanes; ++slot) {
      auto& lanes = inactiveLanes_[slot / kernels::kCableLanes];
      const int lane = static_cast<int>(slot % kernels::kCableLanes);
      if (slot >= n) {
        kernels::clearCableLane(lanes, lane);
        continue;
      }
      const int k = laneElements_[slot];
      const double L = laneLengths_[slot];
      kernels::setCableLane(lanes, lane, g.chain[k], g.chain[k + 1], L, mat,
                            line_assembly::cableLaneWeight(*m_, L, mat), coefficient, wind);
    }
    laneDrag_ = withDrag ? 1 : 0;
  }
  // The energy balance's loads, when kept: the drag is a load, the weight is not.
  Eigen::VectorXd* captured = withDrag ? out.fusedLoads() : nullptr;
  kernels::CableLaneVectors f;
  const std::int64_t elastic[kernels::kCableLanes] = {-1, -1, -1, -1};
  const size_t n = laneElements_.size();
  for (size_t b = 0; b < inactiveLanes_.size(); ++b) {
    const auto& lanes = inactiveLanes_[b];
    kernels::cableForcesAndDrag(p.x.data(), p.v.data(), lanes, p.loadFactor,
                                withDrag ? p.loadFactor : 0.0, elastic, f);
    for (int l = 0; l < kernels::kCableLanes && b * kernels::kCableLanes + l < n; ++l) {
      ++out.work().lineElastic;
      if (mat.density > 0.0) ++out.work().lineMass;
      if (withDrag) ++out.work().drag;
      line_assembly::scatterCableLane(lanes, f, l, captured, out);
    }
  }
}

void SlidingGroupTerm::assemble(const EvalPoint& p, SystemAssembler& out) {
  if (p.inertiaOnly) {  // reads only (no floor_): may run alongside the assembly (EX2)
    assembleInertia(p, out);
    return;
  }
  const auto& g = state_.def();
  const auto& mat = m_->materials[g.material];
  const bool wantJ = out.wantMatrix();
  floor_ = 0.0;
  if (condensed_ && p.xStart) return assembleCondensed(p, out);
  const bool explicitForces = line_assembly::explicitForcesOnly(*m_, p, out);
  const bool inLanes = explicitForces && lanes_;
  if (inLanes) assembleInactiveLanes(p, out, drag_ && fusedLineDrag(*m_, p, out));
  for (int k = 0; k < g.numElements(); ++k) {
    const int n1 = g.chain[k], n2 = g.chain[k + 1];
    const int s = state_.sliderOfElement(k);
    if (s < 0) {  // inactive: a plain two-node cable (docs/formulation.md section 3)
      if (inLanes) continue;
      if (explicitForces)
        line_assembly::addCableExplicitForce(*m_, n1, n2, state_.refLength(k), mat, p, out);
      else
        assembleCable(*m_, n1, n2, state_.refLength(k), g.material, p, out);
      continue;
    }
    const int n3 = g.sliders[s];
    const double L = state_.refLength(k);
    const Vec3 x1 = pos(p.x, n1), x2 = pos(p.x, n2), x3 = pos(p.x, n3);
    ++out.work().sliding;
    Vec9 r;
    Mat9 J;
    if (g.frictionOf(s)) {  // capstan friction, lock or one-way flow (docs/friction.md)
      // FR15: the first iteration of a step, at the converged positions of a slipping slider,
      // takes the tangent of the slip continuing (the stick predictor is on the limit there).
      const auto& committed = state_.friction(s);
      const bool start = wantJ && committed.state != kernels::SliderStick::Stick &&
                         state_.activeElement(s) == state_.committedActiveElement(s) &&
                         atCommitted(p.x, committedX_, {n1, n2, n3});
      const auto res = frictionElement(*m_, state_, s, p.x, p.t, p.dt, wantJ,
                                       start ? committed.state : kernels::SliderStick::Stick);
      floor_ = std::max(floor_, kernels::frictionRoundoffFloor(x1, x2, x3, L, res.s));
      r = res.force;
      J = p.cx * res.stiffness;
      if (wantJ) addSlackPartTangents(res, mat, L, p.cx, J);
    } else if (p.xStart) {
      // Energy-momentum step: the discrete gradient of the element's length (EM11). The case
      // reader allows it only without friction and mass (a step's topology is fixed: slider
      // events end a step where a slider reaches a node).
      const Eigen::VectorXd& x0 = *p.xStart;
      const std::array<Vec3, 3> start = {pos(x0, n1), pos(x0, n2), pos(x0, n3)};
      const std::array<Vec3, 3> end = {2.0 * x1 - start[0], 2.0 * x2 - start[1],
                                       2.0 * x3 - start[2]};
      const auto dg = kernels::slidingDiscreteGradient(start, end, L, mat, p.emDissipation, wantJ);
      r = dg.force;
      J = (2.0 * p.cx) * dg.dForce;
      if (wantJ && dg.strain0 <= 0.0 && dg.strain1 <= 0.0) {
        kernels::PolylineResult<3> slack;
        slack.strain = dg.strain1;
        addSlackTangent<3>(slack, mat, L, {0, 2, 1}, p.cx, J, false);
      }
    } else if (!wantJ) {
      r = kernels::slidingForceOnly(x1, x2, x3, L, mat);  // slidingForce's residual, bit for bit
    } else {
      const auto res = kernels::slidingForce(x1, x2, x3, L, mat, true);
      r = res.force;
      J = p.cx * res.stiffness;
      // path 1 -> slider -> 2
      if (addSlackTangent<3>(res, mat, L, {0, 2, 1}, p.cx, J, p.kinkTangent))
        ++out.work().kinkTangents;
    }
    if (mat.density > 0.0 && p.inertia && !g.frictionOf(s)) {
      // RG8: the whirl of an end node about the slider, damped within kWhirlDampingFraction L.
      kernels::WhirlDampingParams par;
      const double perLength = 0.5 * mat.density * mat.area;
      par.endMass[0] = k > 0 ? perLength * state_.refLength(k - 1) : 0.0;
      par.endMass[1] = k + 1 < g.numElements() ? perLength * state_.refLength(k + 1) : 0.0;
      par.sliderMass = perLength * L;
      par.explicitStep = p.explicitStep;
      Vec9 xe, ve;
      xe << x1, x2, x3;
      ve = gather3(p.v, n1, n2, n3);
      const auto wd = kernels::sliderWhirlDamping(xe, ve, L, mat, par, wantJ);
      if (wd.active) {
        ++out.work().whirlDamping;
        r += wd.force;
        if (wantJ) J += p.cx * wd.dPosition + p.cv * wd.dVelocity;
      }
    }
    if (mat.density > 0.0) {
      ++out.work().lineMass;
      const bool gathered = p.inertia && !p.zeroAcceleration;
      const Vec9 acc = gathered ? gather3(p.a, n1, n2, n3) : Vec9::Zero();
      // A residual-only evaluation at zero acceleration without mass damping (the explicit step,
      // EX2) has M(x) a = 0: skipped, as for the cables and membranes.
      if (p.inertia && (wantJ || m_->massDamping > 0.0 || (gathered && !acc.isZero(0.0)))) {
        const auto in = kernels::slidingInertia(x1, x2, x3, acc, L, mat, m_->massKind);
        r += in.force;
        if (wantJ) J += p.ca * in.mass + p.cx * in.dForce;
        if (m_->massDamping > 0.0) {  // C v with C = alpha M(x) (solver.mass_damping)
          const auto dv =
              kernels::slidingInertia(x1, x2, x3, gather3(p.v, n1, n2, n3), L, mat, m_->massKind);
          r += m_->massDamping * dv.force;
          if (wantJ) J += m_->massDamping * (p.cv * dv.mass + p.cx * dv.dForce);
        }
      }
      if (m_->hasGravity()) {
        const auto gr = kernels::slidingGravity(x1, x2, x3, L, mat, m_->gravity);
        r -= p.loadFactor * gr.force;
        if (wantJ) J -= p.loadFactor * p.cx * gr.dForce;
      }
    }
    out.add<3>({n1, n2, n3}, r, wantJ ? &J : nullptr);
  }
}

void SlidingGroupTerm::addEnergy(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double,
                                 EnergyBreakdown& e) const {
  const auto& g = state_.def();
  const auto& mat = m_->materials[g.material];
  for (int k = 0; k < g.numElements(); ++k) {
    const int n1 = g.chain[k], n2 = g.chain[k + 1];
    const int s = state_.sliderOfElement(k);
    if (s < 0) {
      cableEnergy(*m_, n1, n2, state_.refLength(k), g.material, x, v, e);
      continue;
    }
    const int n3 = g.sliders[s];
    const double L = state_.refLength(k);
    const Vec3 x1 = pos(x, n1), x2 = pos(x, n2), x3 = pos(x, n3);
    e.strain += g.frictionOf(s) ? frictionElement(*m_, state_, s, x, committedT_, 0.0, false).energy
                                : kernels::slidingForce(x1, x2, x3, L, mat, false).energy;
    if (mat.density > 0.0) {
      const Vec9 vv = gather3(v, n1, n2, n3);
      e.kinetic += 0.5 * vv.dot(kernels::slidingInertiaForce(x1, x2, x3, vv, L, mat, m_->massKind));
      // The F11 nodal loads are exactly the weights of the two straight parts placed at their
      // ends, so -f.x is the parts' true potential energy.
      e.gravity -= kernels::slidingGravity(x1, x2, x3, L, mat, m_->gravity)
                       .force.dot(gather3(x, n1, n2, n3));
    }
  }
}

}  // namespace chute
