#include "terms/TermList.hpp"

#include <algorithm>

#include "terms/CableTerm.hpp"
#include "terms/CanopyFlowTerm.hpp"
#include "terms/FaceDragTerm.hpp"
#include "terms/LineDragTerm.hpp"
#include "terms/MembraneTerm.hpp"
#include "terms/PointMassTerm.hpp"
#include "terms/PressureTerm.hpp"
#include "terms/contact/ContactTerm.hpp"
#include "terms/sliding/SlidingGroupTerm.hpp"

namespace chute {

TermList::TermList(const Model& model, TermOptions options,
                   std::vector<std::unique_ptr<Term>> extraTerms) {
  // Only what the scene uses: a term exists only if the model has something for it.
  CableTerm* cables = nullptr;
  if (!model.cables.empty()) {
    auto t = std::make_unique<CableTerm>(model);
    cables = t.get();
    terms_.push_back(std::move(t));
  }
  for (size_t g = 0; g < model.groups.size(); ++g) {
    auto t = std::make_unique<SlidingGroupTerm>(model, static_cast<int>(g), options.search);
    groups_.push_back(t.get());
    terms_.push_back(std::move(t));
  }
  if (std::any_of(model.pointMass.begin(), model.pointMass.end(), [](double m) { return m > 0; }))
    terms_.push_back(std::make_unique<PointMassTerm>(model));
  if (!model.membranes.empty()) {
    auto t = std::make_unique<MembraneTerm>(model);
    membranes_ = t.get();
    terms_.push_back(std::move(t));
  }
  // P2: the explicit step's pressure and face drag of the membranes' triangles in their pass.
  const TakenFaces taken = membranes_ && (!model.pressures.empty() || !model.faceDrags.empty())
                               ? membranes_->takeFaceLoads()
                               : nullptr;
  if (!model.pressures.empty()) {
    auto t = std::make_unique<PressureTerm>(model);
    t->leaveFaces(taken);
    terms_.push_back(std::move(t));
  }
  if (!model.drags.empty()) {
    std::vector<const SlidingGroupState*> states;
    for (auto* g : groups_) states.push_back(&g->state());
    auto t = std::make_unique<LineDragTerm>(model, states);
    // CB1: the explicit step's drag of the cables in the cables' pass.
    if (cables) t->leaveCables(cables->takeLineDrag());
    std::vector<char> takenGroups;
    for (auto* g : groups_) takenGroups.push_back(g->takeLineDrag() ? 1 : 0);
    if (std::find(takenGroups.begin(), takenGroups.end(), 1) != takenGroups.end())
      t->leaveGroups(std::move(takenGroups));
    terms_.push_back(std::move(t));
  }
  if (!model.faceDrags.empty()) {
    auto t = std::make_unique<FaceDragTerm>(model);
    t->leaveFaces(taken);
    terms_.push_back(std::move(t));
  }
  for (size_t f = 0; f < model.canopyFlows.size(); ++f) {
    auto t = std::make_unique<CanopyFlowTerm>(model, static_cast<int>(f));
    // FL13: the explicit step's airflow's loads in the membranes' pass (one canopy).
    if (membranes_ && options.takeCanopyFlow) membranes_->takeCanopyFlow(*t);
    canopyFlows_.push_back(t.get());
    terms_.push_back(std::move(t));
  }
  if (model.contact.enabled) {
    std::vector<const SlidingGroupState*> states;
    for (auto* g : groups_) states.push_back(&g->state());
    auto t = std::make_unique<ContactTerm>(model, states);
    contact_ = t.get();
    terms_.push_back(std::move(t));
  }
  for (auto& t : extraTerms) terms_.push_back(std::move(t));
}

TermList::~TermList() = default;

const std::vector<std::string>& TermList::kinds() {
  static const std::vector<std::string> kinds{"cables",    "sliding_group", "point_masses",
                                              "membranes", "pressure",      "drag",
                                              "face_drag", "canopy_flow",   "contact"};
  return kinds;
}

}  // namespace chute
