// [[cables]] and [[sliding_groups]] (with their friction laws) given by node paths, or by
// mesh groups (MeshGroups.cpp).
#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "case/MeshGroups.hpp"
#include "case/sections/SectionLookup.hpp"
#include "case/sections/Sections.hpp"

namespace chute::caseio {

namespace {

// Points at equal arc length along a polyline, n intervals; returns n + 1 points.
std::vector<Vec3> resample(const std::vector<Vec3>& path, int n, double* totalLength) {
  std::vector<double> s(path.size(), 0.0);
  for (size_t i = 1; i < path.size(); ++i) s[i] = s[i - 1] + (path[i] - path[i - 1]).norm();
  *totalLength = s.back();
  std::vector<Vec3> out;
  size_t seg = 1;
  for (int k = 0; k <= n; ++k) {
    const double target = s.back() * k / n;
    while (seg + 1 < path.size() && s[seg] < target) ++seg;
    const double len = s[seg] - s[seg - 1];
    const double f = len > 0 ? std::clamp((target - s[seg - 1]) / len, 0.0, 1.0) : 0.0;
    out.push_back(path[seg - 1] + f * (path[seg] - path[seg - 1]));
  }
  out.front() = path.front();
  out.back() = path.back();
  return out;
}

std::vector<int> pathNodes(const Model& m, TomlTable& t) {
  const auto names = t.strings("path");
  if (names.size() < 2) t.fail("path", "needs at least two nodes");
  std::vector<int> ids;
  for (const auto& n : names) ids.push_back(nodeRef(m, t, "path", n));
  return ids;
}

void readCable(Model& m, TomlTable t, int index) {
  CableElement proto;
  const std::string name = setName(m, t, "cables" + std::to_string(index));
  proto.material = materialRef(m, t);
  const auto ids = pathNodes(m, t);
  const long perSegment = t.integer("elements_per_segment", 1, 1, kMaxNodes);
  checkNodeBudget(m, t, "elements_per_segment",
                  (perSegment - 1) * static_cast<long>(ids.size() - 1));
  const double prestrain = t.number("prestrain", 0.0);
  if (prestrain <= -1.0) t.fail("prestrain", "must be > -1");
  t.finish();
  proto.set = static_cast<int>(m.lineSets.size());
  m.lineSets.push_back({name, false});
  for (size_t i = 0; i + 1 < ids.size(); ++i) {
    const Vec3 a = m.X[ids[i]], b = m.X[ids[i + 1]];
    if ((b - a).norm() <= 0.0)
      t.fail("path", "zero-length segment between '" + m.nodeName[ids[i]] + "' and '" +
                         m.nodeName[ids[i + 1]] + "'");
    int prev = ids[i];
    for (long k = 1; k <= perSegment; ++k) {
      const int next = k == perSegment ? ids[i + 1]
                                       : m.addNode(a + (b - a) * (double(k) / perSegment),
                                                   name + "." + std::to_string(m.numNodes()));
      CableElement c = proto;
      c.a = prev;
      c.b = next;
      c.L = (m.X[next] - m.X[prev]).norm() / (1.0 + prestrain);
      m.cables.push_back(c);
      prev = next;
    }
  }
}

// Friction, lock and one-way flow of a slider point (docs/friction.md): keys `friction =
// {mu_static, mu_dynamic, slip_rate_scale}`, `lock_at`, `one_way = "+" | "-"` over `base`.
kernels::SliderFrictionLaw readFrictionLaw(TomlTable& t, kernels::SliderFrictionLaw base) {
  if (t.has("friction")) {
    TomlTable f = t.table("friction");
    base.muStatic = f.nonNegative("mu_static", 0.0);
    base.muDynamic = f.nonNegative("mu_dynamic", base.muStatic);
    base.slipRateScale = f.nonNegative("slip_rate_scale", 0.0);
    if (base.muDynamic > base.muStatic)
      f.fail("mu_dynamic", "must not exceed mu_static (the stick limit)");
    f.finish();
  }
  if (t.has("lock_at")) base.lockAt = t.nonNegative("lock_at", 0.0);
  if (t.has("one_way")) base.oneWay = t.choice("one_way", "+", {"+", "-"}) == "+" ? 1 : -1;
  return base;
}

void readSlidingGroup(Model& m, TomlTable t, int index) {
  SlidingGroupDef g;
  g.name = setName(m, t, "sliding_group" + std::to_string(index));
  g.material = materialRef(m, t);
  const auto path = pathNodes(m, t);
  std::vector<int> sliders;
  for (const auto& s : t.strings("sliders")) sliders.push_back(nodeRef(m, t, "sliders", s));
  if (sliders.empty()) t.fail("sliders", "a sliding group needs at least one slider");
  std::set<int> sliderSet(sliders.begin(), sliders.end());
  if (sliderSet.size() != sliders.size()) t.fail("sliders", "a slider is listed twice");
  if (sliderSet.count(path.front()) || sliderSet.count(path.back()))
    t.fail("path", "the chain's end nodes cannot be sliders");
  for (size_t i = 1; i + 1 < path.size(); ++i)
    if (!sliderSet.count(path[i]))
      t.fail("path", "interior path node '" + m.nodeName[path[i]] +
                         "' is not a slider (the path runs end -> sliders -> end)");
  const long n = t.integer("elements", 1, 1, kMaxNodes);
  checkNodeBudget(m, t, "elements", n - 1);
  const double prestrain = t.number("prestrain", 0.0);
  if (prestrain <= -1.0) t.fail("prestrain", "must be > -1");
  std::vector<long> active;
  if (t.has("active")) active = t.integers("active");
  const auto groupLaw = readFrictionLaw(t, {});
  g.friction.assign(sliders.size(), groupLaw);
  for (auto& sp : t.tables("slider_points")) {
    const int node = nodeRef(m, sp, "slider", sp.string("slider"));
    auto it = std::find(sliders.begin(), sliders.end(), node);
    if (it == sliders.end()) sp.fail("slider", "not a slider of this group");
    g.friction[it - sliders.begin()] = readFrictionLaw(sp, groupLaw);
    sp.finish();
  }
  t.finish();

  std::vector<Vec3> geom;
  for (int id : path) geom.push_back(m.X[id]);
  double total = 0.0;
  const auto pts = resample(geom, static_cast<int>(n), &total);
  if (total <= 0.0) t.fail("path", "the path has zero length");
  const double h = total / n;
  g.chain.push_back(path.front());
  for (long k = 1; k < n; ++k)
    g.chain.push_back(m.addNode(pts[k], g.name + "." + std::to_string(k)));
  g.chain.push_back(path.back());
  g.refLength.assign(n, h / (1.0 + prestrain));
  g.sliders = sliders;
  g.set = static_cast<int>(m.lineSets.size());
  m.lineSets.push_back({g.name, true});

  if (!active.empty() && active.size() != sliders.size())
    t.fail("active", "needs one element index per slider (" + std::to_string(sliders.size()) + ")");
  // Arc length of each path vertex, for the initially active element of sliders on the path.
  std::vector<double> arc(path.size(), 0.0);
  for (size_t i = 1; i < path.size(); ++i) arc[i] = arc[i - 1] + (geom[i] - geom[i - 1]).norm();
  for (size_t s = 0; s < sliders.size(); ++s) {
    int k;
    if (!active.empty()) {
      if (active[s] < 0 || active[s] >= n)
        t.fail("active", "element " + std::to_string(active[s]) + " out of range [0, " +
                             std::to_string(n - 1) + "]");
      k = static_cast<int>(active[s]);
    } else {
      auto it = std::find(path.begin(), path.end(), sliders[s]);
      if (it == path.end())
        t.fail("active", "slider '" + m.nodeName[sliders[s]] +
                             "' is not on the path: give its initially active element");
      const double sArc = arc[it - path.begin()];
      k = static_cast<int>(std::clamp(std::floor(sArc / h), 0.0, static_cast<double>(n - 1)));
    }
    // The slider must lie on its active element: l = l1 + l2 equals the element's current
    // length (1 + prestrain) L up to round-off.
    const Vec3 xs = m.X[sliders[s]];
    const double l = (xs - m.X[g.chain[k]]).norm() + (xs - m.X[g.chain[k + 1]]).norm();
    if (std::abs(l - h) > 1e-6 * h)
      t.fail(active.empty() ? "sliders" : "active",
             "slider '" + m.nodeName[sliders[s]] + "' is not on element " + std::to_string(k) +
                 " of the chain (l1 + l2 = " + std::to_string(l) + ", element length " +
                 std::to_string(h) + ")");
    for (size_t o = 0; o < s; ++o)
      if (g.initialActive[o] == k)
        t.fail("sliders", "two sliders on element " + std::to_string(k) +
                              ": use more elements so each slider has its own");
    g.initialActive.push_back(k);
  }
  m.groups.push_back(std::move(g));
}

}  // namespace

void readCables(Model& m, const MeshImport* mesh, TomlTable& top) {
  int i = 0;
  for (auto& t : top.tables("cables"))
    t.has("group") ? readMeshCables(m, mesh, t, i++) : readCable(m, t, i++);
}

void readSlidingGroups(Model& m, const MeshImport* mesh, TomlTable& top) {
  int i = 0;
  for (auto& t : top.tables("sliding_groups"))
    t.has("group") ? readMeshSlidingGroup(m, mesh, t, i++) : readSlidingGroup(m, t, i++);
}

}  // namespace chute::caseio
