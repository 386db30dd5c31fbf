#pragma once
// The wet surface of a coupled run: the membrane faces a flow solver sees and their vertices.
// Pure topology and geometry over the model; data on it is laid out the way preCICE exchanges it:
// one value (pressure, area) or three (x, y, z: coordinates, displacements, normals) per vertex
// or face, vertex-major.
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "model/Model.hpp"

namespace chute::coupling {

struct WetSurface {
  std::vector<int> node;                         // model node id of each vertex (ascending)
  std::vector<int> element;                      // model membrane element of each face
  std::vector<std::array<int, 4>> faceVertices;  // vertex indices; -1 pads a triangle
  std::vector<int> faceSize;                     // 3 (triangle) or 4 (quadrilateral)
  std::vector<int> sets;                         // the membrane sets it covers

  // The faces of the named membrane sets (empty: every membrane). Throws std::invalid_argument
  // for an unknown set or a model without membranes.
  static WetSurface fromModel(const Model& m, const std::vector<std::string>& setNames = {});

  int numVertices() const { return static_cast<int>(node.size()); }
  int numFaces() const { return static_cast<int>(element.size()); }

  // Vertex values (3 per vertex) gathered from a full dof vector (3 per model node).
  Eigen::VectorXd gather(const Eigen::VectorXd& full) const;
  // Area vector |A| n of every face (3 per face) at nodal positions x (full dof vector):
  // kernels::areaVector, the direction pressure pushes.
  Eigen::VectorXd faceAreaVectors(const Eigen::VectorXd& x) const;
  // Face means of vertex values (3 per vertex in, 3 per face out): the face velocity the flow
  // model sees, (1/N) sum_i v_i.
  Eigen::VectorXd faceMeans(const Eigen::VectorXd& vertexValues) const;
};

}  // namespace chute::coupling
