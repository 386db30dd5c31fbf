// Sliding groups: the search picks the right active element along a slider sweep across every
// node of a chain, in both directions, for both strategies; mass and weight of the group are
// invariant as the slider moves; the assembled tangent matches finite differences of the
// assembled residual.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "kernels/CableKernel.hpp"
#include "kernels/SlidingCableKernel.hpp"
#include "model/History.hpp"
#include "solver/StructuralSystem.hpp"
#include "support/FiniteDifference.hpp"
#include "terms/sliding/SlidingGroupState.hpp"
#include "terms/sliding/SlidingGroupTerm.hpp"

using namespace chute;

namespace {

// A rope of total length 2a with fixed ends at the foci (0,0,0), (4,0,0), n elements, and a slider
// at ellipse angle theta. Chain nodes sit at equal arc length along the broken line
// end 1 -> slider -> end 2, so the exact active element is known.
struct EllipseScene {
  Model model;
  double a = 2.6, c = 2.0;
  int n = 6;
  Eigen::VectorXd positions(double theta, int* exactElement) const {
    const double b = std::sqrt(a * a - c * c);
    const Vec3 f1(0, 0, 0), f2(4, 0, 0), p(2 + a * std::cos(theta), 0, -b * std::sin(theta));
    const double l1 = (p - f1).norm(), total = 2 * a;
    Eigen::VectorXd x(3 * model.numNodes());
    for (int k = 0; k <= n; ++k) {
      const double s = total * k / n;
      const Vec3 q =
          s <= l1 ? Vec3(f1 + s * (p - f1) / l1) : Vec3(p + (s - l1) * (f2 - p) / (total - l1));
      x.segment<3>(3 * k) = q;
    }
    x.segment<3>(3 * (n + 1)) = p;
    *exactElement = std::min(n - 1, static_cast<int>(l1 / (total / n)));
    return x;
  }
  EllipseScene() {
    model.materials.push_back({1e5, 1e-2, 0.5, true, 0.0});
    model.materialName.push_back("rope");
    SlidingGroupDef g;
    g.name = "rope";
    g.material = 0;
    for (int k = 0; k <= n; ++k) g.chain.push_back(model.addNode(Vec3::Zero()));
    g.refLength.assign(n, 2 * a / n);
    g.sliders.push_back(model.addNode(Vec3::Zero(), "slider"));
    g.initialActive.push_back(0);
    model.groups.push_back(g);
    model.gravity = Vec3(0, 0, -9.81);
  }
};

}  // namespace

TEST(SlidingGroupSearch, NearestLengthFollowsTheSliderAcrossEveryNodeInBothDirections) {
  EllipseScene scene;
  SlidingGroupState st(scene.model.groups[0]);
  int exact = 0, crossings = 0, positions = 0;
  // theta from pi (slider near end 1) to 0 (near end 2) and back.
  std::vector<double> sweep;
  for (int i = 1; i < 400; ++i) sweep.push_back(M_PI * (1 - i / 400.0));
  for (int i = 398; i >= 1; --i) sweep.push_back(M_PI * (1 - i / 400.0));
  int last = st.activeElement(0);
  for (double th : sweep) {
    const Eigen::VectorXd x = scene.positions(th, &exact);
    // A slider exactly on a node belongs to either element: not a test of the search.
    const double l1 = (x.segment<3>(3 * (scene.n + 1)) - x.segment<3>(0)).norm();
    const double h = 2 * scene.a / scene.n;
    if (std::abs(l1 / h - std::round(l1 / h)) < 1e-9) continue;
    st.search(x, SliderSearch::NearestLength);
    st.commit(x);
    EXPECT_EQ(st.activeElement(0), exact) << "theta " << th;
    crossings += std::abs(st.activeElement(0) - last);
    last = st.activeElement(0);
    ++positions;
    // The material coordinate is the slider's arc length from end 1 (no stretch here).
    EXPECT_NEAR(st.materialCoordinate(0, x), l1, 1e-12);
  }
  std::printf("nearest-length (F12): %d positions, %d node crossings\n", positions, crossings);
  EXPECT_EQ(crossings, 2 * (scene.n - 1));
}

TEST(SlidingGroupSearch, TrackerLocatesEveryNodeCrossingInBothDirections) {
  // A straight chain of 6 elements with fixed nodes; the slider is driven along it and back in
  // linear updates, as Newton moves it. Each update that passes a node is cut where the slider
  // meets the node (event location), the slider arrives and is handed over.
  Model model;
  model.materials.push_back({1e5, 1e-2, 0.0, true, 0.0});
  SlidingGroupDef g;
  g.material = 0;
  const int n = 6;
  for (int k = 0; k <= n; ++k) {
    g.chain.push_back(model.addNode(Vec3(k, 0, 0)));
    model.constraint.back().fixed = {true, true, true};
  }
  g.refLength.assign(n, 1.0);
  g.sliders.push_back(model.addNode(Vec3(0.3, 0, 0)));
  g.initialActive.push_back(0);
  model.groups.push_back(g);
  SlidingGroupState st(model.groups[0]);
  Eigen::VectorXd x(3 * model.numNodes());
  for (int k = 0; k < model.numNodes(); ++k) x.segment<3>(3 * k) = model.X[k];
  st.commit(x);
  const int slider = 3 * n + 3;
  int handovers = 0, events = 0;
  std::vector<double> path;
  for (double s = 0.3; s < 5.8; s += 0.07) path.push_back(s);
  for (double s = 5.8; s > 0.2; s -= 0.07) path.push_back(s);
  for (double target : path) {
    for (int guard = 0; guard < 10; ++guard) {
      Eigen::VectorXd dx = Eigen::VectorXd::Zero(x.size());
      dx[slider] = target - x[slider];
      const double f = st.passageFraction(x, dx);
      if (f >= 1.0) {
        x += dx;
        st.search(x, SliderSearch::MaterialCoordinate);
        st.commit(x);
        break;
      }
      ++events;
      x += f * dx;  // the step cut to end at the node
      const int before = st.activeElement(0);
      st.arriveAtNodes(model, x, kernels::kArrivalFraction, kernels::kSeparationFraction);
      st.commit(x);  // the hand-over takes effect with the committed step
      handovers += std::abs(st.activeElement(0) - before);
    }
    const int expected = std::clamp(static_cast<int>(std::floor(x[slider])), 0, n - 1);
    EXPECT_EQ(st.activeElement(0), expected) << "slider at " << x[slider];
    EXPECT_NEAR(st.materialCoordinate(0, x), x[slider], 1e-12);
  }
  std::printf("material-coordinate tracker: %zu positions, %d events located, %d hand-overs\n",
              path.size(), events, handovers);
  EXPECT_EQ(handovers, 2 * (n - 1));
  EXPECT_EQ(events, 2 * (n - 1));
}

namespace {
// A line folded at a slider: end node a = (0, 0, 2), slider at the origin, the line leaving it
// along t_c = (sin 60, 0, -cos 60); node i, the slider's element's lower end, a hair from the
// slider. Chain a - i - c with the slider in element 0 (a, i); element 1 runs from i to c.
struct Fold {
  Model model;
  Vec3 a{0, 0, 2}, s{0, 0, 0}, tc{std::sin(M_PI / 3), 0, -std::cos(M_PI / 3)};
  Fold() {
    model.materials.push_back({1e5, 1e-2, 0.5, true, 0.0});
    SlidingGroupDef g;
    g.material = 0;
    g.chain = {model.addNode(a), model.addNode(Vec3::Zero()), model.addNode(Vec3::Zero())};
    g.sliders.push_back(model.addNode(s));
    // Both elements stretched by 1e-3 with node i near the slider.
    g.refLength = {2.002 / 1.001, 1.5 / 1.001};
    g.initialActive.push_back(0);
    model.groups.push_back(g);
  }
  // Node i at distance r from the slider, at angle phi from t_c towards t_a (phi = 0: on the
  // lower line; the bisector of the kink at phi = 60 deg); c stays on the lower line.
  Eigen::VectorXd at(double r, double phi) const {
    Eigen::VectorXd x(3 * model.numNodes());
    const Vec3 ta = (a - s).normalized();
    const Vec3 n = tc.cross(ta).normalized();  // the plane of the fold's normal
    const Vec3 dir = Eigen::AngleAxisd(phi, n) * tc;
    x << a, s + r * dir, s + 1.5 * tc, s;
    return x;
  }
};

// Strains of the group's two elements at x, in whatever topology st has.
std::array<double, 2> strains(const SlidingGroupState& st, const Eigen::VectorXd& x,
                              const kernels::LineMaterial& mat) {
  const auto& g = st.def();
  auto p = [&](int n) { return Vec3(x.segment<3>(3 * n)); };
  std::array<double, 2> out{};
  for (int k = 0; k < 2; ++k) {
    const int sl = st.sliderOfElement(k);
    out[k] =
        sl < 0 ? kernels::cableForce(p(g.chain[k]), p(g.chain[k + 1]), st.refLength(k), mat, false)
                     .strain
               : kernels::slidingForce(p(g.chain[k]), p(g.chain[k + 1]), p(g.sliders[sl]),
                                       st.refLength(k), mat, false)
                     .strain;
  }
  return out;
}
}  // namespace

TEST(SlidingGroupHandover, ANodePassingBesideTheSliderTakesItsPartsMaterialAcross) {
  // F12b: node i swings round the slider at 2e-3 (of 2 and 1.5 long elements) from just below
  // the kink's bisector (phi = 55 deg) to just above it (65 deg) in one motion: the part between
  // them never turns round, the old rule never handed over.
  Fold f;
  const auto& mat = f.model.materials[0];
  SlidingGroupState st(f.model.groups[0]);
  const double r = 2e-3;
  const Eigen::VectorXd x0 = f.at(r, 55 * M_PI / 180), x1 = f.at(r, 65 * M_PI / 180);
  st.commit(x0);
  EXPECT_GT(st.handoverGain(0, 1, x0), 0.0);
  EXPECT_LT(st.handoverGain(0, 1, x1), 0.0);
  const Eigen::VectorXd xb = f.at(r, 60 * M_PI / 180);  // on the bisector: Delta = 0
  std::printf("Delta at 55 / 60 / 65 deg: %.3e / %.3e / %.3e\n", st.handoverGain(0, 1, x0),
              st.handoverGain(0, 1, xb), st.handoverGain(0, 1, x1));
  EXPECT_NEAR(st.handoverGain(0, 1, xb), 0.0, r * r);  // the bisector is Delta = 0 to first order
  const auto before = strains(st, xb, mat);
  // Explicit: the step's motion passes Delta = 0 (positions linear over it: close to, not on,
  // the circle; the transfer is the part's material where Delta = 0).
  const Eigen::VectorXd dx = x1 - x0;
  EXPECT_EQ(st.notePassages(x0, dx), 1);
  st.search(x1, SliderSearch::MaterialCoordinate);
  EXPECT_EQ(st.activeElement(0), 1);
  const double moved = 2.0 - st.refLength(0);
  EXPECT_NEAR(st.refLength(0) + st.refLength(1), 3.502 / 1.001, 1e-15);
  // On the bisector the element leaving loses 3r/2 of length (the part r, and a -> i is r/2
  // shorter than a -> slider): 3r/2 / (1 + strain) of material, r cos 5 deg where the chord of
  // the motion meets the bisector.
  EXPECT_NEAR(moved, 1.5 * r * std::cos(5 * M_PI / 180) / 1.001, 1e-3 * r);
  // Both strains across the hand-over, at the bisector: changed by far less than the part's
  // length over the element (r / L = 1e-3) would have.
  const auto after = strains(st, xb, mat);
  std::printf("strains at the bisector before %.6e %.6e, after %.6e %.6e; material moved %.6e\n",
              before[0], before[1], after[0], after[1], moved);
  EXPECT_NEAR(after[0], before[0], 1e-5);
  EXPECT_NEAR(after[1], before[1], 1e-5);
  // Committed, saved and loaded: the lengths come back; a forged set that changes the chain's
  // total is refused.
  st.commit(x1);
  History h;
  st.save(h);
  SlidingGroupState back(f.model.groups[0]);
  HistoryReader rd(h, "rope");
  back.load(rd);
  EXPECT_EQ(back.refLength(0), st.refLength(0));
  EXPECT_EQ(back.refLength(1), st.refLength(1));
  auto reals = h.reals();
  bool forged = false;
  for (auto& v : reals)
    if (v == st.refLength(1)) v *= 1.01, forged = true;
  ASSERT_TRUE(forged);
  const History bad = History::fromRecords(reals, h.ints());
  SlidingGroupState refused(f.model.groups[0]);
  HistoryReader rb(bad, "rope");
  EXPECT_THROW(refused.load(rb), HistoryError);
}

TEST(SlidingGroupHandover, ImplicitUpdatesAreCutWhereTheNodePassesBeside) {
  // The same passage as a Newton update: cut where Delta is half the arrival band, and there the
  // slider is handed over (at once, or at commit), with the same material.
  Fold f;
  SlidingGroupState st(f.model.groups[0]);
  const double r = 2e-3;
  const Eigen::VectorXd x0 = f.at(r, 50 * M_PI / 180), x1 = f.at(r, 70 * M_PI / 180);
  st.commit(x0);
  const double frac = st.passageFraction(x0, x1 - x0);
  ASSERT_LT(frac, 1.0);
  Eigen::VectorXd x = x0 + frac * (x1 - x0);
  const double band = kernels::kArrivalFraction * 2.0;
  std::printf("cut at %.4f of the update: Delta %.3e (band %.1e)\n", frac, st.handoverGain(0, 1, x),
              band);
  EXPECT_LE(std::abs(st.handoverGain(0, 1, x)), band);
  const Eigen::VectorXd xAtCut = x;
  EXPECT_TRUE(
      st.arriveAtNodes(f.model, x, kernels::kArrivalFraction, kernels::kSeparationFraction));
  EXPECT_EQ(x, xAtCut);  // nothing moved: no node placed, no slider moved
  st.commit(x);
  EXPECT_EQ(st.activeElement(0), 1);
  EXPECT_NEAR(2.002 / 1.001 - st.refLength(0), 1.5 * r * std::cos(10 * M_PI / 180) / 1.001,
              1e-3 * r);
}

TEST(SlidingGroupHandover, AFoldedLineHasNoPassageBesideItsNodes) {
  // A line folded back on itself at the slider (a rope over a pulley, t_a = t_c): Delta is ~0
  // wherever the node is; without a change of sign from clearly positive nothing is handed over.
  Model model;
  model.materials.push_back({1e5, 1e-2, 0.5, true, 0.0});
  SlidingGroupDef g;
  g.material = 0;
  g.chain = {model.addNode(Vec3(0.01, 0, -2)), model.addNode(Vec3::Zero()),
             model.addNode(Vec3(-0.01, 0, -2))};
  g.sliders.push_back(model.addNode(Vec3::Zero()));
  g.refLength = {2.0, 2.0};
  g.initialActive.push_back(0);
  model.groups.push_back(g);
  SlidingGroupState st(model.groups[0]);
  Eigen::VectorXd x(12);
  x << 0.01, 0, -2, -0.005, 0, -0.05, -0.01, 0, -2, 0, 0, 0;  // node i 0.05 below, on c's side
  st.commit(x);
  Eigen::VectorXd dx = Eigen::VectorXd::Zero(12);
  dx[3] = 0.01;  // node i moves across to a's side, 0.05 below the slider
  EXPECT_EQ(st.notePassages(x, dx), 0);
  EXPECT_EQ(st.passageFraction(x, dx), 1.0);
}

TEST(SlidingGroupSearch, RevertRestoresTheCommittedActiveElement) {
  EllipseScene scene;
  SlidingGroupState st(scene.model.groups[0]);
  int exact = 0;
  st.search(scene.positions(2.0, &exact), SliderSearch::NearestLength);
  st.commit(scene.positions(2.0, &exact));
  const int committed = st.activeElement(0);
  st.search(scene.positions(0.3, &exact), SliderSearch::NearestLength);
  EXPECT_NE(st.activeElement(0), committed);
  st.revert();
  EXPECT_EQ(st.activeElement(0), committed);
}

TEST(SlidingGroupSystem, MassAndWeightInvariantAsTheSliderMoves) {
  EllipseScene scene;
  for (auto kind : {kernels::MassKind::Lumped, kernels::MassKind::Consistent}) {
    scene.model.massKind = kind;
    StructuralSystem sys(scene.model, SliderSearch::NearestLength);
    const double mTotal = scene.model.totalLineMass();
    int exact = 0;
    for (double th = 0.05; th < M_PI; th += 0.1) {
      const Eigen::VectorXd x = scene.positions(th, &exact);
      sys.updateState(x);
      Eigen::VectorXd v = Eigen::VectorXd::Zero(x.size());
      for (int k = 2; k < v.size(); k += 3) v[k] = 1.0;
      const auto e = sys.energy(x, v, 0.0);
      EXPECT_NEAR(2 * e.kinetic, mTotal, 1e-12 * mTotal);
      Eigen::VectorXd shifted = x;
      for (int k = 2; k < x.size(); k += 3) shifted[k] += 0.25;
      const double weight = (sys.energy(shifted, v, 0.0).gravity - e.gravity) / (0.25 * 9.81);
      EXPECT_NEAR(weight, mTotal, 1e-10 * mTotal);
    }
  }
}

TEST(SlidingGroupSystem, AssembledJacobianMatchesFiniteDifferences) {
  EllipseScene scene;
  scene.model.constraint[0].fixed = {true, true, true};
  scene.model.constraint[scene.n].fixed = {true, true, true};
  StructuralSystem sys(scene.model, SliderSearch::NearestLength);
  int exact = 0;
  Eigen::VectorXd x = scene.positions(1.1, &exact);
  for (int k = 0; k < x.size(); ++k) x[k] *= 1.01;  // stretch: every element taut
  sys.updateState(x);
  Eigen::VectorXd v = Eigen::VectorXd::Constant(x.size(), 0.3), a = Eigen::VectorXd::Zero(x.size());
  for (int k = 0; k < a.size(); ++k) a[k] = std::sin(1.0 + k);
  const double cx = 0.6, ca = 37.0;
  auto residual = [&](const Eigen::VectorXd& xeq) -> Eigen::VectorXd {
    Eigen::VectorXd y = x;
    for (int d = 0, e = 0; d < y.size(); ++d)
      if (sys.dofs().eqOfDof(d) >= 0) y[d] = xeq[e++];
    // The accelerations move with x as the integrator's do: a = a0 + (ca/cx)(y - x).
    Eigen::VectorXd ay = a + (ca / cx) * (y - x);
    sys.assemble(EvalPoint::implicitStep(y, v, ay, 0.0, {cx, 0.0, ca}, 0.0), false);
    return sys.residual();  // dR/dy = dr/dx + (ca/cx) dr/da = J / cx
  };
  const Eigen::VectorXd xeq = sys.gatherEquations(x);
  sys.assemble(EvalPoint::implicitStep(x, v, a, 0.0, {cx, 0.0, ca}, 0.0), true);
  const Eigen::MatrixXd J = Eigen::MatrixXd(sys.matrix()) / cx;
  const Eigen::MatrixXd Jfd = chute::testing::fdJacobian(residual, xeq, 1e-7);
  const double err = chute::testing::relativeError(J, Jfd);
  if (err > 1e-6) {
    Eigen::MatrixXd D = (J - Jfd).cwiseAbs();
    Eigen::Index r, c;
    D.maxCoeff(&r, &c);
    std::printf("worst at (%ld,%ld): J %.6e FD %.6e\n", (long)r, (long)c, J(r, c), Jfd(r, c));
  }
  std::printf("assembled sliding system: relative error of J vs FD %.2e, symmetric=%d\n", err,
              sys.symmetric());
  EXPECT_LE(err, 1e-6);
}
