#include "terms/SurfaceTerms.hpp"

#include <algorithm>

namespace chute {

using kernels::Vec3;

namespace {
template <int N>
std::array<Vec3, N> gatherNodes(const Eigen::VectorXd& x, const MembraneElement& e) {
  std::array<Vec3, N> out;
  for (int i = 0; i < N; ++i) out[i] = x.segment<3>(3 * e.nodes[i]);
  return out;
}
template <int N>
std::array<int, N> nodeIds(const MembraneElement& e) {
  std::array<int, N> ids;
  for (int i = 0; i < N; ++i) ids[i] = e.nodes[i];
  return ids;
}
// N x N scalar matrix times I3.
template <int N>
Eigen::Matrix<double, 3 * N, 3 * N> expand(const Eigen::Matrix<double, N, N>& M) {
  Eigen::Matrix<double, 3 * N, 3 * N> out = Eigen::Matrix<double, 3 * N, 3 * N>::Zero();
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j)
      out.template block<3, 3>(3 * i, 3 * j).diagonal().setConstant(M(i, j));
  return out;
}
}  // namespace

// ---- MembraneTerm --------------------------------------------------------------------------
MembraneTerm::MembraneTerm(const Model& m) : m_(&m), states_(m.membranes.size()) {
  for (const auto& e : m.membranes) {
    const auto& mat = m.membraneMaterials[e.material];
    const double pre = m.membraneSets[e.set].prestrain;
    if (e.numNodes == 3) {
      slot_.push_back(static_cast<int>(refs3_.size()));
      refs3_.push_back(kernels::triangleReference(
          {m.X[e.nodes[0]], m.X[e.nodes[1]], m.X[e.nodes[2]]}, mat.thickness, pre));
    } else {
      slot_.push_back(static_cast<int>(refs4_.size()));
      refs4_.push_back(kernels::quadReference(
          {m.X[e.nodes[0]], m.X[e.nodes[1]], m.X[e.nodes[2]], m.X[e.nodes[3]]}, mat.thickness,
          pre));
    }
  }
}

void MembraneTerm::addCouplings(std::vector<std::vector<int>>& cliques) const {
  for (const auto& e : m_->membranes)
    cliques.emplace_back(e.nodes.begin(), e.nodes.begin() + e.numNodes);
}

std::vector<int> MembraneTerm::elementsAt(int node) const {
  std::vector<int> out;
  for (size_t k = 0; k < m_->membranes.size(); ++k)
    for (int i = 0; i < m_->membranes[k].numNodes; ++i)
      if (m_->membranes[k].nodes[i] == node) out.push_back(static_cast<int>(k));
  return out;
}

template <int N>
void MembraneTerm::assembleElement(int k, const kernels::MembraneReference<N>& ref,
                                   const EvalPoint& p, SystemAssembler& out) {
  const auto& e = m_->membranes[k];
  const auto& mat = m_->membraneMaterials[e.material];
  const bool wantJ = out.wantMatrix();
  const auto x = gatherNodes<N>(p.x, e);
  const auto res = kernels::membraneForce<N>(x, ref, mat, m_->membraneSets[e.set].wrinkling, wantJ);
  ++out.work().membrane;
  states_[k] = {res.state, res.principalStress, res.principalStrain};
  Eigen::Matrix<double, 3 * N, 1> r = res.force;
  Eigen::Matrix<double, 3 * N, 3 * N> J = p.cx * res.stiffness;
  if (wantJ && res.state != kernels::WrinkleState::Taut) {
    // Slack or wrinkled fabric has no stiffness across the wrinkles: the Jacobian (never the
    // residual) gets a membrane tension of kSlackTangent E t in every direction, so that slack
    // regions do not make it singular. Converged states are untouched.
    constexpr double kSlackTangent = 1e-6;
    Eigen::Matrix<double, N, N> G = Eigen::Matrix<double, N, N>::Zero();
    for (int g = 0; g < kernels::MembraneReference<N>::kGauss; ++g)
      G += ref.weight[g] * ref.dN[g] * ref.dN[g].transpose();
    J += p.cx * kSlackTangent * mat.E * expand<N>(G);
  }
  if (mat.density > 0.0) {
    const auto Ms =
        kernels::membraneMass<N>(ref, mat.density, m_->massKind == kernels::MassKind::Lumped);
    if (p.inertia) {
      const auto M = expand<N>(Ms);
      Eigen::Matrix<double, 3 * N, 1> a;
      for (int i = 0; i < N; ++i) a.template segment<3>(3 * i) = p.a.segment<3>(3 * e.nodes[i]);
      r += M * a;
      J += p.ca * M;
      if (m_->massDamping > 0.0) {  // C v with C = alpha M (pseudo-dynamics, physical damping)
        Eigen::Matrix<double, 3 * N, 1> vel;
        for (int i = 0; i < N; ++i) vel.template segment<3>(3 * i) = p.v.segment<3>(3 * e.nodes[i]);
        r += m_->massDamping * M * vel;
        J += p.cv * m_->massDamping * M;
      }
    }
    if (m_->hasGravity()) {
      const Eigen::Matrix<double, N, 1> share = Ms.rowwise().sum();  // rho t0 int N_i dA
      for (int i = 0; i < N; ++i)
        r.template segment<3>(3 * i) -= p.loadFactor * share[i] * m_->gravity;
    }
  }
  out.add<N>(nodeIds<N>(e), r, wantJ ? &J : nullptr);
}

void MembraneTerm::assemble(const EvalPoint& p, SystemAssembler& out) {
  for (size_t k = 0; k < m_->membranes.size(); ++k) {
    if (m_->membranes[k].numNodes == 3)
      assembleElement<3>(static_cast<int>(k), refs3_[slot_[k]], p, out);
    else
      assembleElement<4>(static_cast<int>(k), refs4_[slot_[k]], p, out);
  }
}

void MembraneTerm::addEnergy(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double,
                             EnergyBreakdown& en) const {
  auto one = [&](const auto& ref, const MembraneElement& e, auto nodesTag) {
    constexpr int N = decltype(nodesTag)::value;
    const auto& mat = m_->membraneMaterials[e.material];
    en.strain += kernels::membraneForce<N>(gatherNodes<N>(x, e), ref, mat,
                                           m_->membraneSets[e.set].wrinkling, false)
                     .energy;
    if (mat.density <= 0.0) return;
    const auto Ms =
        kernels::membraneMass<N>(ref, mat.density, m_->massKind == kernels::MassKind::Lumped);
    Eigen::Matrix<double, 3 * N, 1> vv;
    for (int i = 0; i < N; ++i) vv.template segment<3>(3 * i) = v.segment<3>(3 * e.nodes[i]);
    en.kinetic += 0.5 * vv.dot(expand<N>(Ms) * vv);
    const Eigen::Matrix<double, N, 1> share = Ms.rowwise().sum();
    for (int i = 0; i < N; ++i)
      en.gravity -= share[i] * m_->gravity.dot(x.segment<3>(3 * e.nodes[i]));
  };
  for (size_t k = 0; k < m_->membranes.size(); ++k) {
    const auto& e = m_->membranes[k];
    if (e.numNodes == 3)
      one(refs3_[slot_[k]], e, std::integral_constant<int, 3>{});
    else
      one(refs4_[slot_[k]], e, std::integral_constant<int, 4>{});
  }
}

// ---- PressureTerm --------------------------------------------------------------------------
void PressureTerm::addCouplings(std::vector<std::vector<int>>& cliques) const {
  // Only the loaded sets' elements (the membrane term already couples all of them).
  for (const auto& e : m_->membranes)
    if (std::any_of(m_->pressures.begin(), m_->pressures.end(),
                    [&](const PressureLoadDef& l) { return l.set == e.set; }))
      cliques.emplace_back(e.nodes.begin(), e.nodes.begin() + e.numNodes);
}

void PressureTerm::assemble(const EvalPoint& p, SystemAssembler& out) {
  const bool wantJ = out.wantMatrix();
  for (const auto& load : m_->pressures) {
    const double p0 = p.loadFactor * load.at(p.t);
    if (p0 == 0.0) continue;
    int inSet = 0;
    for (const auto& e : m_->membranes) {
      if (e.set != load.set) continue;
      const double pr = load.elementFactor.empty() ? p0 : p0 * load.elementFactor[inSet];
      ++inSet;
      auto one = [&](auto nodesTag) {
        constexpr int N = decltype(nodesTag)::value;
        const auto pl = kernels::pressureLoad<N>(gatherNodes<N>(p.x, e), pr, wantJ);
        ++out.work().pressure;
        const Eigen::Matrix<double, 3 * N, 1> r = -pl.force;
        const Eigen::Matrix<double, 3 * N, 3 * N> J = -p.cx * pl.dForce;
        out.add<N>(nodeIds<N>(e), r, wantJ ? &J : nullptr);
      };
      if (e.numNodes == 3)
        one(std::integral_constant<int, 3>{});
      else
        one(std::integral_constant<int, 4>{});
    }
  }
}

// ---- DragTerm ------------------------------------------------------------------------------
void DragTerm::addCouplings(std::vector<std::vector<int>>& cliques) const {
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

void DragTerm::addSegment(int a, int b, const Vec3& wind, double c, const EvalPoint& p,
                          SystemAssembler& out) const {
  const bool wantJ = out.wantMatrix();
  const auto d = kernels::lineDrag(p.x.segment<3>(3 * a), p.x.segment<3>(3 * b),
                                   p.v.segment<3>(3 * a), p.v.segment<3>(3 * b), wind, c, wantJ);
  ++out.work().drag;
  const Eigen::Matrix<double, 6, 6> J = p.cx * d.dPosition + p.cv * d.dVelocity;
  out.add<2>({a, b}, d.residual, wantJ ? &J : nullptr);
}

void DragTerm::assemble(const EvalPoint& p, SystemAssembler& out) {
  if (!p.inertia) return;  // drag needs motion: nothing in statics
  for (const auto& d : m_->drags) {
    // Drag is an applied load: scaled by the load factor like the others (1 in dynamics).
    const double coef = d.coefficient * p.loadFactor;
    for (const auto& e : d.edges) addSegment(e[0], e[1], d.wind, coef, p, out);
    for (const auto& c : m_->cables)
      if (c.set == d.lineSet) addSegment(c.a, c.b, d.wind, coef, p, out);
    for (size_t gi = 0; gi < m_->groups.size(); ++gi) {
      const auto& g = m_->groups[gi];
      if (g.set != d.lineSet) continue;
      for (int k = 0; k < g.numElements(); ++k) {
        const int s = groups_[gi]->sliderOfElement(k);
        if (s < 0) {
          addSegment(g.chain[k], g.chain[k + 1], d.wind, coef, p, out);
        } else {  // the two straight parts through the slider
          addSegment(g.chain[k], g.sliders[s], d.wind, coef, p, out);
          addSegment(g.sliders[s], g.chain[k + 1], d.wind, coef, p, out);
        }
      }
    }
  }
}

}  // namespace chute

namespace chute {

// The element states are a function of the strain at the last assembly, not memory the
// mechanics needs; they are kept with the history so that output after a restore (coupling
// window, checkpoint) shows the restored state, not the last trial's.
void MembraneTerm::save(History& h) const {
  std::vector<int> wrinkle(states_.size());
  std::vector<double> values;
  values.reserve(4 * states_.size());
  for (size_t k = 0; k < states_.size(); ++k) {
    wrinkle[k] = static_cast<int>(states_[k].state);
    for (int c = 0; c < 2; ++c) values.push_back(states_[k].principalStress[c]);
    for (int c = 0; c < 2; ++c) values.push_back(states_[k].principalStrain[c]);
  }
  h.put(wrinkle);
  h.put(values);
}

void MembraneTerm::load(HistoryReader& h) {
  const auto wrinkle = h.ints(states_.size(), 0, static_cast<int>(kernels::WrinkleState::Slack));
  const auto values = h.reals(4 * states_.size());
  for (size_t k = 0; k < states_.size(); ++k) {
    states_[k].state = static_cast<kernels::WrinkleState>(wrinkle[k]);
    states_[k].principalStress = Eigen::Vector2d(values[4 * k], values[4 * k + 1]);
    states_[k].principalStrain = Eigen::Vector2d(values[4 * k + 2], values[4 * k + 3]);
  }
}

}  // namespace chute
