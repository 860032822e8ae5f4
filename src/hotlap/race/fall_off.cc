#include "hotlap/race/fall_off.h"

#include <algorithm>

#include <fmt/format.h>

#include "hotlap/common/error.h"

namespace hotlap::race {

double FallOff::LapTime(int age, double fuel_kg) const {
  const int n = static_cast<int>(lap_time_s.size());
  const double fuel = fuel_s_per_kg * (fuel_kg - reference_fuel_kg);
  if (age < n) return lap_time_s[std::max(age, 0)] + fuel;
  // The trend of the last ten laps (or as many as there are), carried on linearly.
  const int k = std::min(10, n - 1);
  const double slope = k > 0 ? (lap_time_s[n - 1] - lap_time_s[n - 1 - k]) / k : 0.0;
  return lap_time_s[n - 1] + slope * (age - (n - 1)) + fuel;
}

double FallOff::Spread() const {
  if (lap_time_s.empty()) return 0.0;
  return lap_time_s.back() - *std::min_element(lap_time_s.begin(), lap_time_s.end());
}

FallOff FallOffFromQss(const vehicle::Car& car, std::span<const sim::RoadPoint> road,
                       sim::QssOptions options, int laps, double reference_fuel_kg,
                       double fuel_delta_kg) {
  if (laps < 2) throw InputError(fmt::format("fall-off: {} laps; at least 2", laps));
  if (!(fuel_delta_kg > 0.0)) {
    throw InputError(fmt::format("fall-off: fuel step {:g} kg must be > 0", fuel_delta_kg));
  }
  options.laps = laps;
  FallOff f;
  f.reference_fuel_kg = reference_fuel_kg;
  const sim::QssResult base = sim::RunQssLap(car, road, options);
  for (const sim::QssLap& lap : base.laps) f.lap_time_s.push_back(lap.lap_time);
  vehicle::Car heavier = car;
  vehicle::RequireVehicle(heavier, "the fall-off");
  heavier.vehicle->chassis.mass += fuel_delta_kg;
  const sim::QssResult heavy = sim::RunQssLap(heavier, road, options);
  double sum = 0.0;
  for (int l = 0; l < laps; ++l) sum += heavy.laps[l].lap_time - base.laps[l].lap_time;
  f.fuel_s_per_kg = sum / (laps * fuel_delta_kg);
  return f;
}

}  // namespace hotlap::race
