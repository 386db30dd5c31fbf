#include "coupling/QuasiSteadyFlow.hpp"

#include <cmath>

#include "kernels/CanopyFlow.hpp"
#include "kernels/PressureKernel.hpp"

namespace chute::coupling {

double QuasiSteadyFlowLaw::pressure(const Vec3& A, const Vec3& vf, const Vec3& af, double t) const {
  const double area = A.norm();
  if (area == 0.0) return stagnation(t);
  const Vec3 n = A / area;
  const double vn = (vf - wind).dot(n), an = af.dot(n);
  // The fabric's normal motion as in the canopy's airflow loads (formulation.md FL8).
  return stagnation(t) -
         kernels::normalMotionPressure(0.5 * airDensity * normalDragCoefficient, vn) -
         airDensity * addedMassLength * an;
}

Eigen::VectorXd QuasiSteadyFlow::facePressures(const InterfaceData& d) const {
  const Eigen::VectorXd vf = surface_->faceMeans(d.velocities);
  const Eigen::VectorXd af = surface_->faceMeans(d.accelerations);
  Eigen::VectorXd p(surface_->numFaces());
  for (int f = 0; f < surface_->numFaces(); ++f)
    p[f] = law_.pressure(d.faceAreaVectors.segment<3>(3 * f), vf.segment<3>(3 * f),
                         af.segment<3>(3 * f), d.t);
  return p;
}

void QuasiSteadyPressureTerm::addCouplings(std::vector<std::vector<int>>& cliques) const {
  for (int f = 0; f < surface_->numFaces(); ++f) {
    std::vector<int> c;
    for (int i = 0; i < surface_->faceSize[f]; ++i)
      c.push_back(surface_->node[surface_->faceVertices[f][i]]);
    cliques.push_back(std::move(c));
  }
}

template <int N>
void QuasiSteadyPressureTerm::assembleFace(int f, const EvalPoint& p, SystemAssembler& out) const {
  const auto& s = *surface_;
  const bool wantJ = out.wantMatrix();
  std::array<int, N> ids;
  std::array<Vec3, N> x;
  Vec3 vf = Vec3::Zero(), af = Vec3::Zero();
  for (int i = 0; i < N; ++i) {
    ids[i] = s.node[s.faceVertices[f][i]];
    x[i] = p.x.segment<3>(3 * ids[i]);
    vf += p.v.segment<3>(3 * ids[i]);
    af += p.a.segment<3>(3 * ids[i]);
  }
  vf /= N, af /= N;
  const Vec3 A = kernels::areaVector<N>(x);
  const double pr = p.loadFactor * law_.pressure(A, vf, af, p.t);
  // The follower load of a unit pressure, g, and its derivative: r = -p g (same kernel as the
  // coupled face pressure).
  const auto g = kernels::pressureLoad<N>(x, 1.0, wantJ);
  const Eigen::Matrix<double, 3 * N, 1> r = -pr * g.force;
  if (!wantJ) {
    out.add<N>(ids, r, nullptr);
    return;
  }
  // dp/dx through the normal, dp/dv and dp/da through v_n and a_n (both / N per vertex).
  const double area = A.norm();
  const Vec3 n = A / area;
  const double vn = (vf - law_.wind).dot(n);
  const double dpdvn = -p.loadFactor * kernels::dNormalMotionPressure(
                                           0.5 * law_.airDensity * law_.normalDragCoefficient, vn);
  const double dpdan = -p.loadFactor * law_.airDensity * law_.addedMassLength;
  const Eigen::Matrix3d dndA = (Eigen::Matrix3d::Identity() - n * n.transpose()) / area;
  const Eigen::Matrix<double, 1, 3 * N> dpdx = (dpdvn * (vf - law_.wind) + dpdan * af).transpose() *
                                               dndA * kernels::areaVectorJacobian<N>(x);
  Eigen::Matrix<double, 1, 3 * N> dpdv, dpda;
  for (int i = 0; i < N; ++i) {
    dpdv.template segment<3>(3 * i) = (dpdvn / N) * n.transpose();
    dpda.template segment<3>(3 * i) = (dpdan / N) * n.transpose();
  }
  const Eigen::Matrix<double, 3 * N, 3 * N> J =
      -p.cx * (pr * g.dForce + g.force * dpdx) - p.cv * g.force * dpdv - p.ca * g.force * dpda;
  out.add<N>(ids, r, &J);
}

void QuasiSteadyPressureTerm::assemble(const EvalPoint& p, SystemAssembler& out) {
  if (!p.inertia) return;  // a flow law of motion: dynamics only
  for (int f = 0; f < surface_->numFaces(); ++f) {
    if (surface_->faceSize[f] == 3)
      assembleFace<3>(f, p, out);
    else
      assembleFace<4>(f, p, out);
  }
}

}  // namespace chute::coupling
