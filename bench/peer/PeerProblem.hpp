#pragma once
// The peer problem of issue 8 (item 3): a canopy of membrane triangles with its suspension lines
// as trusses, under a ramped follower pressure, built the same way for chute and for CalculiX.
//
// The canopy is a disk of quadrilaterals (an O-grid: a central square of n x n cells and four
// blocks of n x m cells out to the circle; or mesh::addDisk's triangles) whose reference geometry
// is a shallow cap
// z = bulge (1 - r^2 / R^2) (stress-free, so a flat membrane's zero out-of-plane stiffness never
// arises and CalculiX can start from the same geometry). Every `lineStride`-th rim node is joined
// to a fixed confluence point below the centre by a truss line of `lineElements` elements.
#include <string>

#include "case/CaseSpec.hpp"

namespace chute::bench {

struct PeerParams {
  bool quads = true;     // O-grid of quads (CalculiX M3D4); false: addDisk triangles (M3D3)
  int rings = 8;         // quads: radial cells of the outer blocks (m); triangles: disk rings
  int square = 8;        // quads: cells along the central square side (n, even)
  int lineStride = 1;    // a line at every lineStride-th rim node
  int lineElements = 4;  // truss elements per line (even: a node at the line's midpoint)
  double radius = 1.0;   // m
  double bulge = 0.0;    // cap height of the reference geometry, m (0: flat; see README)
  double confluenceDepth = 2.0;  // confluence below the rim plane, m
  // Canopy fabric (SI units).
  double fabricE = 1.0e9, fabricNu = 0.3, fabricThickness = 1.0e-4, fabricDensity = 500.0;
  // Lines.
  double lineE = 5.0e10, lineArea = 1.0e-7, lineDensity = 1.0e4;
  // Line mass as point masses at the line nodes (the trusses massless): CalculiX expands a T3D2
  // into a 3D solid whose mass matrix is neither chute's consistent nor lumped line mass.
  bool lumpedLineMass = true;
  double pressure = 100.0;   // Pa, along the canopy's +z node-order normal (follower)
  double rampTime = 2.0e-3;  // linear ramp from 0
  double dt = 1.0e-4;
  int steps = 100;
  double rhoInf = 1.0;
  std::string integrator = "bossak";  // rho_inf = 1: Newmark's trapezoidal rule = HHT alpha = 0
};

// Node ids of the probes: canopy apex (disk centre), the rim node of the first line, and the
// midpoint node of the first line.
struct PeerProbes {
  int apex = -1, rim = -1, lineMid = -1;
};

struct PeerProblem {
  CaseSpec spec;  // model, solver (dynamic, consistent mass) and node_position probes
  PeerProbes probes;
  int confluence = -1;
};

PeerProblem buildPeerProblem(const PeerParams& p);

}  // namespace chute::bench
