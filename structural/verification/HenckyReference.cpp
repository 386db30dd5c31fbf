#include "verification/HenckyReference.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

namespace chute::verification {

namespace {
// State (n, n', int rho/n) integrated from rho0 to 1; returns the state at 1.
std::array<double, 3> integrate(double n0, int steps) {
  const double rho0 = 1e-4;
  const double c = -1.0 / (64.0 * n0 * n0);  // series n = n0 + c rho^2 + ...
  std::array<double, 3> y = {n0 + c * rho0 * rho0, 2.0 * c * rho0, rho0 * rho0 / (2.0 * n0)};
  auto f = [](double rho, const std::array<double, 3>& s) {
    return std::array<double, 3>{s[1], (-3.0 * s[1] - rho / (8.0 * s[0] * s[0])) / rho, rho / s[0]};
  };
  const double h = (1.0 - rho0) / steps;
  double rho = rho0;
  for (int k = 0; k < steps; ++k) {
    auto add = [](const std::array<double, 3>& a, const std::array<double, 3>& b, double s) {
      return std::array<double, 3>{a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]};
    };
    const auto k1 = f(rho, y), k2 = f(rho + h / 2, add(y, k1, h / 2)),
               k3 = f(rho + h / 2, add(y, k2, h / 2)), k4 = f(rho + h, add(y, k3, h));
    for (int i = 0; i < 3; ++i) y[i] += h / 6.0 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    rho += h;
  }
  return y;
}
}  // namespace

HenckySolution solveHencky(double nu, int steps) {
  auto residual = [&](double n0) {
    const auto y = integrate(n0, steps);
    return (1.0 - nu) * y[0] + y[1];
  };
  // Secant iteration from two guesses around the known magnitude (n0 ~ 0.4).
  double a = 0.3, b = 0.5, fa = residual(a), fb = residual(b);
  for (int it = 0; it < 60 && std::abs(b - a) > 1e-15; ++it) {
    const double c = b - fb * (b - a) / (fb - fa);
    a = b, fa = fb, b = c, fb = residual(b);
  }
  if (!std::isfinite(b) || std::abs(fb) > 1e-10) throw std::runtime_error("Hencky shooting failed");
  HenckySolution s;
  s.n0 = b;
  s.deflectionCoefficient = 0.5 * integrate(b, steps)[2];
  s.stressCoefficient = b;
  return s;
}

double HenckyReference::centreDeflection() const {
  return a * std::cbrt(p * a / (E * t)) * solveHencky(nu).deflectionCoefficient;
}

double HenckyReference::centreStress() const {
  return std::cbrt(E * p * p * a * a / (t * t)) * solveHencky(nu).stressCoefficient;
}

}  // namespace chute::verification
