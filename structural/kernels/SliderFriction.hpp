#pragma once
// Active sliding element with capstan friction at its slider (docs/friction.md, FR1-FR12).
//
// With friction the two straight parts of the active element (docs/formulation.md section 2) carry
// different tensions: part 1 (end 1 -> slider) has reference length s, part 2 (slider -> end 2)
// L - s, each its own Green strain eps_i = (l_i^2 - L_i^2) / (2 L_i^2) and force
// N_i = E A0 eps_i l_i / L_i (FR1-FR2). The split s is history: a return mapping from the split
// at the start of the step s_n (stick predictor) checks the capstan limit
// N_high <= exp(mu_s beta) N_low (FR5) and otherwise solves the slip condition
// N_high = exp(mu(slip rate) beta) N_low for s by a safeguarded local Newton (FR6-FR8). The
// tangent is the algorithmic one: implicit differentiation of the slip condition (FR9-FR10).
// beta is the wrap angle of the cable at the slider, regularised where the parts are parallel
// or straight (FR4). Pure function; dof order node 1, node 2, slider (as slidingForce).
#include <Eigen/Core>
#include <limits>

#include "kernels/LineElementTypes.hpp"
#include "kernels/Regularisations.hpp"
#include "kernels/UniformStrainPolyline.hpp"

namespace chute::kernels {

// Coulomb-capstan law of one slider point. mu(v) = mu_d + (mu_s - mu_d) exp(-|v| / v_s) on the
// slip rate v = ds/dt (FR7); v_s = 0: mu_d whenever slipping. A lock freezes s from lockAt on;
// oneWay = +1 / -1 lets s (the slider's material coordinate) only grow / only shrink.
struct SliderFrictionLaw {
  double muStatic = 0.0;
  double muDynamic = 0.0;
  double slipRateScale = 0.0;
  double lockAt = std::numeric_limits<double>::infinity();
  int oneWay = 0;
  // Whether the slider needs the friction element at all (else: the frictionless F6-F9 one).
  bool frictional() const {
    return muStatic > 0.0 || muDynamic > 0.0 || oneWay != 0 ||
           lockAt < std::numeric_limits<double>::infinity();
  }
  double mu(double slipRate) const;        // FR7
  double dMuDRate(double slipRate) const;  // d mu / d|v|
};

// The wrap angle is regularised within kWrapApexAngle of parallel or aligned parts (FR4, RG7,
// kernels/Regularisations.hpp).

enum class SliderStick : int { Stick = 0, SlipPlus = 1, SlipMinus = -1 };

struct FrictionSlidingResult {
  double s = 0.0;             // reference length of part 1 (the split)
  double l1 = 0.0, l2 = 0.0;  // current part lengths (regularised at the apex)
  double strain1 = 0.0, strain2 = 0.0;
  double N1 = 0.0, N2 = 0.0;  // part forces (FR2)
  double wrapAngle = 0.0;     // beta (FR3-FR4)
  double energy = 0.0;        // W1 + W2 at the split s
  SliderStick state = SliderStick::Stick;
  int localIterations = 0;
  Vec9 force;      // f = N1 D1 + N2 D2 (FR2)
  Mat9 stiffness;  // algorithmic tangent (FR9-FR10)
};

// x1, x2: element end nodes, x3: slider. L: element reference length. sStart: split at the start
// of the step. dt: step length (<= 0: static, slip rate taken as 0). locked: t >= lockAt.
// startSlip: the direction the slider slipped in over the last step, passed only while the
// positions are those it converged at (the first Newton iteration of a step): the stick predictor
// then sits on the slip limit, and a stick verdict returns the stick force (s = sStart) with the
// slip tangent of that direction at s = sStart (FR15), so that the first update continues the slip.
FrictionSlidingResult frictionSlidingForce(const Vec3& x1, const Vec3& x2, const Vec3& x3, double L,
                                           double sStart, const LineMaterial& mat,
                                           const SliderFrictionLaw& law, double dt, bool locked,
                                           bool withTangent,
                                           SliderStick startSlip = SliderStick::Stick);

// A slider with friction arrives at a node of its element within kFrictionArrivalFraction L of it
// (FR16, RG7, kernels/Regularisations.hpp).

// Round-off floor of positions resolved through the friction element (FR16): a part of reference
// length L_i computes its strain from positions that carry round-off eps |x|, so its force is
// uncertain by E A eps |x| / L_i; in slip that force moves the nodes along the soft direction
// (stiffness ~ E A / L), which is eps |x| L / min(L_1, L_2) of displacement. Returns that with a
// safety factor kRoundoffFloorFactor.
inline constexpr double kRoundoffFloorFactor = 8.0;
double frictionRoundoffFloor(const Vec3& x1, const Vec3& x2, const Vec3& x3, double L, double s);

// Wrap angle beta of the cable at the slider and its gradient (element dof order), FR3-FR4.
struct WrapAngle {
  double beta;
  Vec9 gradient;
};
WrapAngle wrapAngle(const Vec3& x1, const Vec3& x2, const Vec3& x3, double L);

}  // namespace chute::kernels
