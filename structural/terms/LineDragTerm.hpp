#pragma once
// Drag on line sets (cables, sliding groups) relative to a wind (docs/formulation.md section 6),
// with position and velocity tangents.
#include <vector>

#include "assembly/Term.hpp"
#include "model/Model.hpp"
#include "terms/LineDragFusion.hpp"
#include "terms/sliding/SlidingGroupState.hpp"

namespace chute {

class LineDragTerm final : public Term {
 public:
  // groups: the sliding-group states in model order (drag on active elements acts on both parts).
  LineDragTerm(const Model& m, std::vector<const SlidingGroupState*> groups);
  const char* name() const override { return "drag"; }
  bool doesExternalWork() const override { return true; }
  void addCouplings(std::vector<std::vector<int>>& cliques) const override;
  void assemble(const EvalPoint& p, SystemAssembler& out) override;
  void addEnergy(const Eigen::VectorXd&, const Eigen::VectorXd&, double,
                 EnergyBreakdown&) const override {}
  bool symmetricJacobian() const override { return false; }
  double assemblyCost() const override;
  // Reads the model and the sliding groups' active elements, which the search sets before an
  // assembly and no assembly writes: it may run on either thread, beside the groups themselves.
  bool assemblesApart() const override { return true; }
  // CB1: the cables whose drag the cable term adds on the explicit step's evaluations
  // (fusedLineDrag), left out there (nullptr: none).
  void leaveCables(const TakenCables& taken);
  // CB1: per sliding group (model order), whether the group adds the drag of its inactive
  // elements on those evaluations; this term then adds only its active elements' two parts.
  void leaveGroups(std::vector<char> taken);

 private:
  // With the Jacobian (the residual-only segments are inlined into assemble's loop).
  void addSegment(int a, int b, const kernels::Vec3& wind, double c, const EvalPoint& p,
                  SystemAssembler& out) const;
  // segment(a, b, wind, coefficient) for every straight segment under drag, in model order: the
  // edges and cables of each drag load's set, and its sliding groups' elements (an active one as
  // its two parts through the slider).
  // fused: the explicit step's evaluation, without the cables the cable term took (CB1).
  template <class Segment>
  void forEachSegment(const EvalPoint& p, bool fused, Segment&& segment) const;
  const Model* m_;
  std::vector<const SlidingGroupState*> groups_;
  // Per drag load (model order): the cables and the sliding groups of its line set, in model
  // order (found once, not by a search of every cable and group at every evaluation).
  std::vector<std::vector<int>> cablesOf_, groupsOf_;
  std::vector<std::vector<int>> cablesLeft_;  // cablesOf_ less the taken cables (CB1)
  bool cablesTaken_ = false;
  std::vector<char> groupsTaken_;  // per model group (CB1); empty: none
};

}  // namespace chute
