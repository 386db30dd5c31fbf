#pragma once
// The terms of one scene's equations, made from its model: only what the scene uses (no drag term
// without drag, no sliding search without sliding groups), in the one order every evaluation,
// checkpoint and history record follows. The only place that names the kinds of term; the
// solver sees Term. Output code that reports what a kind of term knows (a slider's element, a
// membrane's wrinkling) finds it here.
#include <memory>
#include <string>
#include <vector>

#include "assembly/Term.hpp"
#include "model/Model.hpp"
#include "model/SliderSearch.hpp"

namespace chute {

class SlidingGroupTerm;
class MembraneTerm;
class CanopyFlowTerm;
class ContactTerm;

// The choices the terms are built with (from the case's [solver] table).
struct TermOptions {
  SliderSearch search = SliderSearch::MaterialCoordinate;
  // FL13: the membranes' pass takes a canopy's airflow's loads where it can (off: each term its
  // own, the reference the tests compare it with).
  bool takeCanopyFlow = true;
  TermOptions() = default;
  TermOptions(SliderSearch s) : search(s) {}  // NOLINT: implicit, the one choice there is
};

class TermList {
 public:
  // extraTerms: terms the model does not describe (loads supplied by a coupled flow solver),
  // appended after the model's.
  TermList(const Model& model, TermOptions options,
           std::vector<std::unique_ptr<Term>> extraTerms = {});
  TermList(TermList&&) = default;
  TermList& operator=(TermList&&) = default;
  ~TermList();

  // The names of every kind of term the model may give (Term::name()), for the test that every
  // kind's history round-trips.
  static const std::vector<std::string>& kinds();

  const std::vector<std::unique_ptr<Term>>& terms() const { return terms_; }
  // The sliding group terms, in the model's group order (empty without sliding groups).
  const std::vector<SlidingGroupTerm*>& slidingGroups() const { return groups_; }
  // The membrane term (nullptr without membranes).
  const MembraneTerm* membranes() const { return membranes_; }
  MembraneTerm* membranes() { return membranes_; }
  // The canopies with loads from the airflow, in the model's order.
  const std::vector<CanopyFlowTerm*>& canopyFlows() const { return canopyFlows_; }
  // Fabric contact (nullptr without [contact]).
  const ContactTerm* contact() const { return contact_; }

 private:
  std::vector<std::unique_ptr<Term>> terms_;
  std::vector<SlidingGroupTerm*> groups_;
  MembraneTerm* membranes_ = nullptr;
  std::vector<CanopyFlowTerm*> canopyFlows_;
  ContactTerm* contact_ = nullptr;
};

}  // namespace chute
