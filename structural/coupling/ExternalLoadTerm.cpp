#include "coupling/ExternalLoadTerm.hpp"

#include <stdexcept>
#include <string>

#include "kernels/PressureKernel.hpp"

namespace chute::coupling {

namespace {
void checkSize(const Eigen::VectorXd& v, long expected, const char* what) {
  if (v.size() != expected)
    throw std::invalid_argument(std::string(what) + ": expected " + std::to_string(expected) +
                                " values, got " + std::to_string(v.size()));
  if (!v.allFinite()) throw std::invalid_argument(std::string(what) + ": non-finite value");
}
}  // namespace

ExternalLoadTerm::ExternalLoadTerm(const WetSurface& surface)
    : surface_(&surface),
      facePressure_(Eigen::VectorXd::Zero(surface.numFaces())),
      vertexPressure_(Eigen::VectorXd::Zero(surface.numVertices())),
      vertexForce_(Eigen::VectorXd::Zero(3 * surface.numVertices())) {}

void ExternalLoadTerm::addCouplings(std::vector<std::vector<int>>& cliques) const {
  for (int f = 0; f < surface_->numFaces(); ++f) {
    std::vector<int> c;
    for (int i = 0; i < surface_->faceSize[f]; ++i)
      c.push_back(surface_->node[surface_->faceVertices[f][i]]);
    cliques.push_back(std::move(c));
  }
}

void ExternalLoadTerm::setFacePressures(const Eigen::VectorXd& p) {
  checkSize(p, surface_->numFaces(), "face pressures");
  facePressure_ = p;
}
void ExternalLoadTerm::setVertexPressures(const Eigen::VectorXd& p) {
  checkSize(p, surface_->numVertices(), "vertex pressures");
  vertexPressure_ = p;
  anyVertexPressure_ = p.cwiseAbs().maxCoeff() > 0.0;
}
void ExternalLoadTerm::setVertexForces(const Eigen::VectorXd& f) {
  checkSize(f, 3 * surface_->numVertices(), "vertex forces");
  vertexForce_ = f;
  anyVertexForce_ = f.cwiseAbs().maxCoeff() > 0.0;
}

void ExternalLoadTerm::assemble(const EvalPoint& p, SystemAssembler& out) {
  const bool wantJ = out.wantMatrix();
  const auto& s = *surface_;
  for (int f = 0; f < s.numFaces(); ++f) {
    const double pf = p.loadFactor * facePressure_[f];
    if (pf == 0.0 && !anyVertexPressure_) continue;
    auto one = [&](auto nodesTag) {
      constexpr int N = decltype(nodesTag)::value;
      std::array<int, N> ids;
      std::array<Vec3, N> x;
      Eigen::Matrix<double, N, 1> pv;
      for (int i = 0; i < N; ++i) {
        ids[i] = s.node[s.faceVertices[f][i]];
        x[i] = p.x.segment<3>(3 * ids[i]);
        pv[i] = pf + p.loadFactor * vertexPressure_[s.faceVertices[f][i]];
      }
      // Face pressure alone goes through the case-file pressure kernel (identical results).
      const auto pl = anyVertexPressure_ ? kernels::pressureLoadNodal<N>(x, pv, wantJ)
                                         : kernels::pressureLoad<N>(x, pf, wantJ);
      const Eigen::Matrix<double, 3 * N, 1> r = -pl.force;
      if (!wantJ) {
        out.add<N>(ids, r, nullptr);
        return;
      }
      const Eigen::Matrix<double, 3 * N, 3 * N> J = -p.cx * pl.dForce;
      out.add<N>(ids, r, &J);
    };
    if (s.faceSize[f] == 3)
      one(std::integral_constant<int, 3>{});
    else
      one(std::integral_constant<int, 4>{});
  }
  if (!anyVertexForce_) return;
  for (int v = 0; v < s.numVertices(); ++v) {  // dead load: no stiffness
    const Eigen::Matrix<double, 3, 1> r = -p.loadFactor * vertexForce_.segment<3>(3 * v);
    out.add<1>({s.node[v]}, r, nullptr);
  }
}

}  // namespace chute::coupling
