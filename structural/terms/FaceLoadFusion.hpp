#pragma once
// The explicit step's face loads in the membranes' pass (docs/formulation.md P2): the membrane
// term adds the pressure and face drag of the triangles it took (MembraneTerm::takeFaceLoads) to
// their forces, and the pressure and face-drag terms leave those faces out, in the evaluations
// where fusedFaceLoads() holds and only there: an explicit step's forces, residual only. Every
// other evaluation (the start's, the energy balance's loads, output, implicit steps) has each
// term add its own.
#include <memory>
#include <vector>

#include "assembly/SystemAssembler.hpp"
#include "assembly/Term.hpp"
#include "model/Model.hpp"

namespace chute {

// Per membrane element: whether the membrane term took its face loads.
using TakenFaces = std::shared_ptr<const std::vector<char>>;

inline bool fusedFaceLoads(const EvalPoint& p, const SystemAssembler& out) {
  return p.explicitStep > 0.0 && !out.wantMatrix() && p.zeroAcceleration && !p.xStart &&
         p.inertia && !p.inertiaOnly;
}

// The faces of each of a term's loads on membrane sets (loads: the model's pressures or face
// drags, each with its `set`): the set's elements with their places in the set, in the model's
// order, all of them and those the membrane term did not take (the explicit step's).
class FacesOfLoads {
 public:
  struct Face {
    int element, inSet;
  };
  using Lists = std::vector<std::vector<Face>>;
  template <class Loads>
  FacesOfLoads(const Model& m, const Loads& loads) : all_(loads.size()) {
    for (size_t li = 0; li < loads.size(); ++li) {
      int inSet = 0;
      for (size_t k = 0; k < m.membranes.size(); ++k)
        if (m.membranes[k].set == loads[li].set) all_[li].push_back({static_cast<int>(k), inSet++});
    }
    left_ = all_;
  }
  void leave(const TakenFaces& taken) {
    for (size_t li = 0; li < all_.size(); ++li) {
      left_[li].clear();
      for (const Face& f : all_[li])
        if (!(taken && (*taken)[f.element])) left_[li].push_back(f);
    }
  }
  // The faces an evaluation goes over (left_ is all_ where nothing was taken).
  const Lists& of(const EvalPoint& p, const SystemAssembler& out) const {
    return fusedFaceLoads(p, out) ? left_ : all_;
  }
  // How many faces the explicit step goes over (the split's cost).
  double left() const {
    double n = 0.0;
    for (const auto& l : left_) n += static_cast<double>(l.size());
    return n;
  }

 private:
  Lists all_, left_;
};

}  // namespace chute
