#include "model/StandardAtmosphere.hpp"

#include <cmath>
#include <stdexcept>

namespace chute {

namespace {
// NOAA-S/T 76-1562, table I and eq. 18, 23, 42: sea-level temperature and pressure, standard
// gravity, the gas constant of air (R* / M0 = 8314.32 / 28.9644), the troposphere's lapse rate
// and the effective Earth radius of the geopotential altitude.
constexpr double kT0 = 288.15, kP0 = 101325.0, kG0 = 9.80665;
constexpr double kR = 8314.32 / 28.9644;
constexpr double kLapse = -0.0065;
constexpr double kEarthRadius = 6356766.0;
}  // namespace

AtmosphereState standardAtmosphere(double z) {
  if (!(z >= -500.0 && z <= 11000.0))
    throw std::out_of_range("the standard atmosphere here covers -500 m to 11 km");
  const double H = kEarthRadius * z / (kEarthRadius + z);
  AtmosphereState a;
  a.temperature = kT0 + kLapse * H;
  a.pressure = kP0 * std::pow(a.temperature / kT0, -kG0 / (kR * kLapse));
  a.density = a.pressure / (kR * a.temperature);
  return a;
}

}  // namespace chute
