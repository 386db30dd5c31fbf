#pragma once
// Loads on a canopy from the airflow relative to it, without a flow solver (docs/flight.md,
// FL1-FL12): the captured air inside at one pressure, the outside at the pressure of the flow
// around the canopy (the wake's base pressure on faces turned away from the flow, impact on faces
// turned into it), the fabric's own motion normal to itself, and the air passing through the
// cloth, the mouth and the vent. These are the pure functions of one face or one opening; the
// term (terms/CanopyFlowTerm) adds them up over the canopy.
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>

#include "kernels/PressureKernel.hpp"

namespace chute::kernels {

// FL6: air through the cloth, Delta p = viscous u + inertial u^2 (Darcy-Forchheimer, the form of
// Ergun's law used for parachute cloth), u the normal velocity through it, positive outward. Made
// from the cloth's air permeability: the velocity uRef at the test pressure difference dpRef
// (e.g. ft^3/ft^2/min at 0.5 in of water), with the inertial part given or zero.
struct ClothPermeability {
  double viscous = 0.0;     // Delta p per unit velocity (0 with inertial 0: impermeable)
  double inertial = 0.0;    // Delta p per unit velocity squared
  double perViscous = 0.0;  // 1 / viscous: the linear law by a multiplication (every face, every
                            // step: the division's latency was a fifth of the airflow's loads pass)
  // viscous from the test point once the inertial part is taken out: dpRef = a uRef + b uRef^2.
  static ClothPermeability fromTest(double uRef, double dpRef, double inertial);
  bool permeable() const { return viscous > 0.0 || inertial > 0.0; }
  // u for a pressure difference dp (inside minus outside), and du/d(dp). Inline: called for
  // every canopy face on every step.
  double velocity(double dp) const {
    if (inertial == 0.0) return dp * perViscous;
    // b u^2 + a u = |dp| for u >= 0, odd in dp.
    const double u = 2.0 * std::abs(dp) /
                     (viscous + std::sqrt(viscous * viscous + 4.0 * inertial * std::abs(dp)));
    return dp < 0.0 ? -u : u;
  }
  double dVelocity(double dp) const {
    if (inertial == 0.0) return perViscous;
    return 1.0 / std::sqrt(viscous * viscous + 4.0 * inertial * std::abs(dp));
  }
};

// FL4: volume flow through an opening of area `area` under a pressure difference dp (upstream
// minus downstream), Q = Cd area sgn(dp) sqrt(2 |dp| / rho): Bernoulli with a discharge
// coefficient. Below dpLinear the square root is replaced by the line through (0, 0) and
// (dpLinear, Q(dpLinear)) (a finite derivative at zero flow, for the captured air's implicit
// update; the flow there is a fraction sqrt(dpLinear / dp) of the rest).
double orificeFlow(double dp, double area, double cd, double rho, double dpLinear);
double dOrificeFlow(double dp, double area, double cd, double rho, double dpLinear);

// FL7: the outside pressure coefficient (on the dynamic pressure of the relative flow) of a face
// whose outward normal n makes c = n . U_hat with the direction U_hat the air moves relative to
// the canopy. The outside of a bluff canopy lies in its separated wake, at the wake's base
// pressure Cb < 0, uniform, whichever way its faces turn; faces within kAttachedFlowBand of lying
// along the flow are not (the sides of a slender folded canopy, past which the flow stays
// attached): the base pressure fades to none there, Cb min(1, |c| / band). A face turned into
// the flow (c < 0) also takes impact, rising to stagnation (1) head on: + (1 - Cb) c^2 (modified
// Newtonian). Continuous; its slope jumps at c = 0 and at the band's edges.
// Without branches (min, not a test: every face at every step, the faces' attitudes in no order
// a predictor follows): the impact term (1 - Cb) min(c, 0)^2.
inline constexpr double kAttachedFlowBand = 0.2;  // sin 11.5 deg
inline double outsidePressureCoefficient(double c, double cb) {
  const double into = std::min(c, 0.0);
  return cb * std::min(1.0, std::abs(c) * (1.0 / kAttachedFlowBand)) + (1.0 - cb) * into * into;
}
inline double dOutsidePressureCoefficient(double c, double cb) {
  const double dBase =
      std::abs(c) < kAttachedFlowBand ? (c >= 0.0 ? cb : -cb) * (1.0 / kAttachedFlowBand) : 0.0;
  return dBase + 2.0 * (1.0 - cb) * std::min(c, 0.0);
}

// FL8's resistance of the air to a face's own normal motion, as a pressure against it:
// (1/2) rho Cn |u_n| u_n (halfRhoCn = (1/2) rho Cn), and its derivative in u_n. The coupling
// demo's flow law (coupling/QuasiSteadyFlow) uses the same.
inline double normalMotionPressure(double halfRhoCn, double un) {
  return halfRhoCn * std::abs(un) * un;
}
inline double dNormalMotionPressure(double halfRhoCn, double un) {
  return 2.0 * halfRhoCn * std::abs(un);
}

// What the face loads share over the whole canopy at an evaluation (FL1-FL3).
struct CanopyFlowState {
  Eigen::Vector3d canopyVelocity = Eigen::Vector3d::Zero();  // v_c: area-weighted mean
  Eigen::Vector3d flowDirection = Eigen::Vector3d::Zero();   // U_hat (zero: no relative flow)
  double dynamicPressure = 0.0;                              // q = rho |U|^2 / 2
  double insideGauge = 0.0;      // p_in - p_a, the captured air's pressure over the ambient
  double baseCoefficient = 0.0;  // Cb
  double normalDrag = 0.0;       // (1/2) rho Cn of the fabric's own normal motion (FL8)
};

// FL7-FL8 for one face from its outward unit normal n and its mean velocity vf: the static
// difference p_in - p_a - q Cout(n . U_hat), and the net pressure that also takes the fabric's
// normal motion relative to the canopy. canopyFaceLoad and the term's residual-only path share it.
struct FacePressure {
  double staticDifference = 0.0, netPressure = 0.0;
  double c = 0.0, un = 0.0;  // n . U_hat, (vf - v_c) . n
};
inline FacePressure facePressure(const Eigen::Vector3d& n, const Eigen::Vector3d& vf,
                                 const CanopyFlowState& s) {
  FacePressure f;
  f.c = n.dot(s.flowDirection);
  f.un = (vf - s.canopyVelocity).dot(n);
  f.staticDifference =
      s.insideGauge - s.dynamicPressure * outsidePressureCoefficient(f.c, s.baseCoefficient);
  f.netPressure = f.staticDifference - normalMotionPressure(s.normalDrag, f.un);
  return f;
}

// FL8: the net outward pressure on a face and what the cloth lets through. With n = A / |A| the
// face's outward unit normal and u_n = (v_f - v_c) . n its normal velocity relative to the canopy
// (v_f the mean of its nodes' velocities):
//   staticDifference = p_in - p_a - q Cout(n . U_hat)                 (drives the cloth flow)
//   netPressure      = staticDifference - (1/2) rho Cn |u_n| u_n      (pushes the face along n)
// The face's nodes share the follower force netPressure A equally (one-point rule, as the
// case-file pressure): residual r_i = -netPressure A / N, with its derivatives with respect to
// the face's positions and velocities (the canopy-wide state held fixed).
template <int NumNodes>
struct CanopyFaceLoad {
  static constexpr int kDofs = 3 * NumNodes;
  Eigen::Matrix<double, kDofs, 1> residual;
  Eigen::Matrix<double, kDofs, kDofs> dPosition;  // set only withTangent
  Eigen::Matrix<double, kDofs, kDofs> dVelocity;  // set only withTangent
  double area = 0.0;                              // |A|
  double staticDifference = 0.0;
  double netPressure = 0.0;
};
template <int NumNodes>
CanopyFaceLoad<NumNodes> canopyFaceLoad(const std::array<Eigen::Vector3d, NumNodes>& x,
                                        const std::array<Eigen::Vector3d, NumNodes>& v,
                                        const CanopyFlowState& s, bool withTangent);

// FL3: the captured air's absolute pressure, isentropic from the ambient state: a mass M in a
// volume V is at p_a (M / (rho_a V))^gamma.
inline double capturedAirPressure(double mass, double volume, double ambientPressure,
                                  double ambientDensity, double gamma) {
  return ambientPressure * std::pow(mass / (ambientDensity * volume), gamma);
}

// FL2: the volume enclosed by a triangle (a, b, c) and the origin, signed by the triangle's
// orientation: a . (b x c) / 6. Summed over a closed, outward-oriented surface: its volume.
inline double tetraVolume(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                          const Eigen::Vector3d& c) {
  return a.dot(b.cross(c)) / 6.0;
}

}  // namespace chute::kernels
