#pragma once
/// @file
/// A tyre set's fall-off: the lap time on a set against its age and the fuel aboard, taken from
/// the car's own laps (sim/qss_lap.h: the thermal models settling from pit-out, the wear growing)
/// rather than fitted to a curve of age (docs/race.md).

#include <span>
#include <vector>

#include "hotlap/sim/qss_lap.h"

namespace hotlap::race {

struct FallOff {
  /// Lap time on a set of age a laps (a = 0: the out lap on new, cold tyres), with the car's
  /// reference fuel aboard, s.
  std::vector<double> lap_time_s;
  /// Lap time per kilogram of fuel aboard, s/kg (> 0: fuel is weight).
  double fuel_s_per_kg = 0.0;
  /// The fuel the car's mass includes, kg: lap_time_s holds for it.
  double reference_fuel_kg = 0.0;

  /// The lap time at `age` laps on the set (past the table, the last ten laps' trend carried on)
  /// with `fuel_kg` aboard, s.
  double LapTime(int age, double fuel_kg) const;
  /// The last lap's time over the fastest's, s: how much the set falls off over the table.
  double Spread() const;
};

/// The fall-off of the car's tyres: `laps` QSS laps from the car's pit-out state on new tyres
/// (`options.initial` and the rest as given; `options.laps` is set here), and the fuel's weight
/// from the same laps with `fuel_delta_kg` more mass. `reference_fuel_kg` is the fuel the car's
/// chassis mass includes. InputError for laps < 2 or fuel_delta_kg <= 0.
FallOff FallOffFromQss(const vehicle::Car& car, std::span<const sim::RoadPoint> road,
                       sim::QssOptions options, int laps, double reference_fuel_kg,
                       double fuel_delta_kg = 10.0);

}  // namespace hotlap::race
