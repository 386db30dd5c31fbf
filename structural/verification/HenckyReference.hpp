#pragma once
// Hencky's pressurised circular membrane (Foeppl-Hencky membrane theory): a flat disk of radius a,
// thickness t, clamped at its rim, under uniform pressure p. With N* = (E t p^2 a^2)^(1/3) and
// n(rho) = N_r / N*, rho = r / a, equilibrium and compatibility give
//   rho n'' + 3 n' + rho / (8 n^2) = 0,   n'(0) = 0,   (1 - nu) n(1) + n'(1) = 0 (u(a) = 0),
// solved here by shooting on n(0) (RK4 from a series start near rho = 0, secant on n(0)).
// Centre deflection w0 = a (p a / (E t))^(1/3) (1/2) int_0^1 rho / n drho; centre stress
// sigma0 = n(0) N* / t. Published constants differ in the third digit (an old series error), so
// the reference is computed, not quoted.
namespace chute::verification {

struct HenckySolution {
  double n0 = 0.0;                     // N_r(0) / N*
  double deflectionCoefficient = 0.0;  // w0 / (a (p a / E t)^(1/3))
  double stressCoefficient = 0.0;      // sigma0 / (E p^2 a^2 / t^2)^(1/3)
};

HenckySolution solveHencky(double nu, int steps = 20000);

struct HenckyReference {
  double E, nu, t, p, a;
  double centreDeflection() const;
  double centreStress() const;
};

}  // namespace chute::verification
