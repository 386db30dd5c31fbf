#pragma once
// The probes a parachute engineer reads (docs/output.md): the pull of lines on a node (the
// opening force at a confluence or payload), the largest line force, and a canopy's flow figures
// (docs/flight.md).
#include <Eigen/Core>
#include <vector>

#include "model/Model.hpp"
#include "solver/StructuralState.hpp"
#include "solver/StructuralSystem.hpp"

namespace chute {

// The resultant force the elements of line sets `sets` put on node `node` at positions x (each
// element's axial force along it, towards its other end: a slack line pulls nothing).
Vec3 linePull(const Model& m, const StructuralSystem& sys, int node, const std::vector<int>& sets,
              const Eigen::VectorXd& x, double t);
// The largest axial force over the elements of line sets `sets` (both parts of a slider's
// element).
double largestLineForce(const Model& m, const StructuralSystem& sys, const std::vector<int>& sets,
                        const Eigen::VectorXd& x, double t);
// A canopy's figures, in the columns of the `canopy` probe: volume, projected diameter, inside
// pressure (over the ambient), dynamic pressure, airspeed, descent speed (the canopy's velocity
// along gravity, or -z without it), inflow, cloth outflow, vent outflow, swing (degrees between
// the canopy's axis and the upward vertical).
std::vector<double> canopyFigures(const Model& m, const StructuralSystem& sys, int membraneSet,
                                  const StructuralState& s);

}  // namespace chute
