#pragma once
// Loads from the airflow on one canopy, without a flow solver (docs/flight.md FL1-FL12): the
// relative flow of the canopy as a whole (FL1), the air it has captured at one pressure (FL2-FL3,
// its mass the term's history), the flows through its mouth, vent and cloth that change that mass
// (FL4-FL6, FL9), the outside pressure of the flow around it (FL7), the fabric's own normal
// motion (FL8), and the captured air's inertia with the momentum of the air it takes in (FL10-
// FL11). Residual only: the explicit integrator steps it (the captured air couples every face of
// the canopy through its volume, a dense Jacobian; case/sections refuse implicit integrators).
#include <array>
#include <limits>
#include <vector>

#include "assembly/Term.hpp"
#include "kernels/CanopyFlow.hpp"
#include "kernels/TriangleFlowLoads.hpp"
#include "model/Model.hpp"

namespace chute {

class CanopyFlowTerm final : public Term {
 public:
  CanopyFlowTerm(const Model& m, int flow);
  const char* name() const override { return "canopy_flow"; }
  bool doesExternalWork() const override { return true; }
  bool symmetricJacobian() const override { return false; }
  void addCouplings(std::vector<std::vector<int>>& cliques) const override;
  void assemble(const EvalPoint& p, SystemAssembler& out) override;
  // The kinetic energy of the air moving with the canopy (FL11), and what the captured air
  // brought in with it (EnergyBreakdown::supplied, FL12).
  void addEnergy(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double t,
                 EnergyBreakdown& e) const override;
  // FL11: the air's mass moves with the canopy's nodes by the shares committed with the step.
  bool massChangesAtCommit() const override { return true; }
  const std::vector<int>& committedMassNodes() const override { return nodes_; }
  const double* committedNodalMass() const override;
  // FL12: the captured air is a gas spring over the whole canopy, K = (gamma p / V) a a^T.
  double frequencySquaredBound(const Eigen::VectorXd& x, double t,
                               const std::vector<double>& nodalMass) const override;
  // Taken (FL13), the explicit step's loads are the membranes' work.
  double assemblyCost() const override {
    return taken_ ? 0.0 : 1.3 * static_cast<double>(faces_.size());
  }

  bool hasHistory() const override { return true; }
  void commit(const CommitPoint& c) override;
  void save(History& h) const override;
  void load(HistoryReader& h) override;

  // What the last evaluation of a step found (probes, summary).
  struct Figures {
    double volume = 0.0;         // enclosed by the canopy and its openings
    double mouthArea = 0.0;      // |A_m|
    double projectedArea = 0.0;  // the canopy's area seen along the relative flow
    double insideGauge = 0.0;    // p_in - p_a
    double dynamicPressure = 0.0;
    double inflow = 0.0, ventOutflow = 0.0, clothOutflow = 0.0;  // volume flows
    double capturedMass = 0.0;
    Eigen::Vector3d flowDirection = Eigen::Vector3d::Zero();
    Eigen::Vector3d axis = Eigen::Vector3d::Zero();  // into the canopy through its mouth
  };
  // The figures at positions x and velocities v, with the committed captured air.
  Figures figuresAt(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const;
  int set() const { return def_->set; }
  // The nominal diameter D0 (of the mouth on the flat pattern: the skirt's) and area S0 = pi D0^2
  // / 4, the reference of the drag coefficient C_D0 (docs/flight.md).
  double nominalDiameter() const { return nominalDiameter_; }
  double nominalArea() const;

  // FL13: the membrane term takes the faces' loads on the explicit step's forces
  // (FaceLoadFusion.hpp fusedFaceLoads), when every face is a triangle: takenParameters gives the
  // canopy-wide state for kernels::triangleFlowLoad, the membranes' pass (whole, or in two halves
  // at once) writes each triangle's shares (A / 3, |A| / 3) to its record in faceRecords, and
  // finishTakenPass makes the rest of the evaluation (each node's shares gathered from its
  // triangles' records, the openings, the captured air's update, the inside pressure's and the
  // entrained air's loads per node into out) as assemble would have. assemble then adds nothing
  // on those evaluations. takeFaces: the membranes' triangles in their pass's order, each with
  // its nodes' slots (slotOf), or -1 for one not the canopy's.
  bool trianglesOnly() const;
  void takeFaces(const std::vector<std::array<int, 3>>& triangleSlots);
  int slotOf(int node) const { return slot_[node]; }
  struct FaceSums {
    double volume = 0.0, area = 0.0;
    double cloth = 0.0, dCloth = 0.0;  // FL6's outflow and its derivative in the inside pressure
  };
  // Also keeps the canopy-wide state and the start's gauge for finishTakenPass / finishTakenSums.
  kernels::TriangleFlowParameters takenParameters(const EvalPoint& p);
  // Triangle k's record at 4 k: A / 3, then |A| / 3 (kernels::membraneTriangleForcesAndFlow).
  double* faceRecords() { return faceRecords_.data(); }
  void finishTakenPass(const EvalPoint& p, const FaceSums& sums, SystemAssembler& out);
  // After a pass in two halves: the evaluation from both halves' sums (on one thread), then each
  // half of the nodes' records gathered and their loads added (half 0 and 1, on either thread, at
  // once: each writes its own nodes); finishTakenNodesOver: the nodes [begin, end) so.
  void finishTakenSums(const EvalPoint& p, const FaceSums& sums);
  void finishTakenNodes(SystemAssembler& out, int half);
  void finishTakenNodesOver(SystemAssembler& out, size_t begin, size_t end);

 private:
  struct Loop {
    std::vector<int> nodes;  // in order around the opening
    double sign = 1.0;       // orients its area vector out of the closed surface (FL2)
  };
  // The closed surface's volume and area and the openings' outward area vectors at positions x
  // (FL2).
  struct Geometry {
    double volume = 0.0, area = 0.0;
    Eigen::Vector3d mouth = Eigen::Vector3d::Zero();  // outward area vector of the mouth
    std::vector<Eigen::Vector3d> vents;
  };
  Geometry geometry(const Eigen::VectorXd& x) const;
  // The openings' fans (FL2): their outward area vectors into g, their volume added to g.
  void closeOpenings(const Eigen::VectorXd& x, Geometry& g) const;
  // The one pass over the faces of an evaluation (FL2, FL6, FL8): the volume and area, the
  // cloth's outflow at the inside gauge clothGauge (when permeable), and with keep each node's
  // sums in nodeSums_: its share of the area, of the area vectors, and of the faces' loads at
  // the ambient inside pressure (state s, its insideGauge 0).
  template <bool Keep>
  FaceSums facePass(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                    const kernels::CanopyFlowState& s, double clothGauge, bool permeable) const;
  Eigen::Vector3d loopArea(const Loop& l, const Eigen::VectorXd& x) const;
  // Per canopy node, its share of the canopy's area at x (the captured air's inertia, FL11).
  std::vector<double> areaShares(const Eigen::VectorXd& x) const;
  // FL11: the air moving with the canopy, k_a rho R_p^3 with R_p its projected radius (the
  // canopy's reach from its axis) at x; and that reach.
  double apparentMass(const Eigen::VectorXd& x) const;
  double apparentMassOfVolume(double volume) const;
  double reach(const Eigen::VectorXd& x) const;
  // What the captured air's update over a step needs of an evaluation (FL9): the volume, the
  // openings (the ram pressure into the mouth, the outside pressures at the vents) and the
  // cloth's outflow linearised in the inside pressure about the evaluation's.
  struct AirBudget {
    double volume = 0.0, ram = 0.0, mouthArea = 0.0, dpLinear = 0.0;
    std::vector<std::pair<double, double>> vents;  // (area, outside gauge pressure)
    double cloth = 0.0, dCloth = 0.0, insideGauge = 0.0;
    // The captured mass's rate at a mass M (in the budget's volume), and the mass after a step
    // of length dt from Mn (implicit Euler, FL9).
    double rate(double M, const CanopyFlowTerm& term) const;
    double massAfter(double Mn, double dt, const CanopyFlowTerm& term) const;
  };
  // One evaluation at (x, v): the face loads into out (when given, scaled by loadFactor), the
  // figures, and the air budget.
  struct Evaluation {
    Figures figures;
    AirBudget budget;
    double capturedMass = 0.0;  // at the end of a step (stepDt > 0), else the committed
  };
  Evaluation evaluate(const Eigen::VectorXd& x, const Eigen::VectorXd& v, SystemAssembler* out,
                      double loadFactor, double stepDt) const;
  // Its parts: the canopy-wide state at velocities v (FL1, the inside gauge left 0), the inside
  // gauge of the step's start (the cloth's linearisation, FL9), and what follows the pass over
  // the faces (sums; per-node sums in nodeSums_ when out is given).
  kernels::CanopyFlowState flowState(const Eigen::VectorXd& v,
                                     const InHalves* inHalves = nullptr) const;
  double startGauge() const;
  // loads: an evaluation for the loads (out: where the per-node ones go, or nullptr to add them
  // later with addNodeLoads); otherwise the figures alone. facesTaken: the membranes' pass made
  // the faces' loads (FL13), which the records then do not hold.
  Evaluation complete(const Eigen::VectorXd& x, const FaceSums& sums, kernels::CanopyFlowState s,
                      double gauge, SystemAssembler* out, double loadFactor, double stepDt,
                      bool loads, bool facesTaken) const;
  // FL8's inside pressure p and FL10's entrained air on nodes [begin, end) (their slots), and
  // the faces' loads the records hold unless facesTaken.
  void addNodeLoads(SystemAssembler& out, size_t begin, size_t end, double p, double loadFactor,
                    const Eigen::Vector3d& canopyVelocity, bool facesTaken) const;
  // addNodeLoads with node i's records as record(i) gives them (the halves': merged as read).
  template <class Record>
  void addNodeLoadsOf(SystemAssembler& out, size_t begin, size_t end, double p, double loadFactor,
                      const Eigen::Vector3d& canopyVelocity, bool facesTaken, Record record) const;
  // An explicit step's evaluation at p.t: its captured air and face data kept for the commit.
  void keepStepEvaluation(const EvalPoint& p, const Evaluation& e);

  const Model* m_;
  const CanopyFlowDef* def_;
  std::vector<int> faces_;  // membrane elements of the set
  std::vector<int> nodes_;  // the canopy's nodes, and each node's slot in nodes_
  std::vector<int> slot_;
  struct FaceNodes {
    std::array<int, 4> node{}, slot{};  // model node ids, their slots in nodes_
    int size = 0;                       // 3 or 4
  };
  std::vector<FaceNodes> faceNodes_;  // per face of faces_, in its order
  Loop mouth_;
  std::vector<Loop> vents_;
  double volumeFloor_ = 0.0;
  double nominalDiameter_ = 0.0;
  // History: the captured air's mass (FL3); the apparent mass at the last commit, which the next
  // step's inertia uses (the explicit step evaluates its mass alongside its forces, before the
  // commit), and its rate over the last step (FL10); the kinetic energy the air set moving
  // brought in so far (FL12).
  double captured_ = 0.0, inertiaMass_ = 0.0, massRate_ = 0.0, supplied_ = 0.0;
  // Each node's share of the area at the last commit (FL11's inertia, FL1's canopy velocity), and
  // the volume (FL9's cloth linearisation).
  std::vector<double> committedShares_;
  std::vector<double> nodeMass_;  // inertiaMass_ times committedShares_ (committedNodalMass)
  void formNodeMass();
  double committedVolume_ = 0.0;
  // Of the last evaluation of a step (not history: made again by the next step's evaluation).
  // The captured mass an explicit step's evaluation found at the step's end, and the step's end
  // time (committed with that step only).
  double trialMass_ = 0.0, trialTime_ = -1.0;
  bool taken_ = false;  // FL13
  // From takenParameters to the finish: the canopy-wide state and the start's gauge.
  struct Pass {
    kernels::CanopyFlowState state;
    double gauge = 0.0;
  } pass_;
  // Between finishTakenSums and finishTakenNodes.
  struct Halves {
    double insideGauge = 0.0, loadFactor = 1.0, area = 0.0;
    Eigen::Vector3d canopyVelocity = Eigen::Vector3d::Zero();
  } halves_;
  // Scratch of the last evaluation (its one pass over the faces serves the volume, the cloth,
  // the loads and the commit): per node, the volume, and the time of the explicit step's end
  // whose positions they belong to (NaN: none).
  struct NodeSums {
    Eigen::Vector3d area;   // a_i: the share of the area vectors at node i
    double share;           // the share of the area (over the whole area once the pass is done)
    Eigen::Vector3d force;  // the faces' loads at p_in = p_a (not when taken: the membranes')
    double unused;          // one cache line per node
  };
  mutable std::vector<NodeSums> nodeSums_;
  // FL13: the triangles' records, and each node's records (their offsets) from start[i] to
  // start[i + 1].
  std::vector<double> faceRecords_;
  std::vector<int> nodeRecordsStart_, nodeRecords_;
  mutable double scratchVolume_ = 0.0;
  mutable double scratchTime_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace chute
