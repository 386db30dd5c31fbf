#include "solver/CentralDifference.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <sstream>

namespace chute {

namespace {

// EX1's first half and EX2's velocity over all dofs: v_{n+1/2} = v_n + dt/2 a_n, x_{n+1} = x_n +
// dt v_{n+1/2}, v* = v_n + dt a_n; kDamped: EX7's damped positions x_{n+1} + beta v* in the same
// pass (the dofs the step moves afterwards are made again where they move). The buffers are
// distinct (the state's, the next state's, the step's own): restrict on the parameters lets the
// compiler take two dofs at a time, which it did not for the same loop inline (one dof at a time:
// 40 % of the step's own work, perf).
template <bool kDamped>
void predict(int nd, double dt, double beta, const double* __restrict x, const double* __restrict v,
             const double* __restrict a, double* __restrict vHalf, double* __restrict xNext,
             double* __restrict vStar, double* __restrict xDamped) {
  const double halfStep = 0.5 * dt;
  for (int d = 0; d < nd; ++d) {
    vHalf[d] = v[d] + halfStep * a[d];
    xNext[d] = x[d] + dt * vHalf[d];
    vStar[d] = v[d] + dt * a[d];
    if constexpr (kDamped) xDamped[d] = xNext[d] + beta * vStar[d];
  }
}

// EX1's second half over one run of free dofs with consecutive equations: a_{n+1} = -r / m,
// v_{n+1} = v_{n+1/2} + dt/2 a_{n+1}. Returns the sum of the run's x, a and v times 0: x 0 is 0
// for a finite x and NaN for an infinity or a NaN, so the sum is 0 exactly when all are finite
// (before, a pass of its own over each of x, v and a).
double correct(int count, double halfStep, const double* __restrict r, const double* __restrict m,
               const double* __restrict vHalf, const double* __restrict x, double* __restrict a,
               double* __restrict v) {
  double nonFinite = 0.0;
  for (int i = 0; i < count; ++i) {
    a[i] = -r[i] / m[i];
    v[i] = vHalf[i] + halfStep * a[i];
    nonFinite += x[i] * 0.0 + a[i] * 0.0 + v[i] * 0.0;
  }
  return nonFinite;
}

}  // namespace

CentralDifference::CentralDifference(StructuralSystem& sys, ExplicitSettings settings,
                                     double maxStep)
    : sys_(&sys),
      settings_(settings),
      maxStep_(maxStep),
      massAssembler_(sys.dofs()),
      movingMassAssembler_(sys.dofs()) {
  sys.prepareFor(IntegrationTraits{true, false});
  massAssembler_.buildPattern({});
  movingMassAssembler_.buildPattern({});
  for (const auto& t : sys.terms()) {
    if (t->massMovesWithPositions())
      movingMassTerms_.push_back(t.get());
    else if (t->massChangesAtCommit())
      committedMass_.push_back(CommittedMass{t.get(), {}, {}});
    else
      fixedMassTerms_.push_back(t.get());
  }
  {
    std::vector<char> touched(sys.dofs().numDofs() / 3, 0);
    for (auto* t : movingMassTerms_) markCoupledNodes(*t, touched);
    for (int n = 0; n < static_cast<int>(touched.size()); ++n)
      for (int k = 0; k < 3; ++k) {
        if (const int e = sys.dofs().eq(n, k); touched[n] && e >= 0) movingMassEqs_.push_back(e);
        if (touched[n]) movingMassDofs_.push_back(3 * n + k);
      }
    // Most of the dofs (a canopy's air, docs/flight.md FL11): the whole vector is the key, its
    // copy a vectorised pass, cheaper than one through the list.
    if (2 * movingMassDofs_.size() > static_cast<size_t>(sys.dofs().numDofs()))
      movingMassDofs_.clear(), wholeKey_ = true;
    // Where each committed mass goes (CommittedMass). An equation with one varying mass, a
    // committed one: set to the base plus it. An equation with more (a moving mass and a
    // committed one, two committed ones): its varying masses summed first, in the terms' order,
    // and the base added last, the sums the moving mass's assembly made when it held them all.
    const int numEq = sys.numEquations();
    std::vector<int> sources(numEq, 0);
    std::vector<char> moving(numEq, 0);
    for (int e : movingMassEqs_) moving[e] = 1, sources[e] = 1;
    for (const CommittedMass& c : committedMass_)
      for (int n : c.term->committedMassNodes())
        for (int k = 0; k < 3; ++k)
          if (const int e = sys.dofs().eq(n, k); e >= 0) ++sources[e];
    for (CommittedMass& c : committedMass_) {
      const std::vector<int>& nodes = c.term->committedMassNodes();
      for (size_t i = 0; i < nodes.size(); ++i) {
        const int n = nodes[i], first = sys.dofs().freeNodeEq(n), index = static_cast<int>(i);
        if (first >= 0 && sources[first] == 1 && sources[first + 1] == 1 &&
            sources[first + 2] == 1) {
          c.setNodes.emplace_back(first, index);
          continue;
        }
        for (int k = 0; k < 3; ++k)
          if (const int e = sys.dofs().eq(n, k); e >= 0)
            c.equations.push_back(CommittedMass::Equation{e, index, sources[e] > 1});
      }
    }
    for (int e = 0; e < numEq; ++e) {
      if (sources[e] > 1) sharedMassEqs_.emplace_back(e, moving[e] != 0);
      if (sources[e] > 0 && !moving[e]) committedMassEqs_.push_back(e);
    }
    if (!sharedMassEqs_.empty()) varyingMass_.setZero(numEq);
  }
  const Model& m = sys.model();
  freeNode_.assign(m.numNodes(), 0);
  for (int d = 0; d < sys.dofs().numDofs(); ++d)
    if (sys.dofs().eqOfDof(d) >= 0) freeNode_[d / 3] = 1;
  addedEq_.setZero(sys.numEquations());
  x0_ = sys.initialState().x;
  // The nodes' own stable steps and mass scaling (EX8) both read the mass and the stiffness
  // bounds at the start positions, before any mass is added.
  if (sys.numEquations() > 0) {
    const Eigen::VectorXd massEq = lumpedMass(x0_, 0.0, false);  // without the added mass
    const auto S = sys.stiffnessBound(x0_, 0.0);
    const std::vector<double> mass = nodalMass(massEq);
    const std::vector<double> nodalSteps = recordNodalSteps(S, mass);
    if (settings_.massScalingQuantile > 0.0 && !nodalSteps.empty())
      // The nodes whose own step is below the quantile's get the mass that lifts it there.
      settings_.targetStep = settings_.safety * quantile(nodalSteps, settings_.massScalingQuantile);
    if (settings_.targetStep > 0.0) scaleMass(S, mass);
    cacheValid_ = false;  // the mass evaluated above is without the added mass
  }
  record_.targetStep = settings_.targetStep;
  if (sys.numEquations() > 0) lumpedMass(x0_, 0.0);  // refuses massless nodes at the start
}

void CentralDifference::scaleMass(const std::vector<double>& S, const std::vector<double>& mass) {
  // EX8: the least nodal mass for which the node's bound S_i / m_i allows the target step with
  // the safety factor, m_i >= S_i (target / (2 safety))^2.
  const Model& m = sys_->model();
  const double r = settings_.targetStep / (2.0 * settings_.safety);
  const auto part = nodePartNames(m);
  std::map<std::string, double> byPart;
  for (int n = 0; n < m.numNodes(); ++n) {
    if (!freeNode_[n]) continue;
    const double add = std::max(0.0, S[n] * r * r - mass[n]);
    if (add <= 0.0) continue;
    byPart[part[n]] += add;
    ++record_.scaledNodes;
    for (int k = 0; k < 3; ++k)
      if (const int e = sys_->dofs().eq(n, k); e >= 0) addedEq_[e] = add;
  }
  record_.addedMass.assign(byPart.begin(), byPart.end());
  std::map<std::string, double> partMass;
  for (int n = 0; n < m.numNodes(); ++n)
    if (freeNode_[n] && byPart.count(part[n])) partMass[part[n]] += mass[n];
  record_.partMass.assign(partMass.begin(), partMass.end());
  for (const auto& [name, added] : record_.addedMass) record_.totalAddedMass += added;
  massBaseStale_ = true;
}

double CentralDifference::quantile(const std::vector<double>& sorted, double q) {
  return sorted[static_cast<size_t>(q * static_cast<double>(sorted.size() - 1))];
}

std::vector<double> CentralDifference::recordNodalSteps(const std::vector<double>& S,
                                                        const std::vector<double>& mass) {
  std::vector<double> steps;
  for (size_t n = 0; n < mass.size(); ++n)
    if (freeNode_[n] && mass[n] > 0.0 && S[n] > 0.0)
      steps.push_back(2.0 * std::sqrt(mass[n] / S[n]));
  if (steps.empty()) return steps;
  std::sort(steps.begin(), steps.end());
  record_.nodalSteps = {steps.front(), quantile(steps, 0.01), quantile(steps, 0.1),
                        quantile(steps, 0.5)};
  return steps;
}

Eigen::VectorXd CentralDifference::massOf(const std::vector<Term*>& terms, const Eigen::VectorXd& x,
                                          double t) {
  const long n = x.size();
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n), ones = Eigen::VectorXd::Ones(n);
  // Residual-only evaluations (no Jacobian): the inertia M a is the only part linear in a, so
  // r(a = 1) - r(a = 0) is M 1, the row sums of the mass (EX2).
  auto residualWith = [&](const Eigen::VectorXd& a) {
    const EvalPoint p = EvalPoint::inertiaOf(x, zero, a, t, false);
    massAssembler_.begin(false);
    for (auto* term : terms) term->assemble(p, massAssembler_);
    return Eigen::VectorXd(massAssembler_.residual());
  };
  return residualWith(ones) - residualWith(zero);
}

int CentralDifference::cutSets(double t) const {
  const Model& m = sys_->model();
  return static_cast<int>(std::count_if(m.lineSets.begin(), m.lineSets.end(),
                                        [t](const LineSet& s) { return s.cutBy(t); }));
}

const Eigen::VectorXd& CentralDifference::lumpedMass(const Eigen::VectorXd& x, double t,
                                                     bool check) {
  const int cuts = cutSets(t);
  if (cuts != fixedMassCuts_) {
    // Cables, membranes and point masses: a mass that does not move with the positions. It is
    // evaluated at the start positions (not at x) so that it is the same bits in a run and in
    // its restart; only a cut changes it.
    fixedMass_ = massOf(fixedMassTerms_, x0_, t);
    fixedMassCuts_ = cuts;
    cacheValid_ = false;
    massBaseStale_ = true;
  }
  if (massBaseStale_) {
    // The mass that does not move, and whether it is positive on every equation the moving mass
    // does not touch: what the moving mass changes is then all that a step evaluates and checks.
    massBase_ = fixedMass_ + addedEq_;
    cachedMass_ = massBase_;
    std::vector<char> moving(massBase_.size(), 0);
    for (int e : movingMassEqs_) moving[e] = 1;
    for (int e : committedMassEqs_) moving[e] = 1;
    basePositive_ = true;
    for (long e = 0; e < massBase_.size(); ++e)
      if (!moving[e] && !(massBase_[e] > 0.0)) basePositive_ = false;
    for (CommittedMass& c : committedMass_) {
      c.basePositive = true;
      for (const auto& [first, index] : c.setNodes)
        for (int k = 0; k < 3; ++k) c.basePositive &= massBase_[first + k] > 0.0;
    }
    massBaseStale_ = false;
  }
  // A sliding element's lumped mass follows the slider's split (F10): evaluated at x (the
  // step's end positions are the next step's start: evaluated once for both).
  auto samePositions = [&] {
    if (wholeKey_) return cachedX_.size() == x.size() && cachedX_ == x;
    for (size_t k = 0; k < movingMassDofs_.size(); ++k)
      if (!(cachedX_[static_cast<long>(k)] == x[movingMassDofs_[k]])) return false;
    return true;
  };
  if (!(cacheValid_ && cachedT_ == t && samePositions())) {
    if (!movingMassTerms_.empty()) {
      // M(x) 1 directly: the terms whose mass moves evaluate only their inertia when asked.
      if (zeroDofs_.size() != x.size()) zeroDofs_ = Eigen::VectorXd::Zero(x.size());
      if (onesDofs_.size() != x.size()) onesDofs_ = Eigen::VectorXd::Ones(x.size());
      const EvalPoint p = EvalPoint::inertiaOf(x, zeroDofs_, onesDofs_, t, true);
      movingMassAssembler_.beginOn(movingMassEqs_);
      for (auto* term : movingMassTerms_) term->assemble(p, movingMassAssembler_);
      // Only the moving mass's equations: the others' residual is 0, and m + 0 is m (the fixed
      // and added masses are never -0); the others keep massBase_. Each is checked for a positive
      // mass as it is formed (the base's others when it was formed); refuseMassless, which names
      // the nodes, only when one is not.
      const Eigen::VectorXd& moving = movingMassAssembler_.residual();
      bool positive = true;
      for (int e : movingMassEqs_) {
        const double m = massBase_[e] + moving[e];
        cachedMass_[e] = m;
        positive &= m > 0.0;
      }
      movingPositive_ = positive;
    }
    if (!committedMass_.empty()) {
      // The masses that change at commit, as last committed: no assembly (their per-node values
      // straight to their equations), the same sums as the moving mass's (base + mass).
      bool positive = true;
      double* mass = cachedMass_.data();
      const double* base = massBase_.data();
      double* varying = varyingMass_.data();
      for (const auto& [e, fromMoving] : sharedMassEqs_)
        varying[e] = fromMoving ? movingMassAssembler_.residual()[e] : 0.0;
      for (const CommittedMass& c : committedMass_) {
        const double* nodeMass = c.term->committedNodalMass();
        if (c.basePositive) {
          // A positive base plus a mass not negative is positive: one test per node.
          for (const auto& [first, index] : c.setNodes) {
            const double m = nodeMass[index];
            mass[first] = base[first] + m, mass[first + 1] = base[first + 1] + m,
            mass[first + 2] = base[first + 2] + m;
            positive &= m >= 0.0;
          }
        } else {
          for (const auto& [first, index] : c.setNodes) {
            const double m = nodeMass[index];
            const double m0 = base[first] + m, m1 = base[first + 1] + m, m2 = base[first + 2] + m;
            mass[first] = m0, mass[first + 1] = m1, mass[first + 2] = m2;
            positive &= (m0 > 0.0) & (m1 > 0.0) & (m2 > 0.0);
          }
        }
        for (const auto& eq : c.equations) {
          if (eq.shared) {
            varying[eq.eq] += nodeMass[eq.node];
            continue;
          }
          mass[eq.eq] = base[eq.eq] + nodeMass[eq.node];
          positive &= mass[eq.eq] > 0.0;
        }
      }
      for (const auto& [e, fromMoving] : sharedMassEqs_) {
        mass[e] = base[e] + varying[e];
        positive &= mass[e] > 0.0;
      }
      committedPositive_ = positive;
    }
    if (wholeKey_) {
      cachedX_ = x;
    } else {
      cachedX_.resize(static_cast<long>(movingMassDofs_.size()));
      for (size_t k = 0; k < movingMassDofs_.size(); ++k)
        cachedX_[static_cast<long>(k)] = x[movingMassDofs_[k]];
    }
    cachedT_ = t;
    cacheValid_ = true;
    if (check && !(basePositive_ && movingPositive_ && committedPositive_))
      refuseMassless(cachedMass_);
  }
  return cachedMass_;
}

const std::vector<double>& CentralDifference::nodalMass(const Eigen::VectorXd& massEq) {
  const int nodes = sys_->model().numNodes();
  nodalMass_.resize(nodes);
  const DofMap& dofs = sys_->dofs();
  for (int n = 0; n < nodes; ++n) {
    double least = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k)
      if (const int e = dofs.eq(n, k); e >= 0) least = std::min(least, massEq[e]);
    nodalMass_[n] = std::isfinite(least) ? least : 0.0;
  }
  return nodalMass_;
}

void CentralDifference::refuseMassless(const Eigen::VectorXd& massEq) const {
  // Every equation is a free dof of a node: all positive is the common case, checked at every
  // step in one pass; the nodes are named only when it fails.
  if (massEq.size() == 0 || massEq.minCoeff<Eigen::PropagateNaN>() > 0.0) return;
  const Model& m = sys_->model();
  std::vector<int> massless;
  for (int n = 0; n < m.numNodes(); ++n)
    for (int k = 0; k < 3; ++k)
      if (const int e = sys_->dofs().eq(n, k); e >= 0 && !(massEq[e] > 0.0)) {
        massless.push_back(n);
        break;
      }
  if (massless.empty()) return;
  const std::string names = nodeNames(m, massless);
  // A mass that is not a number (a density or stiffness out of scale: E = 1e300 overflows the
  // mass scaling) is not a missing one: say which.
  bool notFinite = false;
  for (int n : massless)
    for (int k = 0; k < 3; ++k)
      if (const int e = sys_->dofs().eq(n, k); e >= 0 && !std::isfinite(massEq[e]))
        notFinite = true;
  if (notFinite)
    throw MasslessNodesError(
        "solver.integrator = \"central_difference\": " + std::to_string(massless.size()) +
        " free node(s) whose mass is not a finite number (" + names +
        "): a density, E or area out of scale (the mass of an element, or its mass scaling "
        "with solver.target_dt, overflowed)");
  throw MasslessNodesError(
      "solver.integrator = \"central_difference\": " + std::to_string(massless.size()) +
      " free node(s) without mass (" + names +
      "): explicit integration needs a mass at every free node (give the lines or fabric a "
      "density, add a point mass, set solver.target_dt for mass scaling, or use an implicit "
      "integrator; a stiffness out of scale, E x thickness beyond 1e16 times the mass, hides the "
      "mass the same way: it is read as r(a = 1) - r(a = 0), EX2)");
}

void CentralDifference::computeAcceleration(StructuralState& s) {
  if (sys_->numEquations() == 0) return;
  sys_->updateState(s.x);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(s.x.size());
  const EvalPoint p = EvalPoint::explicitForces(s.x, s.v, zero, s.t, 0.0);  // EX2: at a = 0
  sys_->assemble(p, false);
  const Eigen::VectorXd& massEq = lumpedMass(s.x, s.t);
  const Eigen::VectorXd& r = sys_->residual();
  for (int d = 0; d < sys_->dofs().numDofs(); ++d)
    if (const int e = sys_->dofs().eqOfDof(d); e >= 0) s.a[d] = -r[e] / massEq[e];
}

double CentralDifference::chooseStep(double lastStep, const Eigen::VectorXd& x, double t) {
  const double maxStep = maxStep_;
  const Eigen::VectorXd& massEq = lumpedMass(x, t);
  std::vector<double> S;
  if (boundAheadT_ == t && boundAheadX_.size() == x.size() && boundAheadX_ == x) {
    // Made alongside the last step's assembly at this (x, t); in parts, positionStiffnessBound's
    // sum of them.
    if (boundInParts_) {
      S = std::move(boundParts_[0]);
      StructuralSystem::addBoundPart(S, boundParts_[1]);
    } else {
      S = std::move(boundAhead_);
    }
    sys_->addStateStiffnessBound(x, t, S);
  } else {
    S = sys_->stiffnessBound(x, t);
  }
  boundAheadT_ = -1.0;
  const std::vector<double>& mass = nodalMass(massEq);
  auto est = chute::stableStep(S, mass, freeNode_);
  // Modes over many nodes that the nodal bounds do not see (EX5).
  const double w2 = sys_->frequencySquaredBound(x, t, mass);
  if (w2 > 0.0 && 2.0 / std::sqrt(w2) < est.dt) est.dt = 2.0 / std::sqrt(w2), est.node = -1;
  const double stable = settings_.safety * dampedStableStep(est.dt, settings_.stiffnessDamping);
  // EX5: the step changes only when the stable step leaves [step, 1.25 step], and then to 0.9
  // of it. A step that followed the estimate from step to step near the stability limit mixes
  // amplification matrices of different steps, whose product can grow (their eigenvalues lie on
  // the unit circle but they are far from normal): measured on bead_1, it pumped energy into the
  // rope's axial vibration until the rope went slack.
  double dt = lastStep;
  if (dt > stable || dt < 0.8 * stable) dt = 0.9 * stable;
  dt = std::min(dt, maxStep);
  if (record_.history.empty() || dt < record_.least) {
    record_.least = dt;
    record_.limitingNode = est.node;
  }
  record_.largest = std::max(record_.largest, dt);
  if (record_.history.empty() || std::abs(dt / record_.history.back().second - 1.0) > 0.05)
    record_.history.emplace_back(t, dt);
  return dt;
}

std::optional<StepEstimate> CentralDifference::estimateStep(const StructuralState& s) {
  if (sys_->numEquations() == 0) return std::nullopt;
  const Eigen::VectorXd& massEq = lumpedMass(s.x, s.t);
  const auto est = chute::stableStep(sys_->stiffnessBound(s.x, s.t), nodalMass(massEq), freeNode_);
  StepEstimate e;
  e.undamped = est.dt;
  e.limitingNode = est.node;
  // EX5: a step that leaves the band is set to 0.9 of the stable step.
  e.dt = std::min(maxStep_,
                  0.9 * settings_.safety * dampedStableStep(est.dt, settings_.stiffnessDamping));
  return e;
}

StepResult CentralDifference::step(StructuralState& s, double stop, StepCounters& counters) {
  if (counters.steps % kStableStepEvery == 0 || sys_->model().hasCutAt(s.t)) {
    ScopedTimer timer(sys_->timings().stableStep);
    s.control.dt = chooseStep(s.control.dt, s.x, s.t);
  }
  // The next step estimates (if this one is accepted and counted): its bound from this step's
  // end, alongside this step's assembly.
  boundAheadWanted_ = (counters.steps + 1) % kStableStepEvery == 0;
  StepResult result;
  const double h = std::min(s.control.dt, stop - s.t);
  result.reachesStop = h == stop - s.t;
  if (!(h > 0.0) || s.t + h == s.t) {
    // A stable step lost in the time's rounding (an absurd stiffness, density or damping) would
    // repeat the same state for ever.
    std::ostringstream why;
    why.precision(9);
    why << "the stable step " << s.control.dt << " does not move time at t = " << s.t;
    result.accepted = false;
    result.failure = why.str();
    return result;
  }
  const NewtonReport rep = advance(s, h);
  if (!rep.converged) {
    std::ostringstream why;
    why.precision(9);
    why << "unstable explicit step at t = " << s.t << " (" << rep.failure << ")";
    result.accepted = false;
    result.failure = why.str();
  }
  return result;
}

NewtonReport CentralDifference::advance(StructuralState& s, double dt) {
  NewtonReport rep;
  const DofMap& dofs = sys_->dofs();
  const int nd = dofs.numDofs();
  // n: the state being built, its buffers reused from step to step. Every entry of its x, v and
  // a is written below (the free dofs here and at the end, the constrained ones by
  // prescribeMotion), so they are not copied from s first.
  StructuralState& n = next_;
  n.t = s.t + dt;
  n.control = s.control;
  if (n.x.size() != nd) n.x.resize(nd), n.v.resize(nd), n.a.resize(nd);
  if (vHalf_.size() != nd) vHalf_.resize(nd), vStar_.resize(nd);
  // EX1: v_{n+1/2} = v_n + dt/2 a_n, x_{n+1} = x_n + dt v_{n+1/2}; prescribed dofs on their path
  // (the constrained dofs' are overwritten next). With it, in the same pass, the velocity the
  // forces are evaluated with (EX2, below): the forward-Euler prediction v_n + dt a_n.
  // A large system's passes over all dofs in halves, one on each thread (the same values).
  const bool halves = nd >= settings_.halvesFromDofs && sys_->numEquations() >= 2;
  auto overDofs = [&](const std::function<void(int, int)>& pass) {
    if (halves)
      sys_->inHalves(nd, pass);
    else
      pass(0, nd);
  };
  // EX2 with the velocity-dependent forces (drag, mass damping) at the forward-Euler
  // prediction v_{n+1} ~ v_n + dt a_n (second-order local error), and EX7's stiffness-
  // proportional damping as the internal forces at x + beta v: those positions in the same pass,
  // made again below at the dofs that move after it.
  const bool damped = settings_.stiffnessDamping > 0.0;
  const double beta = settings_.stiffnessDamping;
  if (damped && xEval_.size() != nd) xEval_.resize(nd);
  {
    ScopedTimer timer(sys_->timings().passes);
    overDofs([&](int b, int e) {
      auto pass = damped ? &predict<true> : &predict<false>;
      pass(e - b, dt, beta, s.x.data() + b, s.v.data() + b, s.a.data() + b, vHalf_.data() + b,
           n.x.data() + b, vStar_.data() + b, damped ? xEval_.data() + b : nullptr);
    });
  }
  sys_->prescribeMotion(n);
  // EX3: hand-over checked every step. A driven slider is handed over where its path passes a
  // node; a free slider whose part to an end node turns round over the step has passed that
  // node and is handed over to the neighbour there (notePassages), applied by the search below.
  const bool driven = sys_->drivesKinks();
  if (driven) sys_->crossDriven(s.x, n.x);
  // Sliders whose motion passed or reached a node over the step (notePassages, arriveAtNodes),
  // the search, and a slider landing on a node handed over at commit (onConverged).
  const bool movedElsewhere = sys_->settleExplicitMotion(s.x, n.x);
  for (int d : sys_->constrainedDofs()) vStar_[d] = n.v[d];
  if (zeroDofs_.size() != nd) zeroDofs_ = Eigen::VectorXd::Zero(nd);
  if (damped) {
    ScopedTimer timer(sys_->timings().passes);
    // Moved since the pass: the constrained dofs (prescribeMotion), the watchers' (the moves onto
    // nodes), and wherever a driven slider or another source moved a node (all of them again).
    auto again = [&](int d) { xEval_[d] = n.x[d] + beta * vStar_[d]; };
    if (driven || movedElsewhere) {
      overDofs([&](int b, int e) {
        for (int d = b; d < e; ++d) again(d);
      });
    } else {
      for (int d : sys_->constrainedDofs()) again(d);
      for (int d : sys_->watchedDofs()) again(d);
    }
  }
  // EX2: the forces at a = 0; the step's length for RG8.
  const EvalPoint p =
      EvalPoint::explicitForces(damped ? xEval_ : n.x, vStar_, zeroDofs_, n.t, dt,
                                damped ? &n.x : nullptr, settings_.stiffnessDamping);
  const Eigen::VectorXd* mass = nullptr;
  if (cutSets(n.t) == fixedMassCuts_) {
    // The sliding elements' mass M(x) 1 at x_{n+1} (all lumpedMass has to evaluate while no cut
    // changes the fixed mass) alongside the assembly, on the thread that finishes its part first:
    // it reads the positions and the sliding states, as the assembly does, and writes only its
    // own. Kept, rather than asked for again: a second call compares all positions to find it.
    // With two parts, each part's terms' bound after that part, on its thread (the membranes'
    // halves: one on each), summed when the next step's estimate takes them (chooseStep).
    const bool parts = sys_->hasTwoParts();
    auto alongside = [&] {
      mass = &lumpedMass(n.x, n.t);
      if (boundAheadWanted_ && !parts) boundAhead_ = sys_->positionStiffnessBound(n.x, n.t);
    };
    const std::function<void(int)> afterPart = [&](int part) {
      if (boundAheadWanted_) sys_->positionStiffnessBoundPart(n.x, n.t, part, boundParts_[part]);
    };
    if (halves)
      sys_->assembleForHalves(p, alongside, &afterPart);
    else
      sys_->assemble(p, false, alongside, &afterPart);
    if (boundAheadWanted_) {
      boundAheadX_ = n.x;
      boundAheadT_ = n.t;
      boundInParts_ = parts;
    }
  } else {
    sys_->assemble(p, false);
  }
  if (!mass) mass = &lumpedMass(n.x, n.t);
  // a_{n+1} = -r / m and v_{n+1} = v_{n+1/2} + dt/2 a_{n+1} on the free dofs, run by run of
  // consecutive equations (the constrained dofs' are prescribed).
  // With it, in the same pass, whether the new state is finite (x 0 is NaN for an infinite or
  // NaN entry): the free dofs here, the constrained ones after.
  // Over the runs' parts in equations [b, e); in halves, each half's residual summed from the
  // assembly's two parts just before (useResidualInHalves).
  double part[2] = {0.0, 0.0};
  auto correctOver = [&](int b, int e) {
    const double* r = sys_->residualInHalves().data();
    double sum = 0.0;
    for (const auto& run : dofs.freeRuns()) {
      const int from = std::max(run.eq, b), to = std::min(run.eq + run.count, e);
      if (from >= to) continue;
      const int d = run.dof + (from - run.eq);
      sum += correct(to - from, 0.5 * dt, r + from, mass->data() + from, vHalf_.data() + d,
                     n.x.data() + d, n.a.data() + d, n.v.data() + d);
    }
    part[b == 0 ? 0 : 1] = sum;
  };
  {
    ScopedTimer timer(sys_->timings().passes);
    if (halves)
      sys_->useResidualInHalves(correctOver);
    else
      correctOver(0, sys_->numEquations());
  }
  double nonFinite = part[0] + part[1];
  for (int d : sys_->constrainedDofs()) nonFinite += n.x[d] * 0.0 + n.v[d] * 0.0 + n.a[d] * 0.0;
  rep.iterations = 0;
  if (!(nonFinite == 0.0)) {
    rep.failure = "non-finite state: the explicit step is unstable";
    sys_->revert();
    return rep;
  }
  {
    ScopedTimer timer(sys_->timings().commits);
    sys_->commit(CommitPoint{n.x, n.t, dt, n.t, &n.v});
  }
  std::swap(s, n);  // n keeps the old state's buffers for the next step
  rep.converged = true;
  return rep;
}

}  // namespace chute
