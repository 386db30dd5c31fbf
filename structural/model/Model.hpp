#pragma once
// The structural model: nodes, constraints, point masses, materials and line elements.
// Knows nothing of parachutes or of time integration.
#include <Eigen/Core>
#include <array>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "kernels/CanopyFlow.hpp"
#include "kernels/LineElementTypes.hpp"
#include "kernels/MembraneKernel.hpp"
#include "kernels/SliderFriction.hpp"
#include "model/ContactDef.hpp"

namespace chute {

using Vec3 = Eigen::Vector3d;

struct CableElement {
  int a = -1, b = -1;  // node ids
  double L = 0.0;      // reference length
  int material = -1;   // index into Model::materials
  int set = -1;        // index into Model::lineSets
};

// A named set of line elements (a `[[cables]]` or `[[sliding_groups]]` entry), for output.
// A cable set may be cut at a time (`[[events]] cut = ...`): it carries load up to cutAt and is
// gone from the assembly after it (t > cutAt); the run lands a step on cutAt.
struct LineSet {
  std::string name;
  bool sliding = false;
  double cutAt = std::numeric_limits<double>::infinity();
  bool cutBy(double t) const { return t > cutAt; }    // in the forces of a step ending at t
  bool goneAt(double t) const { return t >= cutAt; }  // in the state at t, after its events
};

// A chain of sliding elements and the slider points allowed to pass along it
// (docs/formulation.md section 4).
struct SlidingGroupDef {
  std::string name;
  int material = -1;
  int set = -1;
  std::vector<int> chain;          // node ids along the chain, chain.size() - 1 elements
  std::vector<double> refLength;   // reference length of each element
  std::vector<int> sliders;        // slider node ids
  std::vector<int> initialActive;  // initially active element per slider
  // Friction, lock and one-way flow per slider (docs/friction.md); empty: all frictionless.
  std::vector<kernels::SliderFrictionLaw> friction;
  const kernels::SliderFrictionLaw* frictionOf(int slider) const {
    return static_cast<size_t>(slider) < friction.size() && friction[slider].frictional()
               ? &friction[slider]
               : nullptr;
  }
  int numElements() const { return static_cast<int>(refLength.size()); }
};

// A membrane element: triangle (3 nodes) or quadrilateral (4 nodes, counter-clockwise about its
// normal, which is also the direction pressure pushes).
struct MembraneElement {
  std::array<int, 4> nodes{-1, -1, -1, -1};
  int numNodes = 3;
  int material = -1;  // index into Model::membraneMaterials
  int set = -1;       // index into Model::membraneSets
};

struct MembraneSet {
  std::string name;
  bool wrinkling = true;
  double prestrain = 0.0;  // reference = initial geometry shrunk by 1 / (1 + prestrain)
};

// Follower pressure on a membrane set: p(t) = pressure min(1, t / rampTime).
struct PressureLoadDef {
  int set = -1;
  double pressure = 0.0;
  double rampTime = 0.0;
  std::vector<double> elementFactor;  // per element of the set, in order; empty: uniform
  double at(double t) const {
    return rampTime > 0.0 && t < rampTime ? pressure * t / rampTime : pressure;
  }
};

// Drag on the line elements of a line set, or on the edges joining consecutive nodes of a node
// set (membrane edges, e.g. a slider's four edges) (docs/formulation.md section 6).
struct DragLoadDef {
  int lineSet = -1;
  std::vector<std::array<int, 2>> edges;  // used when lineSet < 0
  double coefficient = 0.0;               // (1/2) rho_air Cd d
  Vec3 wind = Vec3::Zero();
};

// Drag on the faces of a membrane set (docs/formulation.md FD1; kernels/FaceDrag).
struct FaceDragLoadDef {
  int set = -1;              // membrane set
  double coefficient = 0.0;  // (1/2) rho_air Cd
  Vec3 wind = Vec3::Zero();
  bool steadySubtracted = false;  // drag relative to the fabric at rest in the wind
};

// The air the structure moves in ([air]): its density and ambient pressure, and the wind, the
// air's velocity in the model's frame (docs/flight.md).
struct AirSpec {
  bool given = false;
  double density = 0.0, pressure = 0.0;
  Vec3 wind = Vec3::Zero();
};

// Loads from the airflow on a canopy (docs/flight.md FL1-FL12, [[loads.canopy_flow]]): a
// membrane set whose node-order normals point out of the canopy (the way its pressure pushes).
struct CanopyFlowDef {
  int set = -1;
  double baseCoefficient = 0.0;      // Cb (FL7)
  double discharge = 0.61;           // Cd of the mouth and the vent (FL4)
  kernels::ClothPermeability cloth;  // FL6
  double normalDrag = 1.17;          // Cn of the fabric's normal motion (FL8)
  double apparentMass = 8.0 / 3.0;   // k_a: the air moving with it is k_a rho R_p^3 (FL11)
  double gamma = 1.4;                // the captured air's isentropic exponent (FL3)
  double volumeFloor = 1e-4;  // of the pattern's hemisphere: the least volume the gas law sees
  double initialInsideGauge = 0.0;  // p_in - p_a of the air the start holds (FL3)
};

// How a node's three dofs are constrained: free, or prescribed. A prescribed dof follows
// x(t) = X + velocity t + amplitude sin(2 pi frequency t) (all zero: fixed where it starts).
struct NodeConstraint {
  std::array<bool, 3> fixed{false, false, false};
  Vec3 velocity = Vec3::Zero();
  Vec3 amplitude = Vec3::Zero();
  double frequency = 0.0;
  // Prescribed position, velocity and acceleration of dof k at time t.
  double position(double X, int k, double t) const;
  double speed(int k, double t) const;
  double acceleration(int k, double t) const;
};

struct Model {
  std::vector<Vec3> X;   // reference coordinates (elements are stress-free here)
  std::vector<Vec3> u0;  // initial displacement: the run starts at X + u0 (a bulged or folded
                         // start whose reference is the flat cutting pattern)
  std::vector<std::string> nodeName;
  std::map<std::string, int> nodeByName;
  std::vector<NodeConstraint> constraint;
  std::vector<double> pointMass;

  std::vector<std::string> materialName;
  std::vector<kernels::LineMaterial> materials;
  std::vector<LineSet> lineSets;
  std::vector<CableElement> cables;
  std::vector<SlidingGroupDef> groups;

  std::vector<std::string> membraneMaterialName;
  std::vector<kernels::MembraneMaterial> membraneMaterials;
  std::vector<MembraneSet> membraneSets;
  std::vector<MembraneElement> membranes;
  std::map<std::string, std::vector<int>> nodeSets;  // named node sets (e.g. a mesh's rim)

  std::vector<PressureLoadDef> pressures;
  std::vector<DragLoadDef> drags;
  std::vector<FaceDragLoadDef> faceDrags;
  std::vector<CanopyFlowDef> canopyFlows;
  AirSpec air;
  // Initial velocity of each node (free dofs; a prescribed dof follows its constraint): a run
  // that starts in motion, e.g. at line stretch at the system's speed ([initial]).
  std::vector<Vec3> v0;
  ContactDef contact;  // fabric contact ([contact]); enabled = false: none

  Vec3 gravity = Vec3::Zero();
  double massDamping = 0.0;  // Rayleigh mass-proportional damping C = alpha M (every mass)
  kernels::MassKind massKind = kernels::MassKind::Lumped;

  int numNodes() const { return static_cast<int>(X.size()); }
  Vec3 initialVelocity(int n) const {
    return static_cast<size_t>(n) < v0.size() ? v0[n] : Vec3::Zero();
  }
  int addNode(const Vec3& x, const std::string& name = {});
  int nodeId(const std::string& name) const;  // throws std::out_of_range if unknown
  bool hasGravity() const { return gravity.squaredNorm() > 0.0; }
  double totalLineMass() const;  // sum of rho A0 L over all line elements
  // Lines, membranes (rho t A on the reference) and point masses.
  double totalMass() const;
  // The first time a set is cut after t (infinity if none): where a run must land a step.
  double nextCutAfter(double t) const;
  bool hasCutAt(double t) const;      // a set is cut exactly at t
  int membranesInSet(int set) const;  // membrane elements of a set
};

// The part each node belongs to, for reports (the mass added by mass scaling): its first membrane
// set, line set or sliding group, else "point masses".
std::vector<std::string> nodePartNames(const Model& m);

// The nodes named for a message: each node's name ("node k", 1-based, for an unnamed one), the
// first eight, then "and N more".
std::string nodeNames(const Model& m, const std::vector<int>& nodes);

// Equation numbering of the free dofs; constrained dofs map to -1.
class DofMap {
 public:
  explicit DofMap(const Model& m);
  int eq(int node, int k) const { return eq_[3 * node + k]; }
  int eqOfDof(int dof) const { return eq_[dof]; }
  // The first of a node's three consecutive equations when all three of its dofs are free, else
  // -1: one look-up per node instead of three for the assembly's scatter.
  int freeNodeEq(int node) const { return freeNodeEq_[node]; }
  const int* freeNodeEqs() const { return freeNodeEq_.data(); }  // all of them, by node
  // The free dofs as runs of consecutive dofs with consecutive equations, in order: loops over
  // the free dofs without a test per dof (the explicit step's update of every dof).
  struct FreeRun {
    int dof, eq, count;
  };
  const std::vector<FreeRun>& freeRuns() const { return freeRuns_; }
  int numEquations() const { return numEq_; }
  int numDofs() const { return static_cast<int>(eq_.size()); }

 private:
  std::vector<int> eq_;
  std::vector<int> freeNodeEq_;
  std::vector<FreeRun> freeRuns_;
  int numEq_ = 0;
};

}  // namespace chute
