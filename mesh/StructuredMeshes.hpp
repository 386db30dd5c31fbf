#pragma once
// Structured membrane meshes generated straight into a model: a flat disk of triangles and a
// flat rectangle of triangles or quadrilaterals. Generated nodes are named "<name>.<id>";
// special nodes and node sets are listed with each generator.
#include <string>

#include "model/Model.hpp"

namespace chute::mesh {

// Disk of radius `radius` centred at `centre` in the plane z = centre.z, `rings` rings of
// triangles (ring k has 6k nodes), normals +z. Node "<name>.center"; node sets "<name>" (all) and
// "<name>.rim" (the outer ring).
void addDisk(Model& m, const std::string& name, int set, int material, const Vec3& centre,
             double radius, int rings);

// Rectangle [x0, x0 + lx] x [y0, y0 + ly] at z = z0, nx x ny cells, quads or two triangles per
// cell (diagonals alternating), normals +z. Nodes "<name>.c00", ".c10", ".c11", ".c01" (corners)
// and "<name>.center" when nx and ny are even; node sets "<name>", "<name>.xmin", ".xmax",
// ".ymin", ".ymax", ".edge".
void addRectangle(Model& m, const std::string& name, int set, int material, const Vec3& corner,
                  double lx, double ly, int nx, int ny, bool quads);

}  // namespace chute::mesh
