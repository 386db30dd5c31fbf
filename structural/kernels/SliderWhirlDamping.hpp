#pragma once
// RG8 (docs/formulation.md section 9): damping of the whirl of a line node about a slider next to
// it. An active sliding element's end node i with mass m_i, at distance l_i from the slider, has a
// transverse mode relative to the slider of frequency sqrt(N / (mu l_i)) (the part's lateral
// stiffness N / l_i on the pair's reduced mass mu). As the slider nears the node that frequency
// grows without bound and the mode's energy grows with it (its action is kept): the slider is
// thrown back by a centrifugal barrier that a continuous line does not have, and sits at line
// nodes (docs/applications/c9.md). Within a capture distance d_c = kWhirlDampingFraction L the
// relative velocity w = v_i - v_slider transverse to the part is damped:
//   f_i = c P w on node i, -f_i on the slider, P = I - e e^T, e = d l_i / d x_slider,
//   c = 2 phi(l_i) sqrt(mu N+ / max(l_i, l_f)),  phi = (1 - l_i / d_c)^2,  l_f =
//   kWhirlFloorFraction L
// (critical damping of the mode, faded in smoothly, bounded below l_f). Forces are equal and
// opposite (linear momentum is kept); their power c w^T P w is never negative. A pure function of
// the element's coordinates, velocities and parameters; node order (end 1, end 2, slider).
#include "kernels/LineElementTypes.hpp"
#include "kernels/UniformStrainPolyline.hpp"

namespace chute::kernels {

struct WhirlDampingParams {
  double endMass[2] = {0.0, 0.0};  // line mass at end nodes 1, 2 (0: no damping at that end)
  double sliderMass = 0.0;         // the element's line mass at the slider (F10: rho A0 L / 2)
  // > 0: an explicit step of this length; c is capped at mu / dt, the largest damping a
  // forward evaluation integrates stably (EX2v).
  double explicitStep = 0.0;
};

struct WhirlDamping {
  Vec9 force = Vec9::Zero();      // residual sign: + c P w on the end node
  Mat9 dPosition = Mat9::Zero();  // d force / d x (withTangent)
  Mat9 dVelocity = Mat9::Zero();  // d force / d v (withTangent)
  double power = 0.0;             // force . v >= 0: the rate of dissipation
  bool active = false;            // some end within its capture distance
};

// x: (end 1, end 2, slider) positions, v: their velocities, L: the element's reference length.
WhirlDamping sliderWhirlDamping(const Vec9& x, const Vec9& v, double L, const LineMaterial& mat,
                                const WhirlDampingParams& par, bool withTangent);

}  // namespace chute::kernels
