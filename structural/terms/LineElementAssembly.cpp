#include "terms/LineElementAssembly.hpp"

#include "kernels/CableDiscreteGradient.hpp"

namespace chute::line_assembly {

using kernels::Mat6;
using kernels::Vec6;

void assembleCable(const Model& m, int a, int b, double L, int material, const EvalPoint& p,
                   SystemAssembler& out) {
  const auto& mat = m.materials[material];
  if (p.inertiaOnly) {  // EX2's lumped mass of an inactive sliding element: M a only
    addCableInertia(m, a, b, L, mat, p, out);
    return;
  }
  if (explicitForcesOnly(m, p, out)) {
    addCableExplicitForce(m, a, b, L, mat, p, out);
    return;
  }
  const bool wantJ = out.wantMatrix();
  ++out.work().lineElastic;
  Vec6 r;
  Mat6 J;
  if (p.xStart) {
    // Energy-momentum step: the discrete gradient between x_n and x_{n+1} (EM5).
    const Eigen::VectorXd& x0 = *p.xStart;
    const Vec3 a0 = pos(x0, a), b0 = pos(x0, b);
    const auto dg = kernels::cableDiscreteGradient(
        a0, b0, 2.0 * pos(p.x, a) - a0, 2.0 * pos(p.x, b) - b0, L, mat, p.emDissipation, wantJ);
    r = dg.force;
    J = (2.0 * p.cx) * dg.dForce;
    if (wantJ && dg.stress == 0.0 && dg.strain1 <= 0.0) {
      // A slack cable over the whole step: the RG5 spring keeps the matrix regular.
      kernels::PolylineResult<2> slack;
      slack.strain = dg.strain1;
      addSlackTangent<2>(slack, mat, L, {0, 1}, p.cx, J, false);
    }
  } else {
    const auto res = kernels::cableForce(pos(p.x, a), pos(p.x, b), L, mat, wantJ);
    r = res.force;
    if (wantJ) {
      J = p.cx * res.stiffness;
      if (addSlackTangent<2>(res, mat, L, {0, 1}, p.cx, J, p.kinkTangent))
        ++out.work().kinkTangents;
    }
  }
  if (mat.density > 0.0) {
    ++out.work().lineMass;
    const bool gathered = p.inertia && !p.zeroAcceleration;
    const Vec6 acc = gathered ? gather2(p.a, a, b) : Vec6::Zero();
    // A residual-only evaluation at zero acceleration without mass damping (the explicit step,
    // EX2) has M a = 0: skipped.
    if (p.inertia && (wantJ || m.massDamping > 0.0 || (gathered && !acc.isZero(0.0)))) {
      const Mat6 M = kernels::cableMass(L, mat, m.massKind);
      r += M * acc;
      if (wantJ) J += p.ca * M;
      if (m.massDamping > 0.0) {  // C v with C = alpha M (solver.mass_damping)
        r += m.massDamping * M * gather2(p.v, a, b);
        if (wantJ) J += p.cv * m.massDamping * M;
      }
    }
    if (m.hasGravity()) r -= p.loadFactor * kernels::cableGravity(L, mat, m.gravity);
  }
  out.add<2>({a, b}, r, wantJ ? &J : nullptr);
}

double cableStrainEnergy(const Model& m, int a, int b, double L, int material,
                         const Eigen::VectorXd& x) {
  return kernels::cableStrainEnergyOnly(pos(x, a), pos(x, b), L, m.materials[material]);
}

void cableEnergy(const Model& m, int a, int b, double L, int material, const Eigen::VectorXd& x,
                 const Eigen::VectorXd& v, EnergyBreakdown& e) {
  const auto& mat = m.materials[material];
  e.strain += cableStrainEnergy(m, a, b, L, material, x);
  if (mat.density > 0.0) {
    const Vec6 vv = gather2(v, a, b);
    e.kinetic += 0.5 * vv.dot(kernels::cableMassTimes(L, mat, m.massKind, vv));
    e.gravity -= kernels::cableGravity(L, mat, m.gravity).dot(gather2(x, a, b));
  }
}

}  // namespace chute::line_assembly
