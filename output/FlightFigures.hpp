#pragma once
// The figures a parachute is designed with, from a run's probe rows (docs/flight.md, "Figures"):
// peak opening force and its time, opening-force factor, filling time and distance, steady
// descent speed, drag area and coefficient, projected diameter ratio, largest swing.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "case/CaseSpec.hpp"

namespace chute {

// The series the figures are made from: a canopy probe's and a force probe's columns.
struct FlightSeries {
  std::vector<double> t, force, volume, projectedDiameter, dynamicPressure, airspeed, descent,
      swing;
  bool held = false;  // the force is a support's (the payload held in a wind), else a line pull
};

// The series collected row by row while a run streams its rows to probes.csv (a run keeps no
// rows of its own: RunOptions::keepRows). Only the seven columns the figures need are kept, not
// whole rows: memory grows with the rows (at most output.max_rows) but not with the number of
// probes, and the figures are the ones whole rows give, number for number.
class FlightSeriesCollector {
 public:
  // For the first `canopy` probe with the first `support_force` or `line_pull` probe of a case
  // whose rows have the columns `columns`; nullopt when it has no such pair.
  static std::optional<FlightSeriesCollector> forCase(const std::vector<ProbeSpec>& probes,
                                                      const std::vector<std::string>& columns);
  void add(double t, const std::vector<double>& row);
  // Back to the first `rows` rows (a run's output cut back to its last good row).
  void cutBackTo(size_t rows);
  const FlightSeries& series() const { return s_; }

 private:
  FlightSeries s_;
  std::vector<std::pair<std::vector<double> FlightSeries::*, size_t>> columns_;
};

// The same from the rows of a run held whole (rows[i] has the columns of `columns`); nullopt
// when the case has no such pair or there are no rows.
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
