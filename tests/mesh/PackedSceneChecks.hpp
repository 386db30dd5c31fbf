#pragma once
// Shared checks of a generated start (packed parachutes and clusters): the case read back into a
// model, the start's internal force and line lengths, and the intersection count of its first
// frame as a run would write it.
#include <Eigen/Geometry>
#include <algorithm>
#include <string>

#include "IntersectionCheck.hpp"
#include "IntersectionFrames.hpp"
#include "case/CaseSpec.hpp"
#include "solver/StructuralSystem.hpp"

namespace chute::scenes {

struct StartFigures {
  double force = 0.0, forceScale = 0.0;  // |internal force| at the start, largest E A
  double worstLine = 0.0;                // largest line element length / reference length
  mesh::IntersectionCounts intersections;
  size_t triangles = 0, segments = 0;
};

inline StartFigures startFigures(const std::string& caseFile) {
  CaseSpec c = readCase(caseFile);
  Model& m = c.model;
  m.gravity.setZero();
  m.pressures.clear();
  m.drags.clear();
  StructuralSystem sys(m, c.solver.search);
  StructuralState s;
  s.x.resize(3 * m.numNodes());
  for (int i = 0; i < m.numNodes(); ++i) s.x.segment<3>(3 * i) = m.X[i] + m.u0[i];
  s.v = s.a = Eigen::VectorXd::Zero(3 * m.numNodes());
  StartFigures f;
  sys.assemble(EvalPoint::statics(s.x, s.v, 0.0, 1.0), false);
  f.force = sys.residual().norm();
  for (const auto& mat : m.materials) f.forceScale = std::max(f.forceScale, mat.E * mat.area);
  for (const auto& e : m.cables)
    f.worstLine =
        std::max(f.worstLine, (s.x.segment<3>(3 * e.b) - s.x.segment<3>(3 * e.a)).norm() / e.L);
  FrameFields none;
  none.select({});
  const auto soup = intersectionMesh(buildFrame(sys, s, none, false));
  f.triangles = soup.triangles.size();
  f.segments = soup.segments.size();
  f.intersections = mesh::countIntersections(soup);
  return f;
}

}  // namespace chute::scenes
