#pragma once
// One output time of a run as plain arrays (no VTK here): the current geometry as cells, and the
// point and cell fields the VTU files carry (docs/output.md).
//  - lines: cables and trusses as two-node cells; an inactive sliding element likewise; an active
//    sliding element as its two straight parts through the slider;
//  - membranes: triangles and quadrilaterals; point masses: vertices.
// Floating fields that do not apply to a cell (axial force of a membrane) are NaN; integer-valued
// ones are -1.
#include <string>
#include <vector>

#include "solver/EquilibriumPoint.hpp"
#include "solver/StructuralSystem.hpp"

namespace chute {

struct FieldArray {
  std::string name;
  int components = 1;
  std::vector<double> values;  // components per point or cell, interleaved
  bool integer = false;        // integer-valued (codes and indices): written as Int32
  // Names of the components (ComponentName0, ... in the file): ParaView lists "N1", "N2" rather
  // than its default "X", "Y". Empty: none written.
  std::vector<std::string> componentNames = {};
};

// VTK cell type codes (vtkCellType.h), kept here so this file needs no VTK.
enum class CellShape : int { Vertex = 1, Line = 3, Triangle = 5, Quad = 9 };

// Element kind codes of the "kind" cell field.
enum class CellKind : int {
  Cable = 1,
  Truss = 2,
  SlidingInactive = 3,
  SlidingActivePart = 4,
  Membrane = 5,
  PointMass = 6
};

struct SceneFrame {
  double t = 0.0;
  std::vector<double> points;  // current positions, 3 per node
  std::vector<CellShape> shapes;
  std::vector<int> connectivity, offsets;  // offsets: end of each cell in connectivity
  std::vector<FieldArray> pointData, cellData;
  std::vector<std::string> partNames;  // the "part" cell field indexes this list
  int numCells() const { return static_cast<int>(shapes.size()); }
  const FieldArray* cellField(const std::string& name) const;
  const FieldArray* pointField(const std::string& name) const;
};

struct FrameFields {
  bool displacement = true, velocity = true, acceleration = true;
  bool reaction = true, appliedLoad = true;  // need extra residual evaluations
  // The names accepted in a case file's output.vtu.fields (all on by default).
  static const std::vector<std::string>& names();
  void select(const std::vector<std::string>& chosen);  // throws std::invalid_argument
};

// Builds frames of a system; the system's terms hold the element states it reports.
// The geometry and motion are those of s, the forces, strains and reactions those of eq, where
// the step's equations hold (solver/EquilibriumPoint.hpp).
SceneFrame buildFrame(StructuralSystem& sys, const StructuralState& s, const EquilibriumPoint& eq,
                      const FrameFields& fields, bool inertia);
inline SceneFrame buildFrame(StructuralSystem& sys, const StructuralState& s,
                             const FrameFields& fields, bool inertia) {
  return buildFrame(sys, s, EquilibriumPoint{s.x, s.v, s.a, s.t}, fields, inertia);
}

}  // namespace chute
