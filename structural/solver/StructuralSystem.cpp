#include "solver/StructuralSystem.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>

#include "solver/TwoPartSplit.hpp"

namespace chute {

StructuralSystem::StructuralSystem(const Model& model, TermOptions options,
                                   std::vector<std::unique_ptr<Term>> extraTerms)
    : model_(&model),
      dofs_(model),
      list_(model, options, std::move(extraTerms)),
      terms_(list_.terms()),
      assembler_(dofs_),
      secondAssembler_(dofs_) {
  std::vector<char> watched(model.numNodes(), 0);
  for (const auto& t : terms_) {
    if (auto* e = t->events()) {
      events_.push_back(e);
      eventTerms_.push_back(t.get());
      drivesKinks_ = drivesKinks_ || e->drivesKinks();
      if (e->watchesExplicitMotion()) {
        watchesExplicitMotion_ = true;
        markCoupledNodes(*t, watched);
      }
    }
    if (t->dynamicCouplings()) dynamicCouplings_.push_back(t.get());
  }

  for (int n = 0; n < model.numNodes(); ++n)
    if (watched[n])
      for (int k = 0; k < 3; ++k) watchedDofs_.push_back(3 * n + k);
  for (const auto& t : terms_) searchesPerUpdate_ += t->searchesPerUpdate();
  for (int d = 0; d < dofs_.numDofs(); ++d)
    if (dofs_.eqOfDof(d) < 0) constrainedDofs_.push_back(d);
  freeNode_.assign(model.numNodes(), 0);
  for (int i = 0; i < model.numNodes(); ++i) {
    const auto& c = model.constraint[i];
    freeNode_[i] = !(c.fixed[0] && c.fixed[1] && c.fixed[2]);
  }

  std::vector<std::vector<int>> cliques;
  for (const auto& t : terms_) t->addCouplings(cliques);
  // Nodes no term touches (in no element, load or point mass) with a free dof: neither stiffness
  // nor mass there, so the equations are singular (the run refuses them, untouchedFreeNodes()).
  std::vector<char> touched(model.numNodes(), 0);
  for (const auto& c : cliques)
    for (int n : c) touched[n] = 1;
  for (int n = 0; n < model.numNodes(); ++n) {
    const auto& c = model.constraint[n];
    if (!touched[n] && !(c.fixed[0] && c.fixed[1] && c.fixed[2])) untouchedFreeNodes_.push_back(n);
  }
  assembler_.buildPattern(cliques);
  splitAssembly();
  splitSettling(freeNode_);
  std::vector<Term*> apart;
  for (const auto& t : terms_)
    if (t->commitsApart()) apart.push_back(t.get());
  if (apart.size() >= 2) {
    std::vector<int> own(apart.size());
    std::vector<double> cost(apart.size());
    for (size_t i = 0; i < apart.size(); ++i)
      own[i] = static_cast<int>(i), cost[i] = std::max(1.0, apart[i]->assemblyCost());
    const TwoPartSplit split = splitInTwo(own, cost);
    for (int p = 0; p < 2; ++p)
      for (int i : split.part[p]) commitParts_[p].push_back(apart[i]);
  }
}

// The watchers grouped by the free nodes of their couplings (the nodes they read and move), the
// groups dealt into two parts by the watchers' assembly costs (for the sliding groups, their
// elements and sliders: what their notes, searches and moves go over). On the C-9 with its slider
// the 28 lines fall into the four grommets' groups of seven (the confluence, which they all reach,
// is fixed); a free confluence makes one group, and the notes alone are then made in halves.
void StructuralSystem::splitSettling(const std::vector<char>& freeNodes) {
  std::vector<int> watchers;
  for (size_t i = 0; i < events_.size(); ++i)
    if (events_[i]->watchesExplicitMotion()) watchers.push_back(static_cast<int>(i));
  if (watchers.size() < 2) return;
  std::vector<std::vector<int>> nodesOf;
  std::vector<double> cost;
  for (int i : watchers) {
    std::vector<std::vector<int>> cliques;
    eventTerms_[i]->addCouplings(cliques);
    nodesOf.emplace_back();
    for (const auto& c : cliques) nodesOf.back().insert(nodesOf.back().end(), c.begin(), c.end());
    cost.push_back(std::max(1.0, eventTerms_[i]->assemblyCost()));
  }
  const TwoPartSplit split = splitInTwo(groupsBySharedFreeNodes(nodesOf, freeNodes), cost);
  if (!split.split()) return;
  for (int p = 0; p < 2; ++p)
    for (int k : split.part[p]) settleParts_[p].push_back(watchers[k]);
  settleFused_ = true;
  for (const auto& t : terms_)
    if (t->searchesPerUpdate() > 0 && !(t->events() && t->events()->watchesExplicitMotion()))
      settleFused_ = false;
}

// Terms that read only the model and state no assembly writes (Term::assemblesApart) may be
// assembled on the second thread; the others stay on the first. Costs are the terms' own
// estimates (Term::assemblyCost, per element relative to an explicit membrane triangle). Largest
// first, each to the lighter part, a tie to the second; the order of terms within a part is the
// term list's. The explicit step's own work between assemblies also runs on the first thread;
// giving that thread less assembly to make up for it was measured slower on the C-9 (the second
// thread then waits).
void StructuralSystem::splitAssembly() {
  // A term that assembles in halves is two items of half its cost; if both land in one part it
  // stays whole there.
  struct Item {
    double cost;
    Term* term;
  };
  std::vector<Item> movable;
  double first = 0.0;
  for (const auto& t : terms_) {
    if (!t->assemblesApart()) {
      first += t->assemblyCost();
    } else if (t->assemblesInHalves() && !halved_) {
      movable.push_back({0.5 * t->assemblyCost(), t.get()});
      movable.push_back({0.5 * t->assemblyCost(), t.get()});
    } else {
      movable.push_back({t->assemblyCost(), t.get()});
    }
  }
  std::stable_sort(movable.begin(), movable.end(),
                   [](const Item& a, const Item& b) { return a.cost > b.cost; });
  double second = 0.0;
  std::vector<const Term*> toSecond, toFirst;
  for (const Item& item : movable) {
    if (second <= first) {
      second += item.cost;
      toSecond.push_back(item.term);
    } else {
      first += item.cost;
      toFirst.push_back(item.term);
    }
  }
  auto in = [](const std::vector<const Term*>& v, const Term* t) {
    return std::find(v.begin(), v.end(), t) != v.end();
  };
  for (const auto& t : terms_) {
    const bool inSecond = in(toSecond, t.get()), inFirst = in(toFirst, t.get());
    if (inSecond && inFirst) {  // one half in each part
      halved_ = t.get();
      firstPart_.push_back(t.get());
      secondPart_.push_back(t.get());
    } else {
      (inSecond ? secondPart_ : firstPart_).push_back(t.get());
    }
  }
  if (secondPart_.empty()) return;
  secondAssembler_.buildPattern({});  // assemble() gives it the first's pattern when built
  runner_ = std::make_unique<TwoPartRunner>();
}

StructuralState StructuralSystem::initialState() const {
  const Model& m = *model_;
  StructuralState s;
  const int n = 3 * m.numNodes();
  s.x.resize(n);
  for (int i = 0; i < m.numNodes(); ++i) s.x.segment<3>(3 * i) = m.X[i] + m.u0[i];
  s.v.setZero(n);
  s.a.setZero(n);
  for (int d = 0; d < n; ++d)
    s.v[d] = dofs_.eqOfDof(d) < 0 ? m.constraint[d / 3].speed(d % 3, 0.0)
                                  : m.initialVelocity(d / 3)[d % 3];
  return s;
}

void StructuralSystem::prepareFor(const IntegrationTraits& traits) {
  for (const auto& t : terms_) t->prepareFor(traits);
}

std::vector<double> StructuralSystem::stiffnessBound(const Eigen::VectorXd& x, double t) const {
  std::vector<double> S = positionStiffnessBound(x, t);
  addStateStiffnessBound(x, t, S);
  return S;
}

std::vector<double> StructuralSystem::positionStiffnessBound(const Eigen::VectorXd& x,
                                                             double t) const {
  std::vector<double> S;
  if (hasTwoParts()) {
    std::vector<double> second;
    positionStiffnessBoundPart(x, t, 0, S);
    positionStiffnessBoundPart(x, t, 1, second);
    addBoundPart(S, second);
    return S;
  }
  S.assign(model_->numNodes(), 0.0);
  for (const auto& term : terms_)
    if (term->stiffnessBoundOfPositions()) term->addStiffnessBound(x, t, freeNode_, S);
  return S;
}

void StructuralSystem::addBoundPart(std::vector<double>& first, const std::vector<double>& second) {
  for (size_t i = 0; i < first.size(); ++i) first[i] += second[i];
}

void StructuralSystem::positionStiffnessBoundPart(const Eigen::VectorXd& x, double t, int part,
                                                  std::vector<double>& S) const {
  S.assign(model_->numNodes(), 0.0);
  for (Term* term : part == 0 ? firstPart_ : secondPart_) {
    if (!term->stiffnessBoundOfPositions()) continue;
    if (term == halved_)
      term->addStiffnessBoundHalf(x, t, freeNode_, S, part);
    else
      term->addStiffnessBound(x, t, freeNode_, S);
  }
}

void StructuralSystem::addStateStiffnessBound(const Eigen::VectorXd& x, double t,
                                              std::vector<double>& S) const {
  for (const auto& term : terms_)
    if (!term->stiffnessBoundOfPositions()) term->addStiffnessBound(x, t, freeNode_, S);
}

double StructuralSystem::frequencySquaredBound(const Eigen::VectorXd& x, double t,
                                               const std::vector<double>& nodalMass) const {
  double w2 = 0.0;
  for (const auto& term : terms_) w2 = std::max(w2, term->frequencySquaredBound(x, t, nodalMass));
  return w2;
}

bool StructuralSystem::settleExplicitMotion(const Eigen::VectorXd& x, Eigen::VectorXd& xEnd) {
  if (watchesExplicitMotion_) {
    // The motion at the watchers' nodes only (zero elsewhere): a pass over every dof at every
    // step for the few nodes they read.
    if (motion_.size() != xEnd.size()) motion_.setZero(xEnd.size());
    for (int d : watchedDofs_) motion_[d] = xEnd[d] - x[d];
  }
  if (!settleParts_[1].empty()) {
    // Each part's watchers in order; no watcher reads a node that one of the other part moves
    // (splitSettling), and the notes read x and motion_ alone, so the bits are those of the
    // sources one after the other.
    auto settle = [&](int part) {
      const auto& ids = settleParts_[part];
      for (int i : ids) events_[i]->noteExplicitMotion(x, motion_);
      for (int i : ids) events_[i]->afterExplicitMotion(x, motion_, xEnd);
      if (!settleFused_) return;
      if (searchesPerUpdate_ > 0)
        for (int i : ids) eventTerms_[i]->updateState(xEnd);
      for (int i : ids) events_[i]->onConverged(xEnd);
    };
    auto bothParts = [&] {
      runTwo([&] { settle(0); }, [&] { settle(1); });
      return 0;
    };
    if (settleFused_ && searchesPerUpdate_ > 0)
      timedSearch(bothParts);
    else
      bothParts();
    if (settleFused_) {
      // The other sources' moves at the step's end (the watchers' are made).
      bool elsewhere = false;
      for (size_t i = 0; i < events_.size(); ++i)
        if (!events_[i]->watchesExplicitMotion()) elsewhere |= events_[i]->onConverged(xEnd);
      return elsewhere;
    }
  } else if (watchesExplicitMotion_) {
    // The notes in two halves of the sources, at once where there are two threads (each writes
    // its own state; none reads what another's note or move writes: x and motion_ stay as they
    // are), then the moves in order.
    inHalves(static_cast<int>(events_.size()), [&](int begin, int end) {
      for (int i = begin; i < end; ++i)
        if (events_[i]->watchesExplicitMotion()) events_[i]->noteExplicitMotion(x, motion_);
    });
    for (auto* e : events_)
      if (e->watchesExplicitMotion()) e->afterExplicitMotion(x, motion_, xEnd);
  }
  updateState(xEnd);
  bool elsewhere = false;
  for (auto* e : events_) elsewhere |= e->onConverged(xEnd) && !e->watchesExplicitMotion();
  return elsewhere;
}

int StructuralSystem::updateState(const Eigen::VectorXd& x) {
  if (searchesPerUpdate_ == 0) return 0;  // no search without configuration-dependent state
  return timedSearch([&] {
    int changes = 0;
    for (const auto& t : terms_) changes += t->updateState(x);
    return changes;
  });
}

int StructuralSystem::timedSearch(const std::function<int()>& search) {
  ScopedTimer timer(timings_.search);
  ++timings_.searches;
  assembler_.work().sliderSearch += searchesPerUpdate_;
  return search();
}

void StructuralSystem::assemble(const EvalPoint& p, bool wantMatrix) {
  assemble(p, wantMatrix, nullptr, nullptr);
}

void StructuralSystem::assemble(const EvalPoint& at, bool wantMatrix,
                                const std::function<void()>& alongside,
                                const std::function<void(int)>* afterPart) {
  assembleParts(at, wantMatrix, alongside, false, afterPart);
}

void StructuralSystem::assembleForHalves(const EvalPoint& at,
                                         const std::function<void()>& alongside,
                                         const std::function<void(int)>* afterPart) {
  assembleParts(at, false, alongside, true, afterPart);
}

void StructuralSystem::residualNotSummed() {
  throw std::logic_error(
      "StructuralSystem: the residual was read before useResidualInHalves summed its parts");
}

void StructuralSystem::inHalves(int n, const std::function<void(int, int)>& use) {
  const int half = n / 2;
  runTwo([&] { use(0, half); }, [&] { use(half, n); });
}

void StructuralSystem::useResidualInHalves(const std::function<void(int, int)>& use) {
  const int n = numEquations(), half = n / 2;
  if (!sumPending_) {
    inHalves(n, use);
    return;
  }
  // Each half summed where it is used: its second part's residual added just before.
  auto piece = [&](int begin, int end) {
    assembler_.accumulateResidual(secondAssembler_, begin, end);
    use(begin, end);
  };
  runTwo([&] { piece(0, half); }, [&] { piece(half, n); });
  assembler_.accumulateWork(secondAssembler_);
  sumPending_ = false;
}

void StructuralSystem::assembleParts(const EvalPoint& at, bool wantMatrix,
                                     const std::function<void()>& alongside, bool forHalves,
                                     const std::function<void(int)>* afterPart) {
  ScopedTimer timer(timings_.assembly);
  sumPending_ = false;
  ++timings_.assemblies;
  // Couplings that move (contact pairs): a pattern that no longer covers them is built again
  // before the next matrix (and the linear solver analyses it afresh).
  for (auto* t : dynamicCouplings_) patternStale_ |= t->updateCouplings(at.x);
  EvalPoint p = at;
  p.couplingsUpdated = true;
  if (wantMatrix && patternStale_) {
    std::vector<std::vector<int>> cliques;
    for (const auto& t : terms_) t->addCouplings(cliques);
    assembler_.buildPattern(cliques);
    if (!secondPart_.empty()) secondAssembler_.buildPattern({});
    patternStale_ = false;
  }
  // For halves with two parts, each part's residual is cleared on its thread (below).
  const bool split = forHalves && !wantMatrix && !secondPart_.empty();
  sumPending_ = split;  // from here: the residual is read only once useResidualInHalves summed it
  if (split)
    assembler_.beginWithoutClearing(false);
  else
    assembler_.begin(wantMatrix);
  // captureStepLoads: the terms doing external work also add their residual over all dofs, each
  // part into its own vector (the parts may run on two threads).
  const bool capture = captureLoads_ && !wantMatrix && p.explicitStep > 0.0;
  capturedLoadsT_ = std::numeric_limits<double>::quiet_NaN();
  // half: which half of halved_ the part assembles (the first's 0, the second's 1).
  auto assemblePart = [&](const auto& part, SystemAssembler& out, Eigen::VectorXd& loads,
                          int half) {
    if (capture) loads.setZero(3 * model_->numNodes());
    out.captureFusedLoads(capture ? &loads : nullptr);
    for (const auto& t : part) {
      const bool loadTerm = capture && t->doesExternalWork();
      if (loadTerm) out.captureAllDofs(&loads);
      if (&*t == halved_)
        halved_->assembleHalf(p, out, half);
      else
        t->assemble(p, out);
      if (loadTerm) out.captureAllDofs(nullptr);
    }
    out.captureFusedLoads(nullptr);
  };
  auto keepLoads = [&] {
    if (!capture) return;
    if (!secondPart_.empty()) partLoads_[0] += partLoads_[1];
    capturedLoadsT_ = p.t;
  };
  if (secondPart_.empty()) {
    assemblePart(terms_, assembler_, partLoads_[0], 0);
    if (alongside) alongside();
    keepLoads();
    return;
  }
  if (wantMatrix && !secondAssembler_.hasPattern()) secondAssembler_.sharePatternOf(assembler_);
  if (split)
    secondAssembler_.beginWithoutClearing(false);
  else
    secondAssembler_.begin(wantMatrix);
  if (halved_) {
    EvalPoint before = p;
    before.inHalves = &inTwoHalves_;
    halved_->beforeHalves(before, assembler_);
  }
  // alongside() on whichever thread finishes its part first (the other one's part is the longer).
  std::atomic<bool> taken{false};
  auto then = [&] {
    if (alongside && !taken.exchange(true)) alongside();
  };
  runner_->run(
      [&] {
        if (split) assembler_.clearResidual();
        assemblePart(firstPart_, assembler_, partLoads_[0], 0);
        if (afterPart) (*afterPart)(0);
        then();
      },
      [&] {
        if (split) secondAssembler_.clearResidual();
        assemblePart(secondPart_, secondAssembler_, partLoads_[1], 1);
        if (afterPart) (*afterPart)(1);
        then();
      });
  if (halved_ && halved_->afterHalves(p)) {
    auto part = [&](SystemAssembler& out, Eigen::VectorXd& loads, int half) {
      out.captureFusedLoads(capture ? &loads : nullptr);
      halved_->afterHalvesPart(p, out, half);
      out.captureFusedLoads(nullptr);
    };
    runTwo([&] { part(assembler_, partLoads_[0], 0); },
           [&] { part(secondAssembler_, partLoads_[1], 1); });
  }
  if (!split) assembler_.accumulate(secondAssembler_);  // else useResidualInHalves sums them
  keepLoads();
}

void StructuralSystem::runTwo(const std::function<void()>& first,
                              const std::function<void()>& second) {
  if (runner_) {
    runner_->runOther(first, second);
  } else {
    first();
    second();
  }
}

StructuralSystem::NodalForces StructuralSystem::nodalForces(const Eigen::VectorXd& x,
                                                            const Eigen::VectorXd& v,
                                                            const Eigen::VectorXd& a, double t,
                                                            bool inertia) {
  const long n = x.size();
  NodalForces f;
  auto residualOver = [&](bool loadTerms, double load) {
    Eigen::VectorXd out = Eigen::VectorXd::Zero(n);
    const EvalPoint p = EvalPoint::state(x, v, a, t).withInertia(inertia).withLoadFactor(load);
    assembler_.captureAllDofs(&out);
    assembler_.begin(false);
    for (const auto& term : terms_)
      if (term->loadDependent() == loadTerms) term->assemble(p, assembler_);
    assembler_.captureAllDofs(nullptr);
    return out;
  };
  // r = f_int + M a - f_ext: the supports supply r at constrained dofs. Loads are the
  // load-factor-scaled part, f_ext = r(lambda = 0) - r(lambda = 1), nonzero only for the terms
  // that depend on the load factor: those are evaluated twice, the others (membranes, cables
  // without gravity) once.
  const Eigen::VectorXd loaded = residualOver(true, 1.0);
  const Eigen::VectorXd full = residualOver(false, 1.0) + loaded;
  f.reaction = Eigen::VectorXd::Zero(n);
  for (long d = 0; d < n; ++d)
    if (dofs_.eqOfDof(static_cast<int>(d)) < 0) f.reaction[d] = full[d];
  f.applied = residualOver(true, 0.0) - loaded;
  return f;
}

Eigen::VectorXd StructuralSystem::residualOverAllDofs(const EvalPoint& p, bool allTerms) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(p.x.size());
  assembler_.captureAllDofs(&out);
  assembler_.begin(false);
  for (const auto& term : terms_)
    if (allTerms || term->doesExternalWork()) term->assemble(p, assembler_);
  assembler_.captureAllDofs(nullptr);
  return out;
}

bool StructuralSystem::symmetric() const {
  return std::all_of(terms_.begin(), terms_.end(),
                     [](const auto& t) { return t->symmetricJacobian(); });
}

double StructuralSystem::passageFraction(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) {
  double f = 1.0;
  for (auto* e : events_) f = std::min(f, e->passageFraction(x, dx));
  return f;
}

double StructuralSystem::stepEventFraction(const Eigen::VectorXd& start,
                                           const Eigen::VectorXd& motion) {
  double f = 1.0;
  for (auto* e : events_) f = std::min(f, e->stepEventFraction(start, motion));
  return f;
}

bool StructuralSystem::crossNow(Eigen::VectorXd& x) {
  bool changed = false;
  for (auto* e : events_) changed |= e->crossNow(x);
  return changed;
}

bool StructuralSystem::drivesKinks() const {
  return drivesKinks_;
}

int StructuralSystem::crossDriven(const Eigen::VectorXd& from, Eigen::VectorXd& to) {
  int changes = 0;
  for (auto* e : events_) changes += e->crossDriven(from, to);
  return changes;
}

double StructuralSystem::displacementFloor() const {
  double f = 0.0;
  for (const auto* e : events_) f = std::max(f, e->displacementFloor());
  return f;
}

bool StructuralSystem::onConverged(Eigen::VectorXd& x) {
  bool changed = false;
  for (auto* e : events_) changed |= e->onConverged(x);
  return changed;
}

EnergyBreakdown StructuralSystem::energy(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                                         double t) const {
  ++energyEvaluations_;
  EnergyBreakdown e;
  for (const auto& term : terms_) term->addEnergy(x, v, t, e);
  return e;
}

EnergyBreakdown StructuralSystem::energyOnTwoThreads(const Eigen::VectorXd& x,
                                                     const Eigen::VectorXd& v, double t) {
  if (secondPart_.empty()) return energy(x, v, t);
  ++energyEvaluations_;
  EnergyBreakdown a, b;
  // The halved term's energy in its two halves, one in each part (as its assembly).
  runTwo(
      [&] {
        for (auto* term : firstPart_)
          if (term == halved_)
            term->addEnergyHalf(x, v, t, a, 0);
          else
            term->addEnergy(x, v, t, a);
      },
      [&] {
        for (auto* term : secondPart_)
          if (term == halved_)
            term->addEnergyHalf(x, v, t, b, 1);
          else
            term->addEnergy(x, v, t, b);
      });
  a.kinetic += b.kinetic, a.strain += b.strain, a.gravity += b.gravity, a.supplied += b.supplied;
  return a;
}

void StructuralSystem::commit(const CommitPoint& c) {
  CommitPoint at = c;
  if (!at.inHalves) at.inHalves = &inTwoHalves_;
  if (commitParts_[0].empty()) {
    for (const auto& t : terms_) t->commit(at);
    return;
  }
  for (const auto& t : terms_)
    if (!t->commitsApart()) t->commit(at);
  auto part = [&](int p) {
    for (Term* t : commitParts_[p]) t->commit(at);
  };
  runTwo([&] { part(0); }, [&] { part(1); });
}
void StructuralSystem::revert() {
  for (const auto& t : terms_) t->revert();
}

SystemSnapshot StructuralSystem::saveState(const StructuralState& s) const {
  SystemSnapshot snap;
  snap.state = s;
  for (const auto& t : terms_) {
    snap.termNames.emplace_back(t->name());
    snap.histories.emplace_back();
    t->save(snap.histories.back());
  }
  return snap;
}

void StructuralSystem::prescribeMotion(StructuralState& s) const {
  const Model& m = *model_;
  for (int d : constrainedDofs_) {
    const auto& c = m.constraint[d / 3];
    s.x[d] = c.position(m.X[d / 3][d % 3] + m.u0[d / 3][d % 3], d % 3, s.t);
    s.v[d] = c.speed(d % 3, s.t);
    s.a[d] = c.acceleration(d % 3, s.t);
  }
}

StructuralState StructuralSystem::loadState(const SystemSnapshot& snap) {
  const auto& s = snap.state;
  const long n = 3L * model_->numNodes();
  if (s.x.size() != n || s.v.size() != n || s.a.size() != n)
    throw HistoryError("state of " + std::to_string(s.x.size() / 3) + " nodes for a model of " +
                       std::to_string(n / 3));
  if (!s.x.allFinite() || !s.v.allFinite() || !s.a.allFinite() || !std::isfinite(s.t))
    throw HistoryError("state not finite");
  if (!std::isfinite(s.control.dt) || !(s.control.dt > 0.0) ||
      !std::isfinite(s.control.eventStep) || s.control.eventStep < 0.0 ||
      s.control.successesSinceCut < 0)
    throw HistoryError("step control out of range");
  if (snap.histories.size() != terms_.size() || snap.termNames.size() != terms_.size())
    throw HistoryError("the snapshot has " + std::to_string(snap.histories.size()) +
                       " terms, the model " + std::to_string(terms_.size()));
  for (size_t k = 0; k < terms_.size(); ++k)
    if (snap.termNames[k] != terms_[k]->name())
      throw HistoryError("term " + std::to_string(k) + " is " + snap.termNames[k] +
                         " in the snapshot, " + terms_[k]->name() + " in the model");
  // Every record is checked on a copy of the histories first: a bad one changes nothing.
  std::vector<History> current(terms_.size());
  for (size_t k = 0; k < terms_.size(); ++k) terms_[k]->save(current[k]);
  try {
    for (size_t k = 0; k < terms_.size(); ++k) {
      HistoryReader r(snap.histories[k], snap.termNames[k]);
      terms_[k]->load(r);
      r.finish();
    }
  } catch (...) {
    for (size_t k = 0; k < terms_.size(); ++k) {
      HistoryReader r(current[k], terms_[k]->name());
      terms_[k]->load(r);
    }
    throw;
  }
  return s;
}

void StructuralSystem::addToDofs(const Eigen::VectorXd& eqVec, Eigen::VectorXd& dofVec,
                                 double scale) const {
  for (int d = 0; d < dofs_.numDofs(); ++d) {
    const int e = dofs_.eqOfDof(d);
    if (e >= 0) dofVec[d] += scale * eqVec[e];
  }
}

Eigen::VectorXd StructuralSystem::gatherEquations(const Eigen::VectorXd& dofVec) const {
  Eigen::VectorXd out(dofs_.numEquations());
  for (int d = 0; d < dofs_.numDofs(); ++d) {
    const int e = dofs_.eqOfDof(d);
    if (e >= 0) out[e] = dofVec[d];
  }
  return out;
}

}  // namespace chute
