#include "hotlap/race/fall_off.h"

#include <algorithm>
#include <memory>

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

namespace {

double LastOverFastest(const std::vector<double>& t) {
  if (t.empty()) return 0.0;
  return t.back() - *std::min_element(t.begin(), t.end());
}

}  // namespace

double FallOff::Spread() const { return LastOverFastest(lap_time_s); }

double FallOff::HeatOnlySpread() const { return LastOverFastest(heat_only_lap_time_s); }

vehicle::Car WithoutGripLossFromWear(const vehicle::Car& car) {
  vehicle::Car out = car;
  for (tyre::TyreFile& t : out.tyres) {
    if (t.compound == nullptr) continue;
    auto compound = std::make_shared<tyre::TyreCompound>(*t.compound);
    compound->grip_vs_wear = {.wear_mm = {0.0, 1.0}, .factor = {1.0, 1.0}};
    t.compound = std::move(compound);
  }
  return out;
}

FallOff FallOffFromQss(const vehicle::Car& car, std::span<const sim::RoadPoint> road,
                       sim::QssOptions options, int laps, double reference_fuel_kg,
                       double fuel_delta_kg, const CautionLaps& caution) {
  if (laps < 2) throw InputError(fmt::format("fall-off: {} laps; at least 2", laps));
  if (!(fuel_delta_kg > 0.0)) {
    throw InputError(fmt::format("fall-off: fuel step {:g} kg must be > 0", fuel_delta_kg));
  }
  const int restart =
      caution.after_green_laps + caution.laps;  // the first green lap after, 0-based
  if (caution.speed > 0.0 && (caution.after_green_laps < 1 || caution.laps < 1 ||
                              restart + FallOff::kRestartLaps > laps)) {
    throw InputError(fmt::format(
        "fall-off: a caution of {} laps after {} green laps leaves fewer than {} of the {} laps",
        caution.laps, caution.after_green_laps, FallOff::kRestartLaps, laps));
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
  const sim::QssResult heat = sim::RunQssLap(WithoutGripLossFromWear(car), road, options);
  for (const sim::QssLap& lap : heat.laps) f.heat_only_lap_time_s.push_back(lap.lap_time);
  if (caution.speed > 0.0) {
    // The caution's laps wear nothing to speak of: after it the set is as old as before it.
    sim::QssOptions slowed = options;
    slowed.caution_speed = caution.speed;
    for (int l = 0; l < caution.laps; ++l)
      slowed.caution_laps.push_back(caution.after_green_laps + l);
    const sim::QssResult run = sim::RunQssLap(car, road, slowed);
    for (int j = 0; j < FallOff::kRestartLaps; ++j) {
      f.restart_penalty_s +=
          run.laps[restart + j].lap_time - base.laps[caution.after_green_laps + j].lap_time;
    }
  }
  return f;
}

}  // namespace hotlap::race
