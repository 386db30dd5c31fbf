#include "terms/LineDragTerm.hpp"

#include <algorithm>

#include "kernels/LineDragKernel.hpp"

namespace chute {

using kernels::Vec3;

// ---- LineDragTerm --------------------------------------------------------------------------
LineDragTerm::LineDragTerm(const Model& m, std::vector<const SlidingGroupState*> groups)
    : m_(&m), groups_(std::move(groups)), cablesOf_(m.drags.size()), groupsOf_(m.drags.size()) {
  for (size_t d = 0; d < m.drags.size(); ++d) {
    for (size_t c = 0; c < m.cables.size(); ++c)
      if (m.cables[c].set == m.drags[d].lineSet) cablesOf_[d].push_back(static_cast<int>(c));
    for (size_t g = 0; g < m.groups.size(); ++g)
      if (m.groups[g].set == m.drags[d].lineSet) groupsOf_[d].push_back(static_cast<int>(g));
  }
}

void LineDragTerm::leaveCables(const TakenCables& taken) {
  cablesLeft_ = cablesOf_;
  cablesTaken_ = taken != nullptr;
  if (!taken) return;
  for (auto& left : cablesLeft_)
    left.erase(std::remove_if(left.begin(), left.end(), [&](int c) { return (*taken)[c] != 0; }),
               left.end());
}

void LineDragTerm::leaveGroups(std::vector<char> taken) {
  groupsTaken_ = std::move(taken);
}

void LineDragTerm::addCouplings(std::vector<std::vector<int>>& cliques) const {
  for (const auto& d : m_->drags) {
    for (const auto& e : d.edges) cliques.push_back({e[0], e[1]});
    for (const auto& c : m_->cables)
      if (c.set == d.lineSet) cliques.push_back({c.a, c.b});
    for (const auto& g : m_->groups) {
      if (g.set != d.lineSet) continue;
      for (int k = 0; k < g.numElements(); ++k)
        for (int s : g.sliders) cliques.push_back({g.chain[k], g.chain[k + 1], s});
    }
  }
}

void LineDragTerm::addSegment(int a, int b, const Vec3& wind, double c, const EvalPoint& p,
                              SystemAssembler& out) const {
  ++out.work().drag;
  const auto d = kernels::lineDrag(p.x.segment<3>(3 * a), p.x.segment<3>(3 * b),
                                   p.v.segment<3>(3 * a), p.v.segment<3>(3 * b), wind, c, true);
  const Eigen::Matrix<double, 6, 6> J = p.cx * d.dPosition + p.cv * d.dVelocity;
  out.add<2>({a, b}, d.residual, &J);
}

// Per segment, 0.7 of an explicit membrane triangle (Term::assemblyCost); none for the cables
// whose drag the cable term took (CB1).
double LineDragTerm::assemblyCost() const {
  double cost = 0.0;
  for (size_t di = 0; di < m_->drags.size(); ++di) {
    const auto& d = m_->drags[di];
    if (d.lineSet < 0) {
      cost += 0.7 * static_cast<double>(d.edges.size());
      continue;
    }
    cost += 0.7 * static_cast<double>((cablesTaken_ ? cablesLeft_ : cablesOf_)[di].size());
    for (int gi : groupsOf_[di]) {  // a taken group's active elements alone: two parts each
      const auto& g = m_->groups[gi];
      const bool taken = !groupsTaken_.empty() && groupsTaken_[gi] != 0;
      cost += 0.7 * (taken ? 2.0 * static_cast<double>(g.sliders.size()) : g.numElements());
    }
  }
  return cost;
}

template <class Segment>
void LineDragTerm::forEachSegment(const EvalPoint& p, bool fused, Segment&& segment) const {
  const auto& cables = fused && cablesTaken_ ? cablesLeft_ : cablesOf_;
  for (size_t di = 0; di < m_->drags.size(); ++di) {
    const auto& d = m_->drags[di];
    // Drag is an applied load: scaled by the load factor like the others (1 in dynamics).
    const double coef = d.coefficient * p.loadFactor;
    for (const auto& e : d.edges) segment(e[0], e[1], d.wind, coef);
    for (int ci : cables[di]) segment(m_->cables[ci].a, m_->cables[ci].b, d.wind, coef);
    for (int gi : groupsOf_[di]) {
      const auto& g = m_->groups[gi];
      const SlidingGroupState& state = *groups_[gi];
      // The two straight parts through slider s of element k.
      auto through = [&](int k, int s) {
        segment(g.chain[k], g.sliders[s], d.wind, coef);
        segment(g.sliders[s], g.chain[k + 1], d.wind, coef);
      };
      if (fused && !groupsTaken_.empty() && groupsTaken_[gi] != 0) {
        // The group's own pass adds its plain elements' drag (CB1): only the elements with a
        // slider here, in the elements' order, each with its first slider (sliderOfElement), as
        // the loop over all elements below would (which cost 2 % of the C-9 slider case's step).
        if (g.sliders.size() == 1) {
          through(state.activeElement(0), 0);
          continue;
        }
        std::vector<std::pair<int, int>> active;
        for (int s = 0; s < static_cast<int>(g.sliders.size()); ++s)
          active.emplace_back(state.activeElement(s), s);
        std::sort(active.begin(), active.end());
        for (size_t i = 0; i < active.size(); ++i)
          if (i == 0 || active[i].first != active[i - 1].first)
            through(active[i].first, active[i].second);
        continue;
      }
      for (int k = 0; k < g.numElements(); ++k) {
        const int s = state.sliderOfElement(k);
        if (s < 0)
          segment(g.chain[k], g.chain[k + 1], d.wind, coef);
        else
          through(k, s);
      }
    }
  }
}

void LineDragTerm::assemble(const EvalPoint& p, SystemAssembler& out) {
  if (!p.inertia) return;  // drag needs motion: nothing in statics
  const bool fused = (cablesTaken_ || !groupsTaken_.empty()) && fusedLineDrag(*m_, p, out);
  if (out.wantMatrix())
    forEachSegment(p, fused, [&](int a, int b, const Vec3& wind, double coef) {
      addSegment(a, b, wind, coef, p, out);
    });
  else  // the explicit step's: residual only, inlined into the loops (LD1)
    forEachSegment(p, fused, [&](int a, int b, const Vec3& wind, double coef) {
      ++out.work().drag;
      out.addToEachNode<2>({a, b}, kernels::lineDragNodeResidual(
                                       p.x.segment<3>(3 * a), p.x.segment<3>(3 * b),
                                       p.v.segment<3>(3 * a), p.v.segment<3>(3 * b), wind, coef));
    });
}

}  // namespace chute
