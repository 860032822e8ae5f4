#pragma once
/// @file
/// A tyre set's fall-off: the lap time on a set against its age and the fuel aboard, taken from
/// the car's own laps (sim/qss_lap.h: the thermal models settling from pit-out, the wear growing)
/// rather than fitted to a curve of age (docs/race.md).

#include <array>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "hotlap/sim/qss_lap.h"

namespace hotlap::race {

/// One lap on the set, per corner (fl, fr, rl, rr): the tyres' and brakes' state the lap time
/// comes from.
struct SetLap {
  std::array<double, 4> tread_temp{};      ///< time-mean over the lap, K
  std::array<double, 4> carcass_temp{};    ///< time-mean, K
  std::array<double, 4> disc_peak_temp{};  ///< K
  std::array<double, 4> wear_mm{};         ///< at the lap's end
  std::array<double, 4> pressure{};        ///< time-mean hot gauge pressure, Pa (0: no gas node)
};

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
  /// Right-side stops driven: after right_stop_after_laps[i] laps on the set (increasing), the
  /// right tyres replaced by new ones at the pit-out temperatures, the left tyres and the brakes
  /// as they were; right_stop_lap_time_s[i][j] is the j-th lap on the new right tyres (as many
  /// laps as lap_time_s). Empty where they were not run.
  std::vector<int> right_stop_after_laps;
  std::vector<std::vector<double>> right_stop_lap_time_s;
  /// What the tyres and brakes cooled by a caution cost the green laps after it, s: the first
  /// kRestartLaps green laps after a caution against the same laps of the set without it (0
  /// where it was not run).
  double restart_penalty_s = 0.0;
  static constexpr int kRestartLaps = 3;
  /// The set's laps' temperatures, wear and pressures (as lap_time_s); empty where not kept.
  std::vector<SetLap> set_laps;

  /// The lap time at `age` laps on the set (past the table, the last ten laps' trend carried on)
  /// with `fuel_kg` aboard, s.
  double LapTime(int age, double fuel_kg) const;
  /// The lap time with left tyres `left_age` laps old and right tyres `right_age` laps old
  /// (after right-side stops: left_age >= right_age), s: the set's at the right tyres' age plus
  /// what the older left tyres cost, taken from the right-side stops driven (their lap over the
  /// set's at the same right-tyre age), interpolated linearly in the age difference between the
  /// stops driven (and carried on past the last). Equal ages: LapTime(age, fuel_kg) exactly.
  /// InputError if the ages differ and no right-side stops were driven (HasSides), or the left
  /// tyres are the younger.
  double LapTime(int left_age, int right_age, double fuel_kg) const;
  /// Whether right-side stops were driven, so that the sides may differ in age.
  bool HasSides() const;
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

/// What the fall-off's QSS laps measure beside the set's own laps.
struct FallOffRuns {
  double fuel_delta_kg = 10.0;  ///< the mass step for the fuel's weight, kg (> 0)
  CautionLaps caution;          ///< speed 0: no restart penalty
  /// Right-side stops to drive after these laps on the set (each in [1, laps], increasing;
  /// FallOff::right_stop_lap_time_s); empty: none.
  std::vector<int> right_stops_after;
  /// Told before each run of laps what it is ("2 of 5: the same laps 10 kg heavier"); may be empty.
  std::function<void(const std::string&)> progress;
};

/// The fall-off of the car's tyres: `laps` QSS laps from the car's pit-out state on new tyres
/// (`options.initial` and the rest as given; `options.laps` is set here), and the fuel's weight
/// from the same laps with `runs.fuel_delta_kg` more mass. `reference_fuel_kg` is the fuel the
/// car's chassis mass includes; and the heat's part (FallOff::heat_only_lap_time_s) from the same
/// laps with every compound's grip against wear held at 1; with `runs.caution.speed` > 0 the
/// restart penalty from the same laps with a caution run in them; the right-side stops asked for,
/// each followed by `laps` laps. InputError for laps < 2, fuel_delta_kg <= 0 or a caution
/// that leaves fewer than FallOff::kRestartLaps laps of the table after it, or right-side stops
/// outside [1, laps] or not increasing.
FallOff FallOffFromQss(const vehicle::Car& car, std::span<const sim::RoadPoint> road,
                       sim::QssOptions options, int laps, double reference_fuel_kg,
                       const FallOffRuns& runs = {});

/// A right-side stop driven, against the fall-off's two-age lap times: `before` QSS laps on a new
/// set from `options.initial`, then the right tyres replaced by new ones at the car's pit-out
/// temperatures (the left tyres and the brakes as they are) and `after` laps more.
struct SideStopCheck {
  int before = 0, after = 0;
  std::vector<double> driven_s;     ///< the `after` laps' QSS times, s
  std::vector<double> fall_off_s;   ///< FallOff::LapTime(before + k, k, reference fuel), s
  double max_abs_difference_s = 0;  ///< the largest |driven - fall_off| over those laps
  double mean_difference_s = 0;     ///< mean (driven - fall_off), s
};

/// The check above (InputError if `fall_off` has no sides, before < 1 or after < 1).
SideStopCheck CheckRightSideStop(const vehicle::Car& car, std::span<const sim::RoadPoint> road,
                                 sim::QssOptions options, const FallOff& fall_off, int before,
                                 int after);

}  // namespace hotlap::race
