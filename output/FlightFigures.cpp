#include "FlightFigures.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace chute {

std::optional<FlightSeriesCollector> FlightSeriesCollector::forCase(
    const std::vector<ProbeSpec>& probes, const std::vector<std::string>& columns) {
  const ProbeSpec* canopy = nullptr;
  const ProbeSpec* force = nullptr;
  for (const auto& p : probes) {
    if (!canopy && p.kind == ProbeKind::Canopy) canopy = &p;
    if (!force && (p.kind == ProbeKind::SupportForce || p.kind == ProbeKind::LinePull)) force = &p;
  }
  if (!canopy || !force) return std::nullopt;
  const std::vector<std::pair<std::vector<double> FlightSeries::*, std::string>> wanted{
      {&FlightSeries::force, force->name + ".magnitude"},
      {&FlightSeries::volume, canopy->name + ".volume"},
      {&FlightSeries::projectedDiameter, canopy->name + ".projected_diameter"},
      {&FlightSeries::dynamicPressure, canopy->name + ".dynamic_pressure"},
      {&FlightSeries::airspeed, canopy->name + ".airspeed"},
      {&FlightSeries::descent, canopy->name + ".descent_speed"},
      {&FlightSeries::swing, canopy->name + ".swing"}};
  FlightSeriesCollector c;
  c.s_.held = force->kind == ProbeKind::SupportForce;
  for (const auto& [member, name] : wanted) {
    const auto it = std::find(columns.begin(), columns.end(), name);
    if (it == columns.end()) return std::nullopt;
    c.columns_.push_back({member, static_cast<size_t>(it - columns.begin())});
  }
  return c;
}

void FlightSeriesCollector::add(double t, const std::vector<double>& row) {
  s_.t.push_back(t);
  for (const auto& [member, c] : columns_) (s_.*member).push_back(row[c]);
}

void FlightSeriesCollector::cutBackTo(size_t rows) {
  if (rows >= s_.t.size()) return;
  s_.t.resize(rows);
  for (const auto& column : columns_) (s_.*column.first).resize(rows);
}

std::optional<FlightSeries> flightSeries(const std::vector<ProbeSpec>& probes,
                                         const std::vector<std::string>& columns,
                                         const std::vector<double>& times,
                                         const std::vector<std::vector<double>>& rows) {
  auto c = FlightSeriesCollector::forCase(probes, columns);
  if (!c || times.empty()) return std::nullopt;
  for (size_t i = 0; i < rows.size(); ++i) c->add(times[i], rows[i]);
  return c->series();
}

namespace {
double meanFrom(const std::vector<double>& v, size_t from) {
  if (from >= v.size()) return 0.0;
  return std::accumulate(v.begin() + static_cast<long>(from), v.end(), 0.0) /
         static_cast<double>(v.size() - from);
}
}  // namespace

FlightFigures flightFigures(const FlightSeries& s, double D0, double S0, double weight) {
  FlightFigures f;
  f.held = s.held;
  const size_t n = s.t.size();
  if (n == 0) return f;
  // The steady state: the last fifth of the run.
  const double t0 = s.t.front(), t1 = s.t.back();
  size_t from = 0;
  while (from + 1 < n && s.t[from] < t1 - 0.2 * (t1 - t0)) ++from;
  f.steadyFrom = s.t[from];
  f.steadyForce = meanFrom(s.force, from);
  double var = 0.0;
  for (size_t i = from; i < n; ++i) var += std::pow(s.force[i] - f.steadyForce, 2);
  f.steadyVariation =
      f.steadyForce > 0.0 ? std::sqrt(var / static_cast<double>(n - from)) / f.steadyForce : 0.0;
  f.steadyDescentSpeed = meanFrom(s.descent, from);
  f.steadyAirspeed = meanFrom(s.airspeed, from);
  // The drag area: of what the held support holds, or of the whole free system, whose drag in
  // steady descent is its weight.
  const double q = meanFrom(s.dynamicPressure, from);
  const double drag = s.held ? f.steadyForce : weight;
  f.dragArea = q > 0.0 ? drag / q : 0.0;
  f.dragCoefficient = S0 > 0.0 ? f.dragArea / S0 : 0.0;
  f.projectedDiameterRatio = D0 > 0.0 ? meanFrom(s.projectedDiameter, from) / D0 : 0.0;
  const auto peak = std::max_element(s.force.begin(), s.force.end());
  f.peakForce = *peak;
  f.peakForceTime = s.t[static_cast<size_t>(peak - s.force.begin())];
  // Opening-force factor: against the steady force (held, infinite mass), or against the steady
  // drag area at the line-stretch dynamic pressure (free: C_x X_1 of Knacke's method).
  const double q0 = s.dynamicPressure.front();
  f.openingForceFactor = s.held ? (f.steadyForce > 0.0 ? f.peakForce / f.steadyForce : 0.0)
                                : (f.dragArea * q0 > 0.0 ? f.peakForce / (f.dragArea * q0) : 0.0);
  // Filling: from line stretch (the run's start) to the first time the captured volume reaches
  // kFilled of its steady value (the volume breathes about it by a few per cent once open); the
  // distance in nominal diameters at the line-stretch airspeed.
  constexpr double kFilled = 0.95;
  const double V = meanFrom(s.volume, from);
  for (size_t i = 0; i < n; ++i)
    if (s.volume[i] >= kFilled * V) {
      f.fillingTime = s.t[i] - t0;
      f.fillingDistance = D0 > 0.0 ? f.fillingTime * s.airspeed.front() / D0 : -1.0;
      for (size_t j = i; j < n; ++j) f.largestSwing = std::max(f.largestSwing, s.swing[j]);
      break;
    }
  return f;
}

}  // namespace chute
