#include "kernels/SliderWhirlDamping.hpp"

#include <algorithm>
#include <cmath>

#include "kernels/SlidingCableKernel.hpp"

namespace chute::kernels {

WhirlDamping sliderWhirlDamping(const Vec9& x, const Vec9& v, double L, const LineMaterial& mat,
                                const WhirlDampingParams& par, bool withTangent) {
  WhirlDamping out;
  const Vec3 x1 = x.segment<3>(0), x2 = x.segment<3>(3), x3 = x.segment<3>(6);
  const double capture = kWhirlDampingFraction * L, floor = kWhirlFloorFraction * L;
  // Quick exit: neither end within the capture distance (most elements, most of the time).
  if (!((x3 - x1).squaredNorm() < capture * capture || (x3 - x2).squaredNorm() < capture * capture))
    return out;
  // N+ and its gradient over the element's dofs (F8): N = E A0 eps l / L, dN/dl = E A0 / L
  // (eps + l^2 / L^2).
  const auto el = slidingForce(x1, x2, x3, L, mat, false);
  const double N = el.axialForce;
  if (!(N > 0.0)) return out;  // slack: no lateral stiffness, no whirl
  const double dNdl = mat.E * mat.area / L * (el.strain + el.length * el.length / (L * L));
  const Vec9 dN = dNdl * el.dLength;
  // The part's direction as the element's own (RG1): exact outside the apex radius. (A wider
  // regularisation, 1e-5 L, was tried: inside it P tends to the identity and damps the sliding
  // itself; a heavy bead then dragged the node along and the run blew up at the crossing.)
  const double apex = kApexFraction * L;
  for (int i = 0; i < 2; ++i) {
    const double mi = par.endMass[i], ms = par.sliderMass;
    if (!(mi > 0.0) || !(ms > 0.0)) continue;
    const Vec3 xi = x.segment<3>(3 * i);
    const PartLength part = partLength(x3 - xi, apex);  // e = d l_i / d x3, H = d e / d x3
    const double l = part.length;
    if (!(l < capture)) continue;
    out.active = true;
    const double mu = mi * ms / (mi + ms);
    const double phi = (1.0 - l / capture) * (1.0 - l / capture);
    const double le = std::max(l, floor);
    double c = 2.0 * phi * std::sqrt(mu * N / le);
    bool capped = false;
    if (par.explicitStep > 0.0 && c > mu / par.explicitStep)
      c = mu / par.explicitStep, capped = true;
    const Vec3& e = part.gradient;
    const Mat3 P = Mat3::Identity() - e * e.transpose();
    const Vec3 w = v.segment<3>(3 * i) - v.segment<3>(6);
    const Vec3 Pw = P * w;
    const Vec3 f = c * Pw;
    out.force.segment<3>(3 * i) += f;
    out.force.segment<3>(6) -= f;
    out.power += c * w.dot(Pw);
    if (!withTangent) continue;
    // d/dv: f_i = c P (v_i - v_3).
    const Mat3 Cv = c * P;
    out.dVelocity.block<3, 3>(3 * i, 3 * i) += Cv;
    out.dVelocity.block<3, 3>(3 * i, 6) -= Cv;
    out.dVelocity.block<3, 3>(6, 3 * i) -= Cv;
    out.dVelocity.block<3, 3>(6, 6) += Cv;
    // d/dx, at fixed v: (P w) dc/dx + c d(P w)/dx, with d(P w)/dd = -(e.w) H - e (H w)^T for the
    // part vector d = x3 - x_i.
    const Mat3 dPw = -(e.dot(w)) * part.hessian - e * (part.hessian * w).transpose();
    Vec9 dc = Vec9::Zero();
    if (!capped) {
      // c = 2 phi sqrt(mu N) le^-1/2: through phi(l), le(l) and N(x).
      const double dphi = -2.0 * (1.0 - l / capture) / capture;
      double dcdl = 2.0 * std::sqrt(mu * N) * dphi / std::sqrt(le);
      if (l > floor) dcdl -= c / (2.0 * l);
      dc = (c / (2.0 * N)) * dN;
      dc.segment<3>(6) += dcdl * e;
      dc.segment<3>(3 * i) -= dcdl * e;
    }
    for (int rows : {3 * i, 6}) {
      const double sign = rows == 6 ? -1.0 : 1.0;
      out.dPosition.block<3, 9>(rows, 0) += sign * Pw * dc.transpose();
      out.dPosition.block<3, 3>(rows, 6) += sign * c * dPw;
      out.dPosition.block<3, 3>(rows, 3 * i) -= sign * c * dPw;
    }
  }
  return out;
}

}  // namespace chute::kernels
