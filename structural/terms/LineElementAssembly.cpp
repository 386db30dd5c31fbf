#include "terms/LineElementAssembly.hpp"

namespace chute::line_assembly {

using kernels::Mat6;
using kernels::Vec6;

void assembleCable(const Model& m, int a, int b, double L, int material, const EvalPoint& p,
                   SystemAssembler& out) {
  const auto& mat = m.materials[material];
  const bool wantJ = out.wantMatrix();
  const auto res = kernels::cableForce(pos(p.x, a), pos(p.x, b), L, mat, wantJ);
  ++out.work().lineElastic;
  Vec6 r = res.force;
  Mat6 J = p.cx * res.stiffness;
  if (wantJ) addSlackTangent<2>(res, mat, L, {0, 1}, p.cx, J);
  if (mat.density > 0.0) {
    ++out.work().lineMass;
    if (p.inertia) {
      const Mat6 M = kernels::cableMass(L, mat, m.massKind);
      r += M * gather2(p.a, a, b);
      J += p.ca * M;
      if (m.massDamping > 0.0) {  // C v with C = alpha M (solver.mass_damping)
        r += m.massDamping * M * gather2(p.v, a, b);
        J += p.cv * m.massDamping * M;
      }
    }
    if (m.hasGravity()) r -= p.loadFactor * kernels::cableGravity(L, mat, m.gravity);
  }
  out.add<2>({a, b}, r, wantJ ? &J : nullptr);
}

void cableEnergy(const Model& m, int a, int b, double L, int material, const Eigen::VectorXd& x,
                 const Eigen::VectorXd& v, EnergyBreakdown& e) {
  const auto& mat = m.materials[material];
  e.strain += kernels::cableForce(pos(x, a), pos(x, b), L, mat, false).energy;
  if (mat.density > 0.0) {
    const Vec6 vv = gather2(v, a, b);
    e.kinetic += 0.5 * vv.dot(kernels::cableMass(L, mat, m.massKind) * vv);
    e.gravity -= kernels::cableGravity(L, mat, m.gravity).dot(gather2(x, a, b));
  }
}

}  // namespace chute::line_assembly
