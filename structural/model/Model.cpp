#include "model/Model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace chute {

std::string nodeNames(const Model& m, const std::vector<int>& nodes) {
  std::string names;
  for (size_t i = 0; i < nodes.size() && i < 8; ++i) {
    const int n = nodes[i];
    names +=
        (i ? ", " : "") + (m.nodeName[n].empty() ? "node " + std::to_string(n + 1) : m.nodeName[n]);
  }
  if (nodes.size() > 8) names += " and " + std::to_string(nodes.size() - 8) + " more";
  return names;
}

std::vector<std::string> nodePartNames(const Model& m) {
  std::vector<std::string> part(m.numNodes());
  for (const auto& e : m.membranes)
    for (int i = 0; i < e.numNodes; ++i)
      if (part[e.nodes[i]].empty()) part[e.nodes[i]] = m.membraneSets[e.set].name;
  for (const auto& c : m.cables)
    for (int n : {c.a, c.b})
      if (part[n].empty()) part[n] = m.lineSets[c.set].name;
  for (const auto& g : m.groups) {
    for (int n : g.chain)
      if (part[n].empty()) part[n] = m.lineSets[g.set].name;
    for (int n : g.sliders)
      if (part[n].empty()) part[n] = m.lineSets[g.set].name;
  }
  for (auto& p : part)
    if (p.empty()) p = "point masses";
  return part;
}

int Model::membranesInSet(int set) const {
  int n = 0;
  for (const auto& e : membranes) n += e.set == set ? 1 : 0;
  return n;
}

namespace {
constexpr double kTwoPi = 6.283185307179586;
}

double NodeConstraint::position(double X, int k, double t) const {
  return X + velocity[k] * t + amplitude[k] * std::sin(kTwoPi * frequency * t);
}
double NodeConstraint::speed(int k, double t) const {
  return velocity[k] + amplitude[k] * kTwoPi * frequency * std::cos(kTwoPi * frequency * t);
}
double NodeConstraint::acceleration(int k, double t) const {
  const double w = kTwoPi * frequency;
  return -amplitude[k] * w * w * std::sin(w * t);
}

int Model::addNode(const Vec3& x, const std::string& name) {
  const int id = numNodes();
  X.push_back(x);
  u0.push_back(Vec3::Zero());
  nodeName.push_back(name);
  constraint.emplace_back();
  pointMass.push_back(0.0);
  if (!name.empty()) nodeByName[name] = id;
  return id;
}

int Model::nodeId(const std::string& name) const {
  auto it = nodeByName.find(name);
  if (it == nodeByName.end()) throw std::out_of_range("unknown node '" + name + "'");
  return it->second;
}

double Model::totalLineMass() const {
  double m = 0.0;
  for (const auto& c : cables)
    m += materials[c.material].density * materials[c.material].area * c.L;
  for (const auto& g : groups)
    for (double L : g.refLength)
      m += materials[g.material].density * materials[g.material].area * L;
  return m;
}

double Model::totalMass() const {
  double m = totalLineMass();
  for (double p : pointMass) m += p;
  for (const auto& e : membranes) {
    const auto& mat = membraneMaterials[e.material];
    const Vec3 A =
        e.numNodes == 3
            ? Vec3(0.5 * (X[e.nodes[1]] - X[e.nodes[0]]).cross(X[e.nodes[2]] - X[e.nodes[0]]))
            : Vec3(0.5 * (X[e.nodes[2]] - X[e.nodes[0]]).cross(X[e.nodes[3]] - X[e.nodes[1]]));
    m += mat.density * mat.thickness * A.norm();
  }
  return m;
}

double Model::nextCutAfter(double t) const {
  double next = std::numeric_limits<double>::infinity();
  for (const auto& s : lineSets)
    if (s.cutAt > t) next = std::min(next, s.cutAt);
  return next;
}

bool Model::hasCutAt(double t) const {
  return std::any_of(lineSets.begin(), lineSets.end(),
                     [t](const LineSet& s) { return s.cutAt == t; });
}

DofMap::DofMap(const Model& m) : eq_(3 * m.numNodes(), -1), freeNodeEq_(m.numNodes(), -1) {
  for (int n = 0; n < m.numNodes(); ++n) {
    for (int k = 0; k < 3; ++k)
      if (!m.constraint[n].fixed[k]) eq_[3 * n + k] = numEq_++;
    if (eq_[3 * n] >= 0 && eq_[3 * n + 1] >= 0 && eq_[3 * n + 2] >= 0) freeNodeEq_[n] = eq_[3 * n];
  }
  for (int d = 0; d < numDofs(); ++d) {
    if (eq_[d] < 0) continue;
    if (!freeRuns_.empty() && freeRuns_.back().dof + freeRuns_.back().count == d)
      ++freeRuns_.back().count;
    else
      freeRuns_.push_back({d, eq_[d], 1});
  }
}

}  // namespace chute
