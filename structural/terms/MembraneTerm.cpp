#include "terms/MembraneTerm.hpp"

#include <algorithm>
#include <limits>
#include <type_traits>

#include "kernels/MembraneDiscreteGradient.hpp"
#include "kernels/Regularisations.hpp"
#include "terms/CanopyFlowTerm.hpp"
#include "terms/MembraneElementAssembly.hpp"

namespace chute {

namespace {
// A load taken (P2), in explicit triangles: on the C-9 slider case the membranes' pass took 29.6
// ns per triangle with a pressure and a face drag, 20.4 without (timed per term), 0.23 of a
// triangle per load.
constexpr double kTakenFaceCost = 0.23;
// The airflow's loads of a triangle taken (FL13), with the airflow's per-node work after the pass
// shared over its triangles: on the generated C-9 in free flight (cases/c9_flight.toml) the pass
// made 362 instructions per triangle with them, 193 without (callgrind).
constexpr double kTakenFlowCost = 0.85;
}  // namespace

using kernels::Vec3;
using membrane_assembly::expand;
using membrane_assembly::gatherNodes;
using membrane_assembly::nodeIds;

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
  // The weight of every path, made once when the model has gravity (empty without).
  if (m.hasGravity())
    for (size_t k = 0; k < m.membranes.size(); ++k) massShare_.push_back(massSharesOf(k));
  makeExplicitTriangles();
}

void MembraneTerm::prepareFor(const IntegrationTraits& traits) {
  if (traits.explicitSteps) makeBound();
}

std::array<double, 4> MembraneTerm::massSharesOf(size_t k) const {
  // rho t0 int N_i dA: the element's mass matrix, row by row (lumped or consistent alike).
  std::array<double, 4> out{0.0, 0.0, 0.0, 0.0};
  const auto& e = m_->membranes[k];
  const double density = m_->membraneMaterials[e.material].density;
  if (!(density > 0.0)) return out;
  const bool lumped = m_->massKind == kernels::MassKind::Lumped;
  auto shares = [&](const auto& ref, auto nodesTag) {
    constexpr int N = decltype(nodesTag)::value;
    const Eigen::Matrix<double, N, 1> share =
        kernels::membraneMass<N>(ref, density, lumped).rowwise().sum();
    for (int i = 0; i < N; ++i) out[i] = share[i];
  };
  if (e.numNodes == 3)
    shares(refs3_[slot_[k]], std::integral_constant<int, 3>{});
  else
    shares(refs4_[slot_[k]], std::integral_constant<int, 4>{});
  return out;
}

void MembraneTerm::makeExplicitTriangles() {
  explicitTriangles_.resize(refs3_.size());
  for (size_t k = 0; k < m_->membranes.size(); ++k) {
    const auto& e = m_->membranes[k];
    if (e.numNodes != 3) {
      quads_.push_back(static_cast<int>(k));
      continue;
    }
    ExplicitTriangle& t = explicitTriangles_[slot_[k]];
    t.nodes = nodeIds<3>(e);
    t.force = kernels::membraneTriangleRecord(refs3_[slot_[k]], m_->membraneMaterials[e.material],
                                              m_->membraneSets[e.set].wrinkling);
    const std::array<double, 4> share = massSharesOf(k);  // with or without gravity
    for (int i = 0; i < 3; ++i) t.share[i] = share[i];
  }
  // The lumped triangles' masses per node (M4), summed in the triangles' order: their kinetic and
  // gravity energy node by node (NodeMassEnergy.hpp).
  if (m_->massKind == kernels::MassKind::Lumped) {
    std::vector<double> mass(m_->numNodes(), 0.0);
    std::vector<char> has(m_->numNodes(), 0);
    for (size_t k = 0; k < m_->membranes.size(); ++k) {
      const auto& e = m_->membranes[k];
      if (e.numNodes != 3 || m_->membraneMaterials[e.material].density <= 0.0) continue;
      const ExplicitTriangle& t = explicitTriangles_[slot_[k]];
      for (int i = 0; i < 3; ++i) mass[t.nodes[i]] += t.share[i], has[t.nodes[i]] = 1;
    }
    triangleNodeMass_ = nodesWithMass(mass, has);
  }
  constexpr size_t kLanes = kernels::kTriangleLanes;
  triangleLanes_.resize((explicitTriangles_.size() + kLanes - 1) / kLanes);
  for (size_t b = 0; b < triangleLanes_.size(); ++b)
    for (size_t l = 0; l < kLanes; ++l) {
      const ExplicitTriangle& t =
          explicitTriangles_[std::min(b * kLanes + l, explicitTriangles_.size() - 1)];
      kernels::setLane(triangleLanes_[b], static_cast<int>(l), t.force, t.nodes);
    }
}

// The explicit step's triangles, four at a time (kernels/MembraneTriangleBatch.hpp): their forces
// (each lane membraneTriangleForce's bits) with their weights, scattered in the triangles' order;
// what assembleInternalForce<3> gives (M3, M4). Their wrinkling states are not written to
// states_: elementStates() makes them, with the principal values, from the assembly's positions
// when output asks (writing a state per triangle touched a cache line of states_ each, 2 % of the
// generated 12k C-9's step, perf).
void MembraneTerm::assembleExplicitTriangles(const EvalPoint& p, SystemAssembler& out, size_t b0,
                                             size_t b1, int half) {
  constexpr int kLanes = kernels::kTriangleLanes;
  const double* x = p.x.data();
  const double* v = p.v.data();
  const bool weighed = !massShare_.empty();
  const size_t count = explicitTriangles_.size();
  if (flow_ && fusedFaceLoads(p, out)) {
    assembleTrianglesWithFlow(p, out, b0, b1, half);
    return;
  }
  // P2: the face loads taken, at this evaluation's time and load factor (PressureTerm's and
  // FaceDragTerm's products); also kept over all dofs where the energy balance asks.
  const bool loads = !taken_.empty() && fusedFaceLoads(p, out);
  Eigen::VectorXd* captured = loads ? out.fusedLoads() : nullptr;
  if (loads) {
    // Counted as PressureTerm counts (not while a pressure is zero) and FaceDragTerm does, once.
    std::vector<double>& pressureNow = pressureNow_[half];
    std::vector<double>& dragNow = dragNow_[half];
    for (size_t i = 0; i < pressureNow.size(); ++i) {
      pressureNow[i] = p.loadFactor * m_->pressures[i].at(p.t);
      if (pressureNow[i] != 0.0 && half == 0) out.work().pressure += takenPerPressure_[i];
    }
    for (size_t i = 0; i < dragNow.size(); ++i)
      dragNow[i] = m_->faceDrags[i].coefficient * p.loadFactor;
    if (half == 0) out.work().faceDrag += takenDrags_;
  }
  if (!kernels::useAvx2()) {
    // Without AVX2 one at a time: the baseline copy of the four-lane kernel, two SSE2 operations
    // for each, was slower than this (chute's step on the generated C-9 113 ns per triangle
    // against 100). The same bits (each lane is membraneTriangleForce's, and
    // triangleFaceLoad's).
    for (size_t k = b0 * kLanes; k < std::min(count, b1 * kLanes); ++k) {
      const ExplicitTriangle& t = explicitTriangles_[k];
      Eigen::Matrix<double, 9, 1> r;
      kernels::membraneTriangleForce(x + 3 * t.nodes[0], x + 3 * t.nodes[1], x + 3 * t.nodes[2],
                                     t.force, r.data());
      double f[3];
      if (loads) {
        kernels::triangleFaceLoad(x + 3 * t.nodes[0], x + 3 * t.nodes[1], x + 3 * t.nodes[2],
                                  v + 3 * t.nodes[0], v + 3 * t.nodes[1], v + 3 * t.nodes[2],
                                  takenParameters(k, half), f);
        for (int i = 0; i < 3; ++i)
          for (int c = 0; c < 3; ++c) r[3 * i + c] += f[c];
      }
      scatterTriangle(t, r, loads ? f : nullptr, captured, weighed, p.loadFactor, out);
    }
    return;
  }
  // The batches with and without the face loads in loops of their own: one loop testing for the
  // loads at every triangle cost 11 % more instructions without any (callgrind, generated 12k C-9).
  auto batches = [&](auto withLoads) {
    constexpr bool kLoads = decltype(withLoads)::value;
    for (size_t b = b0; b < b1; ++b) {
      const size_t first = b * kLanes;
      const int lanes = static_cast<int>(std::min<size_t>(kLanes, count - first));
      kernels::TriangleLaneVectors fs;  // with the face loads added where taken
      double f[3][kLanes];
      if constexpr (kLoads) {
        kernels::TriangleFaceLoadLanes& q = takenLanes_[b];
        for (int l = 0; l < kLanes; ++l) {  // the missing lanes repeat the last triangle
          const TakenLoad& tl = taken_[std::min(first + l, count - 1)];
          q.pressure[l] = takenPressure(tl, half);
          q.drag[l] = takenDrag(tl, half);
        }
        kernels::membraneTriangleForcesAndLoads(x, v, triangleLanes_[b], q, fs, f);
      } else {
        kernels::membraneTriangleForces(x, triangleLanes_[b], fs, nullptr);  // states: see above
      }
      for (int l = 0; l < lanes; ++l)
        scatterLane(fs, f, l, explicitTriangles_[first + l], kLoads, captured, weighed,
                    p.loadFactor, out);
    }
  };
  if (loads)
    batches(std::true_type{});
  else
    batches(std::false_type{});
}

kernels::TriangleFaceLoadParameters MembraneTerm::takenParameters(size_t triangle, int half) const {
  const TakenLoad& tl = taken_[triangle];
  kernels::TriangleFaceLoadParameters q;
  q.pressure = takenPressure(tl, half);
  q.drag = takenDrag(tl, half);
  if (tl.drag >= 0) {
    const FaceDragLoadDef& d = m_->faceDrags[tl.drag];
    for (int c = 0; c < 3; ++c) q.wind[c] = d.wind[c];
    q.steady = d.steadySubtracted ? 1.0 : 0.0;
  }
  return q;
}

void MembraneTerm::assembleTrianglesWithFlow(const EvalPoint& p, SystemAssembler& out, size_t b0,
                                             size_t b1, int half) {
  constexpr int kLanes = kernels::kTriangleLanes;
  const double* x = p.x.data();
  const double* v = p.v.data();
  const bool weighed = !massShare_.empty();
  const size_t count = explicitTriangles_.size();
  // The whole pass makes the airflow's parameters; the halves have them (beforeHalves).
  if (!flowHalves_) flowParameters_ = flow_->takenParameters(p);
  const kernels::TriangleFlowParameters& q = flowParameters_;
  double* records = flow_->faceRecords();        // triangle k's at 4 k: each half writes its own
  Eigen::VectorXd* captured = out.fusedLoads();  // the energy balance's loads, when kept
  // The canopy's sums lane by lane, triangle k in lane k mod 4 whichever path runs (the same
  // bits), added up once the faces are done (flowSums). On the stack while the pass runs, kept
  // at its end: the two halves' members share a cache line, and both threads adding to it at
  // every batch made two threads slower than one.
  kernels::TriangleFlowAccumulators acc;
  if (!kernels::useAvx2()) {
    // One at a time (as assembleExplicitTriangles, for the same reason): the lanes' bits.
    for (size_t k = b0 * kLanes; k < std::min(count, b1 * kLanes); ++k) {
      const ExplicitTriangle& t = explicitTriangles_[k];
      const double* x0 = x + 3 * t.nodes[0];
      const double* x1 = x + 3 * t.nodes[1];
      const double* x2 = x + 3 * t.nodes[2];
      Eigen::Matrix<double, 9, 1> r;
      kernels::membraneTriangleForce(x0, x1, x2, t.force, r.data());
      const bool inFlow = flowSlots_[k][0] >= 0;
      double f[3];
      if (inFlow) {
        kernels::TriangleFlowSums o;
        kernels::triangleFlowLoad(x0, x1, x2, v + 3 * t.nodes[0], v + 3 * t.nodes[1],
                                  v + 3 * t.nodes[2], q, f, o);
        for (int i = 0; i < 3; ++i)
          for (int c = 0; c < 3; ++c) r[3 * i + c] += f[c];
        const size_t lane = k % kLanes;
        acc.volume[lane] += o.volume, acc.area[lane] += o.area;
        acc.cloth[lane] += o.cloth, acc.dCloth[lane] += o.dCloth;
        double* record = records + 4 * k;
        for (int c = 0; c < 3; ++c) record[c] = o.nodeArea[c];
        record[3] = o.share;
      }
      scatterTriangle(t, r, inFlow ? f : nullptr, captured, weighed, p.loadFactor, out);
    }
  } else {
    for (size_t b = b0; b < b1; ++b) {
      const size_t first = b * kLanes;
      const int lanes = static_cast<int>(std::min<size_t>(kLanes, count - first));
      kernels::TriangleLaneVectors fs;
      double f[3][kLanes];
      kernels::membraneTriangleForcesAndFlow(x, v, triangleLanes_[b], flowLanes_[b], q, fs, f, acc,
                                             records + 4 * first);
      for (int l = 0; l < lanes; ++l)
        scatterLane(fs, f, l, explicitTriangles_[first + l],
                    captured && flowLanes_[b].inFlow[l] != 0, captured, weighed, p.loadFactor, out);
    }
  }
  flowSums_[half] = acc;
}

CanopyFlowTerm::FaceSums MembraneTerm::flowSums(bool halves) const {
  constexpr int kLanes = kernels::kTriangleLanes;
  auto total = [&](auto member) {
    auto lanes = [&](const kernels::TriangleFlowAccumulators& a) {
      const double(&lane)[kLanes] = a.*member;
      return ((lane[0] + lane[1]) + lane[2]) + lane[3];
    };
    return halves ? lanes(flowSums_[0]) + lanes(flowSums_[1]) : lanes(flowSums_[0]);
  };
  using A = kernels::TriangleFlowAccumulators;
  return {total(&A::volume), total(&A::area), total(&A::cloth), total(&A::dCloth)};
}

bool MembraneTerm::takeCanopyFlow(CanopyFlowTerm& flow) {
  const Model& m = *m_;
  if (m.massDamping != 0.0 || explicitTriangles_.empty() || !taken_.empty() || flow_ ||
      !flow.trianglesOnly())
    return false;
  flowSlots_.assign(explicitTriangles_.size(), {-1, -1, -1});
  for (size_t k = 0; k < m.membranes.size(); ++k) {
    const auto& e = m.membranes[k];
    if (e.set != flow.set()) continue;
    for (int i = 0; i < 3; ++i) flowSlots_[slot_[k]][i] = flow.slotOf(e.nodes[i]);
  }
  // The missing lanes of the last batch are not the canopy's.
  constexpr size_t kLanes = kernels::kTriangleLanes;
  flowLanes_.assign(triangleLanes_.size(), {});
  for (size_t b = 0; b < flowLanes_.size(); ++b)
    for (size_t l = 0; l < kLanes; ++l) {
      const size_t k = b * kLanes + l;
      const bool in = k < flowSlots_.size() && flowSlots_[k][0] >= 0;
      flowLanes_[b].inFlow[l] = in ? -1 : 0;
    }
  flow_ = &flow;
  flow.takeFaces(flowSlots_);
  return true;
}

TakenFaces MembraneTerm::takeFaceLoads() {
  const Model& m = *m_;
  if (m.massDamping != 0.0 || explicitTriangles_.empty()) return nullptr;
  // Per set: its one pressure and one face drag, -2 where it has more than one.
  std::vector<int> pressureOf(m.membraneSets.size(), -1), dragOf(m.membraneSets.size(), -1);
  for (size_t i = 0; i < m.pressures.size(); ++i) {
    int& slot = pressureOf[m.pressures[i].set];
    slot = slot == -1 ? static_cast<int>(i) : -2;
  }
  for (size_t i = 0; i < m.faceDrags.size(); ++i) {
    int& slot = dragOf[m.faceDrags[i].set];
    slot = slot == -1 ? static_cast<int>(i) : -2;
  }
  auto taken = std::make_shared<std::vector<char>>(m.membranes.size(), 0);
  std::vector<TakenLoad> loads(explicitTriangles_.size());
  std::vector<int> inSet(m.membraneSets.size(), 0);  // the element's place in its set
  long pressures = 0, drags = 0;
  for (size_t k = 0; k < m.membranes.size(); ++k) {
    const auto& e = m.membranes[k];
    const int place = inSet[e.set]++;
    const int pi = pressureOf[e.set], di = dragOf[e.set];
    if (e.numNodes != 3 || pi == -2 || di == -2 || (pi < 0 && di < 0)) continue;
    TakenLoad& tl = loads[slot_[k]];
    tl.pressure = pi, tl.drag = di;
    if (pi >= 0 && !m.pressures[pi].elementFactor.empty())
      tl.pressureFactor = m.pressures[pi].elementFactor[place];
    (*taken)[k] = 1;
    pressures += pi >= 0, drags += di >= 0;
  }
  if (pressures + drags == 0) return nullptr;
  taken_ = std::move(loads);
  takenDrags_ = drags;
  takenPerPressure_.assign(m.pressures.size(), 0);
  for (const TakenLoad& tl : taken_)
    if (tl.pressure >= 0) ++takenPerPressure_[tl.pressure];
  for (int half = 0; half < 2; ++half) {
    pressureNow_[half].assign(m.pressures.size(), 0.0);
    dragNow_[half].assign(m.faceDrags.size(), 0.0);
  }
  // The lanes' winds and steady parts (the missing lanes of the last batch: its last triangle's).
  constexpr size_t kLanes = kernels::kTriangleLanes;
  takenLanes_.assign(triangleLanes_.size(), kernels::TriangleFaceLoadLanes{});
  for (size_t b = 0; b < takenLanes_.size(); ++b)
    for (size_t l = 0; l < kLanes; ++l) {
      const kernels::TriangleFaceLoadParameters q =
          takenParameters(std::min(b * kLanes + l, taken_.size() - 1), 0);
      for (int c = 0; c < 3; ++c) takenLanes_[b].wind[c][l] = q.wind[c];
      takenLanes_[b].steady[l] = q.steady;
    }
  return taken;
}

void MembraneTerm::makeBound() const {
  if (!bound_.empty()) return;
  bound_.reserve(m_->membranes.size());
  for (const auto& e : m_->membranes) {
    // On the reference geometry: the initial one shrunk by the set's prestrain.
    const double shrink = 1.0 / (1.0 + m_->membraneSets[e.set].prestrain);
    std::array<Vec3, 4> X;
    X.fill(Vec3::Zero());
    for (int i = 0; i < e.numNodes; ++i) X[i] = shrink * m_->X[e.nodes[i]];
    bound_.push_back(
        kernels::membraneBoundReference(X, e.numNodes, m_->membraneMaterials[e.material]));
  }
}

void MembraneTerm::addStiffnessBound(const Eigen::VectorXd& x, double /*t*/,
                                     const std::vector<char>& /*free*/,
                                     std::vector<double>& S) const {
  addStiffnessBoundOver(x, 0, m_->membranes.size(), S);
}

void MembraneTerm::addStiffnessBoundHalf(const Eigen::VectorXd& x, double /*t*/,
                                         const std::vector<char>& /*free*/, std::vector<double>& S,
                                         int half) const {
  const auto [begin, end] = halfOf(m_->membranes.size(), half);
  addStiffnessBoundOver(x, begin, end, S);
}

void MembraneTerm::addStiffnessBoundOver(const Eigen::VectorXd& x, size_t begin, size_t end,
                                         std::vector<double>& S) const {
  makeBound();
  for (size_t k = begin; k < end; ++k) {
    const auto& e = m_->membranes[k];
    if (!(bound_[k].perNode > 0.0)) continue;
    const double perNode =  // EX6m
        e.numNodes == 3 ? kernels::membraneNodeBound<3>(bound_[k], gatherNodes<3>(x, e))
                        : kernels::membraneNodeBound<4>(bound_[k], gatherNodes<4>(x, e));
    for (int i = 0; i < e.numNodes; ++i) S[e.nodes[i]] += perNode;
  }
}

// A triangle is the unit; a quad, which the explicit step takes one at a time, costs 5; a face
// load taken (P2), a pressure or a drag, kTakenFaceCost; the airflow's (FL13) kTakenFlowCost
// (Term::assemblyCost).
double MembraneTerm::assemblyCost() const {
  double tri = 0.0, quad = 0.0;
  for (const auto& e : m_->membranes) (e.numNodes == 3 ? tri : quad) += 1.0;
  double taken = static_cast<double>(takenDrags_);
  for (long n : takenPerPressure_) taken += static_cast<double>(n);
  double flow = 0.0;
  for (const auto& slots : flowSlots_) flow += slots[0] >= 0 ? 1.0 : 0.0;
  return tri + 5.0 * quad + kTakenFaceCost * taken + kTakenFlowCost * flow;
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
  const bool wrinkling = m_->membraneSets[e.set].wrinkling;
  ++out.work().membrane;
  Eigen::Matrix<double, 3 * N, 1> r;
  Eigen::Matrix<double, 3 * N, 3 * N> J;
  kernels::WrinkleState state;
  if (p.xStart) {
    // Energy-momentum step: the discrete gradient between x_n and x_{n+1} = 2 x_mid - x_n (EM10).
    const auto x0 = gatherNodes<N>(*p.xStart, e);
    std::array<Vec3, N> x1;
    for (int i = 0; i < N; ++i) x1[i] = 2.0 * x[i] - x0[i];
    const auto dg =
        kernels::membraneDiscreteGradient<N>(x0, x1, ref, mat, wrinkling, p.emDissipation, wantJ);
    states_[k].state = dg.state;
    r = dg.force;
    if (wantJ) J = (2.0 * p.cx) * dg.dForce;
    state = dg.state;
  } else {
    // Principal stresses and strains are output-only: computed when output asks for them.
    const auto res = kernels::membraneForce<N>(x, ref, mat, wrinkling, wantJ, false);
    states_[k].state = res.state;
    r = res.force;
    if (wantJ) J = p.cx * res.stiffness;
    state = res.state;
  }
  if (wantJ && state != kernels::WrinkleState::Taut) {
    // Slack or wrinkled fabric has no stiffness across the wrinkles: the Jacobian (never the
    // residual) gets a membrane tension of kMembraneSlackTangent E t in every direction (RG6), so
    // that slack regions do not make it singular. Converged states are untouched.
    Eigen::Matrix<double, N, N> G = Eigen::Matrix<double, N, N>::Zero();
    for (int g = 0; g < kernels::MembraneReference<N>::kGauss; ++g)
      G += ref.weight[g] * ref.dN[g] * ref.dN[g].transpose();
    J += p.cx * kernels::kMembraneSlackTangent * mat.E * expand<N>(G);
  }
  // A residual-only evaluation at zero acceleration without mass damping (the explicit step,
  // EX2) has M a = 0: skipped, and so is the mass (the weight comes from the shares).
  const bool gathered = p.inertia && !p.zeroAcceleration;
  Eigen::Matrix<double, 3 * N, 1> a;
  if (gathered)
    for (int i = 0; i < N; ++i) a.template segment<3>(3 * i) = p.a.segment<3>(3 * e.nodes[i]);
  else
    a.setZero();
  const bool withInertia = mat.density > 0.0 && p.inertia &&
                           (wantJ || m_->massDamping > 0.0 || (gathered && !a.isZero(0.0)));
  if (withInertia) {
    const auto M = expand<N>(
        kernels::membraneMass<N>(ref, mat.density, m_->massKind == kernels::MassKind::Lumped));
    r += M * a;
    if (wantJ) J += p.ca * M;
    if (m_->massDamping > 0.0) {  // C v with C = alpha M (pseudo-dynamics, physical damping)
      Eigen::Matrix<double, 3 * N, 1> vel;
      for (int i = 0; i < N; ++i) vel.template segment<3>(3 * i) = p.v.segment<3>(3 * e.nodes[i]);
      r += m_->massDamping * M * vel;
      if (wantJ) J += p.cv * m_->massDamping * M;
    }
  }
  if (!massShare_.empty()) addWeight<N>(massShare_[k].data(), p.loadFactor, r);
  out.add<N>(nodeIds<N>(e), r, wantJ ? &J : nullptr);
}

template <int N>
void MembraneTerm::assembleInternalForce(int k, const kernels::MembraneReference<N>& ref,
                                         const EvalPoint& p, SystemAssembler& out) {
  const auto& e = m_->membranes[k];
  ++out.work().membrane;
  const auto res =
      kernels::membraneForce<N>(gatherNodes<N>(p.x, e), ref, m_->membraneMaterials[e.material],
                                m_->membraneSets[e.set].wrinkling, false, false);
  states_[k].state = res.state;
  if (massShare_.empty()) {
    out.add<N>(nodeIds<N>(e), res.force, nullptr);
    return;
  }
  Eigen::Matrix<double, 3 * N, 1> r = res.force;
  addWeight<N>(massShare_[k].data(), p.loadFactor, r);
  out.add<N>(nodeIds<N>(e), r, nullptr);
}

bool MembraneTerm::explicitPath(const EvalPoint& p, const SystemAssembler& out) const {
  // No Jacobian, a = 0 and no mass damping: only the internal force f(x) and the weight (what
  // assembleElement gives then, without its other branches).
  return !out.wantMatrix() && !p.xStart && (!p.inertia || p.zeroAcceleration) &&
         m_->massDamping == 0.0;
}

void MembraneTerm::assemble(const EvalPoint& p, SystemAssembler& out) {
  lastX_ = p.x;
  principalsStale_ = true;
  if (explicitPath(p, out)) {
    assembleExplicitTriangles(p, out, 0, triangleLanes_.size(), 0);
    for (int k : quads_) assembleInternalForce<4>(k, refs4_[slot_[k]], p, out);
    if (flow_ && fusedFaceLoads(p, out)) {
      // The rest of the airflow's evaluation (its per-node loads kept as the face loads are).
      Eigen::VectorXd* captured = out.fusedLoads();
      if (captured) out.captureAllDofs(captured);
      flow_->finishTakenPass(p, flowSums(false), out);
      if (captured) out.captureAllDofs(nullptr);
    }
    out.work().membrane += static_cast<long>(refs3_.size());
    return;
  }
  for (size_t k = 0; k < m_->membranes.size(); ++k) {
    if (m_->membranes[k].numNodes == 3)
      assembleElement<3>(static_cast<int>(k), refs3_[slot_[k]], p, out);
    else
      assembleElement<4>(static_cast<int>(k), refs4_[slot_[k]], p, out);
  }
}

void MembraneTerm::assembleHalf(const EvalPoint& p, SystemAssembler& out, int half) {
  if (!explicitPath(p, out)) {
    if (half == 0) assemble(p, out);
    return;
  }
  // Half of the batches each (the triangles' state and scratch of each half its own).
  const size_t batches = triangleLanes_.size(), middle = (batches + 1) / 2;
  // The positions kept for the element states (elementStates), each half copying half of them
  // (lastX_ sized in beforeHalves).
  const long n = p.x.size(), from = half == 0 ? 0 : n / 2, to = half == 0 ? n / 2 : n;
  lastX_.segment(from, to - from) = p.x.segment(from, to - from);
  if (half == 0) {
    principalsStale_ = true;
    assembleExplicitTriangles(p, out, 0, middle, 0);
    out.work().membrane += static_cast<long>(refs3_.size());
  } else {
    assembleExplicitTriangles(p, out, middle, batches, 1);
    for (int k : quads_) assembleInternalForce<4>(k, refs4_[slot_[k]], p, out);
  }
}

void MembraneTerm::beforeHalves(const EvalPoint& p, const SystemAssembler& out) {
  if (lastX_.size() != p.x.size()) lastX_.resize(p.x.size());
  flowHalves_ = flow_ && explicitPath(p, out) && fusedFaceLoads(p, out);
  if (flowHalves_) flowParameters_ = flow_->takenParameters(p);  // both halves read them
}

bool MembraneTerm::afterHalves(const EvalPoint& p) {
  if (!flowHalves_) return false;
  flow_->finishTakenSums(p, flowSums(true));
  return true;  // the airflow's per-node loads (afterHalvesPart)
}

void MembraneTerm::afterHalvesPart(const EvalPoint& /*p*/, SystemAssembler& out, int half) {
  if (!flowHalves_) return;
  // The airflow's per-node loads, half of the nodes each (kept as the face loads are).
  Eigen::VectorXd* captured = out.fusedLoads();
  if (captured) out.captureAllDofs(captured);
  flow_->finishTakenNodes(out, half);
  if (captured) out.captureAllDofs(nullptr);
}

const std::vector<MembraneTerm::ElementState>& MembraneTerm::elementStates() const {
  if (!principalsStale_) return states_;
  // The same kernel at the same positions as the last assembly: the values it would have given.
  for (size_t k = 0; k < m_->membranes.size(); ++k) {
    const auto& e = m_->membranes[k];
    const auto& mat = m_->membraneMaterials[e.material];
    const bool wrinkling = m_->membraneSets[e.set].wrinkling;
    auto one = [&](const auto& ref, auto nodesTag) {
      constexpr int N = decltype(nodesTag)::value;
      const auto res =
          kernels::membraneForce<N>(gatherNodes<N>(lastX_, e), ref, mat, wrinkling, false, true);
      states_[k] = {res.state, res.principalStress, res.principalStrain, res.principalResultant};
    };
    if (e.numNodes == 3)
      one(refs3_[slot_[k]], std::integral_constant<int, 3>{});
    else
      one(refs4_[slot_[k]], std::integral_constant<int, 4>{});
  }
  principalsStale_ = false;
  return states_;
}

void MembraneTerm::addEnergy(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double,
                             EnergyBreakdown& en) const {
  addEnergyOver(x, v, 0, m_->membranes.size(), en);
  addNodeMassEnergy(triangleNodeMass_, 0, triangleNodeMass_.size(), m_->gravity, x, v, en);
}

void MembraneTerm::addEnergyHalf(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double,
                                 EnergyBreakdown& en, int half) const {
  const auto [begin, end] = halfOf(m_->membranes.size(), half);
  addEnergyOver(x, v, begin, end, en);
  const auto [nodesBegin, nodesEnd] = halfOf(triangleNodeMass_.size(), half);
  addNodeMassEnergy(triangleNodeMass_, nodesBegin, nodesEnd, m_->gravity, x, v, en);
}

void MembraneTerm::addEnergyOver(const Eigen::VectorXd& x, const Eigen::VectorXd& v, size_t begin,
                                 size_t end, EnergyBreakdown& en) const {
  auto one = [&](const auto& ref, const MembraneElement& e, auto nodesTag) {
    constexpr int N = decltype(nodesTag)::value;
    const auto& mat = m_->membraneMaterials[e.material];
    en.strain += kernels::membraneEnergy<N>(gatherNodes<N>(x, e), ref, mat,
                                            m_->membraneSets[e.set].wrinkling);
    if (mat.density <= 0.0) return;
    const bool lumped = m_->massKind == kernels::MassKind::Lumped;
    const auto Ms = kernels::membraneMass<N>(ref, mat.density, lumped);
    Eigen::Matrix<double, 3 * N, 1> vv, Mv;
    for (int i = 0; i < N; ++i) vv.template segment<3>(3 * i) = v.segment<3>(3 * e.nodes[i]);
    if (lumped) {  // a diagonal mass: the product below without its zeros, bit for bit
      for (int i = 0; i < N; ++i)
        Mv.template segment<3>(3 * i) = Ms(i, i) * vv.template segment<3>(3 * i);
    } else {
      Mv = expand<N>(Ms) * vv;
    }
    en.kinetic += 0.5 * vv.dot(Mv);
    const Eigen::Matrix<double, N, 1> share = Ms.rowwise().sum();
    for (int i = 0; i < N; ++i)
      en.gravity -= share[i] * m_->gravity.dot(x.segment<3>(3 * e.nodes[i]));
  };
  const bool lumped = m_->massKind == kernels::MassKind::Lumped;
  // With AVX2 the explicit records' energies four at a time (triangleLanes_, made with them in
  // makeExplicitTriangles), a batch when its first triangle is reached (the triangles' slots grow
  // with k), added in k's order: the same bits
  // (MembraneKernel.FourTrianglesAtATimeAreTheExplicitTriangleBitForBit). One at a time they cost
  // about 1.5 force passes per triangle.
  constexpr int kLanes = kernels::kTriangleLanes;
  const bool inLanes = kernels::useAvx2();
  size_t batch = std::numeric_limits<size_t>::max();
  double laneEnergy[kLanes];
  for (size_t k = begin; k < end; ++k) {
    const auto& e = m_->membranes[k];
    if (e.numNodes == 4) {
      one(refs4_[slot_[k]], e, std::integral_constant<int, 4>{});
      continue;
    }
    if (!lumped) {
      one(refs3_[slot_[k]], e, std::integral_constant<int, 3>{});
      continue;
    }
    // A triangle of lumped mass: its strain energy from the explicit record (one()'s bits).
    const size_t slot = static_cast<size_t>(slot_[k]);
    const ExplicitTriangle& t = explicitTriangles_[slot];
    const double* xd = x.data();
    if (inLanes) {
      if (slot / kLanes != batch) {
        batch = slot / kLanes;
        kernels::membraneTriangleEnergies(xd, triangleLanes_[batch], laneEnergy);
      }
      en.strain += laneEnergy[slot % kLanes];
    } else {
      en.strain += kernels::membraneTriangleEnergy(xd + 3 * t.nodes[0], xd + 3 * t.nodes[1],
                                                   xd + 3 * t.nodes[2], t.force);
    }
    // Its kinetic and gravity energy: node by node (addNodeMassEnergy).
  }
}

// The element states are a function of the strain at the last assembly, not memory the
// mechanics needs; they are kept with the history so that output after a restore (coupling
// window, checkpoint) shows the restored state, not the last trial's.
void MembraneTerm::save(History& h) const {
  elementStates();  // principal values of the last assembly
  std::vector<int> wrinkle(states_.size());
  std::vector<double> values;
  values.reserve(6 * states_.size());
  for (size_t k = 0; k < states_.size(); ++k) {
    wrinkle[k] = static_cast<int>(states_[k].state);
    for (int c = 0; c < 2; ++c) values.push_back(states_[k].principalStress[c]);
    for (int c = 0; c < 2; ++c) values.push_back(states_[k].principalStrain[c]);
    for (int c = 0; c < 2; ++c) values.push_back(states_[k].principalResultant[c]);
  }
  h.put(wrinkle);
  h.put(values);
}

void MembraneTerm::load(HistoryReader& h) {
  principalsStale_ = false;  // the loaded values stand until the next assembly
  const auto wrinkle = h.ints(states_.size(), 0, static_cast<int>(kernels::WrinkleState::Slack));
  const auto values = h.reals(6 * states_.size());
  for (size_t k = 0; k < states_.size(); ++k) {
    const double* v = &values[6 * k];
    states_[k].state = static_cast<kernels::WrinkleState>(wrinkle[k]);
    states_[k].principalStress = Eigen::Vector2d(v[0], v[1]);
    states_[k].principalStrain = Eigen::Vector2d(v[2], v[3]);
    states_[k].principalResultant = Eigen::Vector2d(v[4], v[5]);
  }
}

}  // namespace chute
