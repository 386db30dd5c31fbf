#include "SceneFrame.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "case/CaseSpec.hpp"
#include "kernels/CableKernel.hpp"
#include "terms/MembraneTerm.hpp"
#include "terms/sliding/SlidingGroupTerm.hpp"

namespace chute {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Cell fields, appended one cell at a time so every field stays aligned with the cells.
struct CellFields {
  FieldArray kind{"kind", 1, {}, true}, part{"part", 1, {}, true};
  FieldArray axialForce{"axial_force", 1, {}}, axialStrain{"axial_strain", 1, {}};
  FieldArray stress{"principal_stress", 2, {}, false, {"S1", "S2"}};
  FieldArray strain{"principal_strain", 2, {}, false, {"E1", "E2"}};
  // Principal true stress resultants (force per current width) and the larger over the
  // material's strength (NaN without one).
  FieldArray resultant{"stress_resultant", 2, {}, false, {"N1", "N2"}};
  FieldArray utilisation{"utilisation", 1, {}};
  FieldArray wrinkling{"wrinkling_state", 1, {}, true}, pressure{"pressure", 1, {}};
  FieldArray sliderGroup{"slider_group", 1, {}, true}, sliderS{"slider_material_coordinate", 1, {}};
  // Friction at sliders (docs/friction.md): 0 stick, +1 / -1 slip with the split growing /
  // shrinking, NaN without friction; tension ratio N2 / N1 of the active element's parts.
  FieldArray sliderStick{"slider_stick_state", 1, {}}, sliderRatio{"slider_tension_ratio", 1, {}};

  void add(CellKind k, int partIndex, double N, double eps, const Eigen::Vector2d& S,
           const Eigen::Vector2d& E, double wrinkle, double p, int group, double s,
           double stick = std::numeric_limits<double>::quiet_NaN(),
           double ratio = std::numeric_limits<double>::quiet_NaN()) {
    sliderStick.values.push_back(stick);
    sliderRatio.values.push_back(ratio);
    kind.values.push_back(static_cast<int>(k));
    part.values.push_back(partIndex);
    axialForce.values.push_back(N);
    axialStrain.values.push_back(eps);
    stress.values.insert(stress.values.end(), {S[0], S[1]});
    strain.values.insert(strain.values.end(), {E[0], E[1]});
    wrinkling.values.push_back(wrinkle);
    pressure.values.push_back(p);
    sliderGroup.values.push_back(group);
    sliderS.values.push_back(s);
    resultant.values.insert(resultant.values.end(), {kNaN, kNaN});
    utilisation.values.push_back(kNaN);
  }
  // The membrane cell just added: its resultants and utilisation.
  void setResultant(const Eigen::Vector2d& n, double strength) {
    const size_t c = utilisation.values.size() - 1;
    resultant.values[2 * c] = n[0];
    resultant.values[2 * c + 1] = n[1];
    utilisation.values[c] = strength > 0.0 ? n[0] / strength : kNaN;
  }
  std::vector<FieldArray> take() {
    return {std::move(kind),        std::move(part),        std::move(axialForce),
            std::move(axialStrain), std::move(stress),      std::move(strain),
            std::move(wrinkling),   std::move(pressure),    std::move(sliderGroup),
            std::move(sliderS),     std::move(sliderStick), std::move(sliderRatio),
            std::move(resultant),   std::move(utilisation)};
  }
};

const Eigen::Vector2d kNaN2(kNaN, kNaN);

void addCell(SceneFrame& f, CellShape shape, std::initializer_list<int> nodes) {
  f.shapes.push_back(shape);
  f.connectivity.insert(f.connectivity.end(), nodes.begin(), nodes.end());
  f.offsets.push_back(static_cast<int>(f.connectivity.size()));
}

FieldArray vectorField(const std::string& name, const Eigen::VectorXd& v) {
  return {name, 3, std::vector<double>(v.data(), v.data() + v.size())};
}
}  // namespace

const FieldArray* SceneFrame::cellField(const std::string& name) const {
  for (const auto& a : cellData)
    if (a.name == name) return &a;
  return nullptr;
}

const FieldArray* SceneFrame::pointField(const std::string& name) const {
  for (const auto& a : pointData)
    if (a.name == name) return &a;
  return nullptr;
}

const std::vector<std::string>& FrameFields::names() {
  return vtuPointFieldNames();
}

void FrameFields::select(const std::vector<std::string>& chosen) {
  displacement = velocity = acceleration = reaction = appliedLoad = false;
  for (const auto& c : chosen) {
    if (c == "displacement")
      displacement = true;
    else if (c == "velocity")
      velocity = true;
    else if (c == "acceleration")
      acceleration = true;
    else if (c == "reaction")
      reaction = true;
    else if (c == "applied_load")
      appliedLoad = true;
    else
      throw std::invalid_argument("unknown field '" + c + "'");
  }
}

SceneFrame buildFrame(StructuralSystem& sys, const StructuralState& s, const EquilibriumPoint& eq,
                      const FrameFields& fields, bool inertia) {
  const Model& m = sys.model();
  ++sys.workCounters().sceneFrames;
  SceneFrame f;
  f.t = s.t;
  f.points.assign(s.x.data(), s.x.data() + s.x.size());
  auto at = [&](int n) { return Vec3(s.x.segment<3>(3 * n)); };
  auto atEq = [&](int n) { return Vec3(eq.x.segment<3>(3 * n)); };  // forces

  // Parts: line sets, then membrane sets, then the point masses.
  for (const auto& ls : m.lineSets) f.partNames.push_back(ls.name);
  const int membranePart0 = static_cast<int>(f.partNames.size());
  for (const auto& ms : m.membraneSets) f.partNames.push_back(ms.name);
  const int massPart = static_cast<int>(f.partNames.size());
  f.partNames.push_back("point_masses");

  CellFields c;
  for (const auto& e : m.cables) {
    if (m.lineSets[e.set].cutBy(s.t)) continue;  // cut ([[events]]): no longer in the structure
    const auto& mat = m.materials[e.material];
    const auto r = kernels::cableForce(atEq(e.a), atEq(e.b), e.L, mat, false);
    addCell(f, CellShape::Line, {e.a, e.b});
    c.add(mat.tensionOnly ? CellKind::Cable : CellKind::Truss, e.set, r.axialForce, r.strain, kNaN2,
          kNaN2, -1, kNaN, -1, kNaN);
  }
  for (size_t g = 0; g < m.groups.size(); ++g) {
    const auto& def = m.groups[g];
    const auto& st = sys.termList().slidingGroups()[g]->state();
    const auto& mat = m.materials[def.material];
    for (int k = 0; k < def.numElements(); ++k) {
      const int a = def.chain[k], b = def.chain[k + 1];
      const int sl = st.sliderOfElement(k);
      if (sl < 0) {
        const auto r = kernels::cableForce(atEq(a), atEq(b), st.refLength(k), mat, false);
        addCell(f, CellShape::Line, {a, b});
        c.add(CellKind::SlidingInactive, def.set, r.axialForce, r.strain, kNaN2, kNaN2, -1, kNaN,
              static_cast<int>(g), kNaN);
        continue;
      }
      const int node = def.sliders[sl];
      const auto parts = sys.termList().slidingGroups()[g]->activeParts(k, eq.x);
      const double sMat = st.materialCoordinate(sl, s.x);
      const bool friction = st.hasFriction(sl);
      const double stick = friction ? static_cast<double>(st.friction(sl).state) : kNaN;
      const double ratio = parts.N1 > 0.0 ? parts.N2 / parts.N1 : kNaN;
      addCell(f, CellShape::Line, {a, node});
      c.add(CellKind::SlidingActivePart, def.set, parts.N1, parts.strain1, kNaN2, kNaN2, -1, kNaN,
            static_cast<int>(g), sMat, stick, ratio);
      addCell(f, CellShape::Line, {node, b});
      c.add(CellKind::SlidingActivePart, def.set, parts.N2, parts.strain2, kNaN2, kNaN2, -1, kNaN,
            static_cast<int>(g), sMat, stick, ratio);
    }
  }
  if (!m.membranes.empty()) {
    // Pressure on each element now: the sum of the loads on its set, with per-element factors.
    std::vector<double> pressure(m.membranes.size(), 0.0);
    for (const auto& load : m.pressures) {
      long k = 0;
      for (size_t e = 0; e < m.membranes.size(); ++e) {
        if (m.membranes[e].set != load.set) continue;
        const double factor = load.elementFactor.empty() ? 1.0 : load.elementFactor[k];
        pressure[e] += load.at(s.t) * factor;
        ++k;
      }
    }
    const auto* mt = sys.termList().membranes();
    for (size_t e = 0; e < m.membranes.size(); ++e) {
      const auto& el = m.membranes[e];
      if (el.numNodes == 3)
        addCell(f, CellShape::Triangle, {el.nodes[0], el.nodes[1], el.nodes[2]});
      else
        addCell(f, CellShape::Quad, {el.nodes[0], el.nodes[1], el.nodes[2], el.nodes[3]});
      const auto& st = mt->elementStates()[e];
      c.add(CellKind::Membrane, membranePart0 + el.set, kNaN, kNaN, st.principalStress,
            st.principalStrain, static_cast<int>(st.state), pressure[e], -1, kNaN);
      c.setResultant(st.principalResultant, m.membraneMaterials[el.material].strength);
    }
  }
  for (int n = 0; n < m.numNodes(); ++n) {
    if (m.pointMass[n] <= 0.0) continue;
    addCell(f, CellShape::Vertex, {n});
    c.add(CellKind::PointMass, massPart, kNaN, kNaN, kNaN2, kNaN2, -1, kNaN, -1, kNaN);
  }
  f.cellData = c.take();

  if (fields.displacement) {
    Eigen::VectorXd u(s.x.size());
    for (int n = 0; n < m.numNodes(); ++n) u.segment<3>(3 * n) = at(n) - m.X[n];
    f.pointData.push_back(vectorField("displacement", u));
  }
  if (fields.velocity) f.pointData.push_back(vectorField("velocity", s.v));
  if (fields.acceleration) f.pointData.push_back(vectorField("acceleration", s.a));
  if (fields.reaction || fields.appliedLoad) {
    const auto forces = sys.nodalForces(eq.x, eq.v, eq.a, eq.t, inertia);
    if (fields.reaction) f.pointData.push_back(vectorField("reaction", forces.reaction));
    if (fields.appliedLoad) f.pointData.push_back(vectorField("applied_load", forces.applied));
  }
  return f;
}

}  // namespace chute
