#pragma once
// The figures a parachute is designed with, from a run's probe rows (docs/flight.md, "Figures"):
// peak opening force and its time, opening-force factor, filling time and distance, steady
// descent speed, drag area and coefficient, projected diameter ratio, largest swing.
#include <optional>
#include <string>
#include <vector>

#include "case/CaseSpec.hpp"

namespace chute {

// The series the figures are made from: a canopy probe's and a force probe's columns.
struct FlightSeries {
  std::vector<double> t, force, volume, projectedDiameter, dynamicPressure, airspeed, descent,
      swing;
  bool held = false;  // the force is a support's (the payload held in a wind), else a line pull
};

// The first `canopy` probe with the first `support_force` or `line_pull` probe, from the rows of
// a run (rows[i] has the columns of `columns`); nullopt when the case has no such pair.
std::optional<FlightSeries> flightSeries(const std::vector<ProbeSpec>& probes,
                                         const std::vector<std::string>& columns,
                                         const std::vector<double>& times,
                                         const std::vector<std::vector<double>>& rows);

struct FlightFigures {
  double peakForce = 0.0, peakForceTime = 0.0;
  // The steady state: means over the last fifth of the run, and how much the force varied there
  // (its standard deviation over its mean).
  double steadyFrom = 0.0, steadyForce = 0.0, steadyVariation = 0.0;
  double steadyDescentSpeed = 0.0, steadyAirspeed = 0.0;
  double dragArea = 0.0, dragCoefficient = 0.0;  // C_D S = F / q; C_D0 = C_D S / S0
  double projectedDiameterRatio = 0.0;           // D_p / D_0
  // Held: peak over steady force (C_k). Free: peak over C_D S q at line stretch (C_x X_1).
  double openingForceFactor = 0.0;
  // To 95 % of the steady captured volume; -1: never filled.
  double fillingTime = -1.0, fillingDistance = -1.0;
  double largestSwing = 0.0;  // degrees, after filling
  bool held = false;
};

// nominalDiameter D0 and nominalArea S0: the canopy's (its flat pattern's). systemWeight: the
// whole model's weight, the drag of a free system in steady descent.
FlightFigures flightFigures(const FlightSeries& s, double nominalDiameter, double nominalArea,
                            double systemWeight);

}  // namespace chute
