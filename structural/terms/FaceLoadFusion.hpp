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

namespace chute {

// Per membrane element: whether the membrane term took its face loads.
using TakenFaces = std::shared_ptr<const std::vector<char>>;

inline bool fusedFaceLoads(const EvalPoint& p, const SystemAssembler& out) {
  return p.explicitStep > 0.0 && !out.wantMatrix() && p.zeroAcceleration && !p.xStart &&
         p.inertia && !p.inertiaOnly;
}

}  // namespace chute
