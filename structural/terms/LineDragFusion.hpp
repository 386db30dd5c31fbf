#pragma once
// The explicit step's drag of the cables in the cables' pass (docs/formulation.md CB1): the cable
// term adds the drag of the cables it took (CableTerm::takeLineDrag) to their forces, and the
// line-drag term leaves those cables out, in the evaluations where fusedLineDrag() holds and only
// there: an explicit step's forces, residual only, without mass damping. Every other evaluation
// (the start's, the energy balance's loads, output, implicit steps) has each term add its own.
#include <memory>
#include <vector>

#include "terms/FaceLoadFusion.hpp"
#include "terms/LineElementAssembly.hpp"

namespace chute {

// Per cable (Model::cables): whether the cable term took its drag.
using TakenCables = std::shared_ptr<const std::vector<char>>;

inline bool fusedLineDrag(const Model& m, const EvalPoint& p, const SystemAssembler& out) {
  return fusedFaceLoads(p, out) && line_assembly::explicitForcesOnly(m, p, out);
}

}  // namespace chute
