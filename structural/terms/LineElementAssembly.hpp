#pragma once
// Shared by the line-element terms (CableTerm, SlidingGroupTerm): nodal gathers, the Jacobian-only
// slack spring (docs/formulation.md RG5) and one two-node cable's assembly and energy (an
// inactive element of a sliding group is a plain cable, docs/formulation.md section 3).
// Internal to terms/.
#include <array>

#include "assembly/SystemAssembler.hpp"
#include "assembly/Term.hpp"
#include "kernels/CableBatch.hpp"
#include "kernels/CableKernel.hpp"
#include "kernels/Regularisations.hpp"
#include "model/Model.hpp"

namespace chute::line_assembly {

inline Vec3 pos(const Eigen::VectorXd& x, int n) {
  return x.segment<3>(3 * n);
}

inline kernels::Vec6 gather2(const Eigen::VectorXd& v, int a, int b) {
  kernels::Vec6 r;
  r << v.segment<3>(3 * a), v.segment<3>(3 * b);
  return r;
}
// EX2's M a of a two-node cable alone (an inertia-only evaluation: the lumped mass M(x) 1 of an
// inactive sliding element, asked for at every explicit step). Inline: through assembleCable's
// call and cableMassTimes's it had cost 2-3 times its arithmetic.
inline void addCableInertia(const Model& m, int a, int b, double L,
                            const kernels::LineMaterial& mat, const EvalPoint& p,
                            SystemAssembler& out) {
  if (!(mat.density > 0.0)) return;
  ++out.work().lineMass;
  out.add<2>({a, b}, kernels::cableMassTimes(L, mat, m.massKind, gather2(p.a, a, b)), nullptr);
}

inline kernels::Vec9 gather3(const Eigen::VectorXd& v, int a, int b, int c) {
  kernels::Vec9 r;
  r << v.segment<3>(3 * a), v.segment<3>(3 * b), v.segment<3>(3 * c);
  return r;
}

// A slack tension-only part has no stiffness at all, so a massless node between slack parts
// would make the Newton matrix singular. The Jacobian (never the residual) gets a spring of
// kCableSlackTangent E A / L between the part's ends (RG5): converged states are untouched.
// A part on the kink, slack by less than the slack / taut band (RG4), also gets the taut axial
// stiffness E A0 / L D D^T when onKink (RG10: the first Newton iteration of a step, EvalPoint::
// kinkTangent; res.dLength is the kernel's, so not for the discrete-gradient results of the
// energy-momentum scheme): without it a straight line of parts at zero strain is pulled taut
// one part per Newton iteration. Returns whether RG10 applied (the
// Jacobian is then not the residual's exact derivative: Newton confirms its convergence with one
// iteration without it).
template <int N>
bool addSlackTangent(const kernels::PolylineResult<N>& res, const kernels::LineMaterial& mat,
                     double L, const std::array<int, N>& pathToLocal, double cx,
                     Eigen::Matrix<double, 3 * N, 3 * N>& J, bool onKink = true) {
  if (!mat.tensionOnly || mat.compressionStiffnessRatio > 0.0 || res.strain > 0.0) return false;
  const bool kink = onKink && res.strain > -kernels::kSlackTautBand;
  if (kink) J += cx * (mat.E * mat.area / L) * res.dLength * res.dLength.transpose();
  const Eigen::Matrix3d k =
      cx * kernels::kCableSlackTangent * mat.E * mat.area / L * Eigen::Matrix3d::Identity();
  for (int seg = 0; seg + 1 < N; ++seg) {
    const int a = pathToLocal[seg], b = pathToLocal[seg + 1];
    J.template block<3, 3>(3 * a, 3 * a) += k;
    J.template block<3, 3>(3 * b, 3 * b) += k;
    J.template block<3, 3>(3 * a, 3 * b) -= k;
    J.template block<3, 3>(3 * b, 3 * a) -= k;
  }
  return kink;
}

// Whether an evaluation is the explicit step's (EX2): residual only, M a = 0 (no acceleration
// or a = 0), no mass damping, no discrete gradient. Then a cable carries its internal force and
// its weight alone (addCableExplicitForce), what assembleCable gives then.
inline bool explicitForcesOnly(const Model& m, const EvalPoint& p, const SystemAssembler& out) {
  return !p.inertiaOnly && !out.wantMatrix() && !p.xStart && (!p.inertia || p.zeroAcceleration) &&
         m.massDamping == 0.0;
}

// assembleCable's explicit path (explicitForcesOnly), inlined into the terms' loops over their
// elements: called once per element across files it cost about 150 instructions an element
// (the general path's tests, the call, the scatter's set-up); the same operations, so the same
// bits. With gravity the general path had cost three times this one (a generated C-9 in free
// flight).
[[gnu::always_inline]] inline void addCableExplicitForce(const Model& m, int a, int b, double L,
                                                         const kernels::LineMaterial& mat,
                                                         const EvalPoint& p, SystemAssembler& out) {
  ++out.work().lineElastic;
  kernels::Vec6 r = kernels::cableForceOnly(pos(p.x, a), pos(p.x, b), L, mat);
  if (mat.density > 0.0) {
    ++out.work().lineMass;
    if (m.hasGravity()) r -= p.loadFactor * kernels::cableGravity(L, mat, m.gravity);
  }
  out.add<2>({a, b}, r, nullptr);
}

// CB1's lane of a cable of reference length L: addCableExplicitForce's weight per node, as
// cableGravity gives it (zero without density or gravity).
inline Vec3 cableLaneWeight(const Model& m, double L, const kernels::LineMaterial& mat) {
  return mat.density > 0.0 && m.hasGravity()
             ? Vec3(kernels::cableGravity(L, mat, m.gravity).head<3>())
             : Vec3::Zero();
}

// Lane `lane` of a CB1 batch (cableForcesAndDrag's f) scattered through the assembler; its drag
// also added to `drag` over all dofs (the energy balance's loads) unless nullptr.
inline void scatterCableLane(const kernels::CableLanes& lanes, const kernels::CableLaneVectors& f,
                             int lane, Eigen::VectorXd* drag, SystemAssembler& out) {
  kernels::Vec6 r;
  for (int k = 0; k < 3; ++k) r[k] = f.v[0][k][lane], r[3 + k] = f.v[1][k][lane];
  const int a = lanes.nodes[lane][0], b = lanes.nodes[lane][1];
  out.add<2>({a, b}, r, nullptr);
  if (drag)
    for (int k = 0; k < 3; ++k) {
      (*drag)[3 * a + k] += f.drag[k][lane];
      (*drag)[3 * b + k] += f.drag[k][lane];
    }
}

// Internal force, inertia and gravity of one two-node cable, scattered through the assembler.
void assembleCable(const Model& m, int a, int b, double L, int material, const EvalPoint& p,
                   SystemAssembler& out);

// Strain, kinetic and gravity energy of one two-node cable.
void cableEnergy(const Model& m, int a, int b, double L, int material, const Eigen::VectorXd& x,
                 const Eigen::VectorXd& v, EnergyBreakdown& e);
// Its strain energy alone (cableEnergy's first term, the same bits).
double cableStrainEnergy(const Model& m, int a, int b, double L, int material,
                         const Eigen::VectorXd& x);

}  // namespace chute::line_assembly
