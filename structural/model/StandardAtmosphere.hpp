#pragma once
// The U.S. Standard Atmosphere 1976 (NOAA-S/T 76-1562) in its troposphere, 0-11 km geopotential
// altitude (docs/flight.md FL0): T = T0 + L H, p = p0 (T / T0)^(-g0 / (R L)), rho = p / (R T),
// H = r0 z / (r0 + z) the geopotential altitude of the geometric altitude z.

namespace chute {

struct AtmosphereState {
  double temperature = 0.0;  // K
  double pressure = 0.0;     // Pa
  double density = 0.0;      // kg/m^3
};

// z: geometric altitude in metres, within [-500, 11000]; throws std::out_of_range outside.
AtmosphereState standardAtmosphere(double altitude);

}  // namespace chute
