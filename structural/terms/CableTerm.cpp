#include "terms/CableTerm.hpp"

#include <algorithm>
#include <cmath>

#include "kernels/CableKernel.hpp"
#include "kernels/StiffnessBound.hpp"
#include "terms/LineElementAssembly.hpp"

namespace chute {

using line_assembly::assembleCable;
using line_assembly::cableEnergy;
using line_assembly::cableStrainEnergy;
using line_assembly::pos;

// ---- CableTerm -------------------------------------------------------------------------------
CableTerm::CableTerm(const Model& m) : m_(&m) {
  hanging_.assign(static_cast<size_t>(m.numNodes()), 1);
  for (const auto& e : m.membranes)
    for (const int n : e.nodes)
      if (n >= 0) hanging_[static_cast<size_t>(n)] = 0;
  if (!kernels::useAvx2()) return;  // the baseline copy of the lanes is slower than one by one
  const size_t n = m.cables.size(), batches = (n + kernels::kCableLanes - 1) / kernels::kCableLanes;
  lanes_.resize(batches);
  laneCable_.assign(batches * kernels::kCableLanes, -1);
  for (size_t slot = 0; slot < laneCable_.size(); ++slot) {
    auto& lanes = lanes_[slot / kernels::kCableLanes];
    const int lane = static_cast<int>(slot % kernels::kCableLanes);
    if (slot >= n) {
      kernels::clearCableLane(lanes, lane);
      continue;
    }
    const auto& c = m.cables[slot];
    const auto& mat = m.materials[c.material];
    kernels::setCableLane(lanes, lane, c.a, c.b, c.L, mat,
                          line_assembly::cableLaneWeight(m, c.L, mat), 0.0, Vec3::Zero());
    laneCable_[slot] = static_cast<int>(slot);
    anyCut_ = anyCut_ || std::isfinite(m.lineSets[c.set].cutAt);
  }
}

TakenCables CableTerm::takeLineDrag() {
  if (lanes_.empty()) return nullptr;
  auto taken = std::make_shared<std::vector<char>>(m_->cables.size(), 0);
  takenSlot_.assign(laneCable_.size(), 0);
  for (size_t ci = 0; ci < m_->cables.size(); ++ci) {
    const DragLoadDef* only = nullptr;
    int loads = 0;
    for (const auto& d : m_->drags)
      if (d.lineSet >= 0 && d.lineSet == m_->cables[ci].set) only = &d, ++loads;
    if (loads != 1) continue;  // none, or several: the line-drag term adds them
    auto& lanes = lanes_[ci / kernels::kCableLanes];
    const int lane = static_cast<int>(ci % kernels::kCableLanes);
    lanes.drag[lane] = only->coefficient;
    for (int k = 0; k < 3; ++k) lanes.wind[k][lane] = only->wind[k];
    (*taken)[ci] = 1;
    takenSlot_[ci] = 1;
    dragTaken_ = true;
  }
  return dragTaken_ ? taken : nullptr;
}

void CableTerm::assembleLanes(const EvalPoint& p, SystemAssembler& out, bool withDrag) {
  // The energy balance's loads, when kept: the drag is a load, the weight is not (the gravity
  // energy books it).
  Eigen::VectorXd* captured = withDrag ? out.fusedLoads() : nullptr;
  const double dragFactor = withDrag ? p.loadFactor : 0.0;  // LD1's coefficient times it
  kernels::CableLaneVectors f;
  std::int64_t elastic[kernels::kCableLanes];
  for (size_t b = 0; b < lanes_.size(); ++b) {
    const int* cables = &laneCable_[b * kernels::kCableLanes];
    for (int l = 0; l < kernels::kCableLanes; ++l)
      elastic[l] =
          cables[l] >= 0 && !(anyCut_ && m_->lineSets[m_->cables[cables[l]].set].cutBy(p.t)) ? -1
                                                                                             : 0;
    kernels::cableForcesAndDrag(p.x.data(), p.v.data(), lanes_[b], p.loadFactor, dragFactor,
                                elastic, f);
    const auto& lanes = lanes_[b];
    for (int l = 0; l < kernels::kCableLanes && cables[l] >= 0; ++l) {
      if (elastic[l] != 0) {
        ++out.work().lineElastic;
        if (m_->materials[m_->cables[cables[l]].material].density > 0.0) ++out.work().lineMass;
      }
      const bool dragged = withDrag && takenSlot_[b * kernels::kCableLanes + l] != 0;
      if (dragged) ++out.work().drag;
      line_assembly::scatterCableLane(lanes, f, l, dragged ? captured : nullptr, out);
    }
  }
}

void CableTerm::addCouplings(std::vector<std::vector<int>>& cliques) const {
  for (const auto& c : m_->cables) cliques.push_back({c.a, c.b});
}

void CableTerm::assemble(const EvalPoint& p, SystemAssembler& out) {
  if (line_assembly::explicitForcesOnly(*m_, p, out)) {
    if (!lanes_.empty()) {
      assembleLanes(p, out, dragTaken_ && fusedLineDrag(*m_, p, out));
      return;
    }
    for (const auto& c : m_->cables)
      if (!m_->lineSets[c.set].cutBy(p.t))
        line_assembly::addCableExplicitForce(*m_, c.a, c.b, c.L, m_->materials[c.material], p, out);
    return;
  }
  for (const auto& c : m_->cables)
    if (!m_->lineSets[c.set].cutBy(p.t)) assembleCable(*m_, c.a, c.b, c.L, c.material, p, out);
}

void CableTerm::addEnergy(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double t,
                          EnergyBreakdown& e) const {
  if (m_->massKind != kernels::MassKind::Lumped) {
    for (const auto& c : m_->cables)
      if (!m_->lineSets[c.set].goneAt(t)) cableEnergy(*m_, c.a, c.b, c.L, c.material, x, v, e);
    return;
  }
  // A lumped mass's kinetic and gravity energy node by node (each node's mass its cables' halves,
  // those whose set is not gone at t), where a pass over the cables formed a six-vector product
  // for each: the same sums to round-off.
  for (const auto& c : m_->cables)
    if (!m_->lineSets[c.set].goneAt(t))
      e.strain += cableStrainEnergy(*m_, c.a, c.b, c.L, c.material, x);
  const NodeMasses& nodes = nodeMassAt(t);
  addNodeMassEnergy(nodes, 0, nodes.size(), m_->gravity, x, v, e);
}

const NodeMasses& CableTerm::nodeMassAt(double t) const {
  // Made again only when the sets gone at t are not those it was made for (a cut).
  std::vector<char> gone(m_->lineSets.size());
  for (size_t s = 0; s < gone.size(); ++s) gone[s] = m_->lineSets[s].goneAt(t) ? 1 : 0;
  if (nodeMassMade_ && gone == nodeMassGone_) return nodeMass_;
  std::vector<double> mass(m_->numNodes(), 0.0);
  std::vector<char> has(m_->numNodes(), 0);
  for (const auto& c : m_->cables) {
    const auto& mat = m_->materials[c.material];
    if (gone[c.set] || !(mat.density > 0.0)) continue;
    const double half = 0.5 * (mat.density * mat.area * c.L);  // cableMassTimes' lumped entries
    mass[c.a] += half, mass[c.b] += half;
    has[c.a] = has[c.b] = 1;
  }
  nodeMass_ = nodesWithMass(mass, has);
  nodeMassGone_ = std::move(gone);
  nodeMassMade_ = true;
  return nodeMass_;
}

void CableTerm::addStiffnessBound(const Eigen::VectorXd& /*x*/, double t,
                                  const std::vector<char>& free, std::vector<double>& S) const {
  for (const auto& c : m_->cables) {
    if (m_->lineSets[c.set].cutBy(t)) continue;
    const auto& mat = m_->materials[c.material];
    // EX6; EX6l: a tension-only line's ends that hang free of the fabric with a margin.
    auto factor = [&](int n) {
      return mat.tensionOnly && hanging_[static_cast<size_t>(n)] ? kernels::kHangingLineBound : 1.0;
    };
    kernels::addLineBound(c.a, c.b, kernels::lineStiffness(mat, c.L), free, S, factor(c.a),
                          factor(c.b));
  }
}

// Per element, 0.7 of an explicit membrane triangle one by one; in lanes 0.55, and 0.6 more for
// the drag taken (Term::assemblyCost; the lanes with drag at 1.14 of a triangle, perf, the C-9
// slider case on one thread).
double CableTerm::assemblyCost() const {
  if (lanes_.empty()) return 0.7 * static_cast<double>(m_->cables.size());
  const double taken = static_cast<double>(std::count(takenSlot_.begin(), takenSlot_.end(), 1));
  return 0.55 * static_cast<double>(m_->cables.size()) + 0.6 * taken;
}

double CableTerm::stepEventFraction(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) {
  double fraction = 1.0;
  for (const auto& c : m_->cables) {
    const auto& mat = m_->materials[c.material];
    if (!mat.tensionOnly || mat.compressionStiffnessRatio == 1.0) continue;  // no kink
    fraction = std::min(fraction, kernels::slackTautCrossing(pos(x, c.b) - pos(x, c.a),
                                                             pos(dx, c.b) - pos(dx, c.a), c.L));
  }
  return fraction;
}

}  // namespace chute
