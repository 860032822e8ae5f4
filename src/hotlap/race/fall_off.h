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
  /// The same laps with the tyres' grip kept from falling with wear (h(wear) = 1): the heat's
  /// part of the fall-off alone, s; empty where it was not run.
  std::vector<double> heat_only_lap_time_s;
  /// What the tyres and brakes cooled by a caution cost the green laps after it, s: the first
  /// kRestartLaps green laps after a caution against the same laps of the set without it (0
  /// where it was not run).
  double restart_penalty_s = 0.0;
  static constexpr int kRestartLaps = 3;

  /// The lap time at `age` laps on the set (past the table, the last ten laps' trend carried on)
  /// with `fuel_kg` aboard, s.
  double LapTime(int age, double fuel_kg) const;
  /// The last lap's time over the fastest's, s: how much the set falls off over the table.
  double Spread() const;
  /// The same of heat_only_lap_time_s (0 if empty): the fall-off the heat makes without wear.
  double HeatOnlySpread() const;
};

/// The car with every tyre's grip independent of its wear (h(wear) = 1; the wear still grows).
vehicle::Car WithoutGripLossFromWear(const vehicle::Car& car);

/// How a caution is driven in the fall-off's laps: `laps` laps at `speed` after `after_green_laps`
/// green laps on the set (speed 0: no caution run, no restart penalty).
struct CautionLaps {
  int after_green_laps = 20;
  int laps = 6;
  double speed = 0.0;  ///< m/s
};

/// The fall-off of the car's tyres: `laps` QSS laps from the car's pit-out state on new tyres
/// (`options.initial` and the rest as given; `options.laps` is set here), and the fuel's weight
/// from the same laps with `fuel_delta_kg` more mass. `reference_fuel_kg` is the fuel the car's
/// chassis mass includes; and the heat's part (FallOff::heat_only_lap_time_s) from the same laps
/// with every compound's grip against wear held at 1; with `caution.speed` > 0 the restart penalty
/// from the same laps with a caution run in them. InputError for laps < 2, fuel_delta_kg <= 0 or a
/// caution that leaves fewer than FallOff::kRestartLaps laps of the table after it.
FallOff FallOffFromQss(const vehicle::Car& car, std::span<const sim::RoadPoint> road,
                       sim::QssOptions options, int laps, double reference_fuel_kg,
                       double fuel_delta_kg = 10.0, const CautionLaps& caution = {});

}  // namespace hotlap::race
