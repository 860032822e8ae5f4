#include "hotlap/race/fall_off.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "hotlap/common/corner.h"
#include "hotlap/common/error.h"
#include "hotlap/sim/replay.h"

namespace hotlap::race {

namespace {

// t[age], past the table the trend of its last ten laps (or as many as there are) carried on
// linearly.
double AtAge(const std::vector<double>& t, int age) {
  const int n = static_cast<int>(t.size());
  if (age < n) return t[std::max(age, 0)];
  const int k = std::min(10, n - 1);
  const double slope = k > 0 ? (t[n - 1] - t[n - 1 - k]) / k : 0.0;
  return t[n - 1] + slope * (age - (n - 1));
}

}  // namespace

double FallOff::LapTime(int age, double fuel_kg) const {
  return AtAge(lap_time_s, age) + fuel_s_per_kg * (fuel_kg - reference_fuel_kg);
}

bool FallOff::HasSides() const {
  return !right_stop_after_laps.empty() &&
         right_stop_lap_time_s.size() == right_stop_after_laps.size();
}

double FallOff::LapTime(int left_age, int right_age, double fuel_kg) const {
  if (left_age == right_age) return LapTime(right_age, fuel_kg);
  if (!HasSides() || left_age < right_age) {
    throw InputError(fmt::format(
        "fall-off: left tyres {} laps old, right {}: needs right-side stops driven and the left "
        "tyres the older",
        left_age, right_age));
  }
  // What left tyres d laps older than the right ones cost at this right-tyre age: 0 at d = 0,
  // each driven stop's lap over the set's, linear between and past the last two.
  const int d = left_age - right_age;
  const double set = AtAge(lap_time_s, right_age);
  double d0 = 0.0, c0 = 0.0, d1 = 0.0, c1 = 0.0;
  for (size_t i = 0; i < right_stop_after_laps.size(); ++i) {
    d0 = d1;
    c0 = c1;
    d1 = right_stop_after_laps[i];
    c1 = AtAge(right_stop_lap_time_s[i], right_age) - set;
    if (d <= d1) break;
  }
  const double cost = c0 + (c1 - c0) * (d - d0) / (d1 - d0);
  return LapTime(right_age, fuel_kg) + cost;
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

namespace {

// A lap's per-corner state from its thermal replay.
SetLap SetLapOf(const sim::ReplayResult& r) {
  SetLap out;
  for (size_t k = 0; k < 4; ++k) {
    const sim::CornerHistory& h = r.corners[k];
    out.tread_temp[k] = sim::CalcHistoryStats(r.time, h.tread_temp).mean;
    out.carcass_temp[k] = sim::CalcHistoryStats(r.time, h.carcass_temp).mean;
    out.disc_peak_temp[k] = sim::CalcHistoryStats(r.time, h.disc_temp).peak;
    out.wear_mm[k] = h.wear.empty() ? 0.0 : h.wear.back();
    out.pressure[k] = h.pressure.empty() ? 0.0 : sim::CalcHistoryStats(r.time, h.pressure).mean;
  }
  return out;
}

// The state after a right-side stop made at the end of `before` (the left tyres and brakes as
// they are, new right tyres at the pit-out temperatures).
sim::ReplayInitialState AfterRightSideStop(const vehicle::Car& car, const sim::QssLap& before) {
  sim::ReplayInitialState state = sim::EndState(before.thermal);
  const sim::ReplayInitialState fresh = sim::CarStartState(car);
  for (Corner c : {Corner::kFrontRight, Corner::kRearRight}) {
    state.tyres[CornerIndex(c)] = fresh.tyres[CornerIndex(c)];
  }
  return state;
}

}  // namespace

FallOff FallOffFromQss(const vehicle::Car& car, std::span<const sim::RoadPoint> road,
                       sim::QssOptions options, int laps, double reference_fuel_kg,
                       const FallOffRuns& runs) {
  const double fuel_delta_kg = runs.fuel_delta_kg;
  const CautionLaps& caution = runs.caution;
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
  int previous = 0;
  for (int a : runs.right_stops_after) {
    if (a <= previous || a > laps) {
      throw InputError(
          fmt::format("fall-off: right-side stops after {} laps: increasing and in [1, {}]",
                      fmt::join(runs.right_stops_after, ", "), laps));
    }
    previous = a;
  }
  const int total = 3 + (caution.speed > 0.0) + static_cast<int>(runs.right_stops_after.size());
  int done = 0;
  const auto tell = [&](const std::string& what) {
    if (runs.progress) runs.progress(fmt::format("{} of {}: {}", ++done, total, what));
  };
  tell(fmt::format("{} laps on a new set", laps));
  const sim::QssResult base = sim::RunQssLap(car, road, options);
  for (const sim::QssLap& lap : base.laps) {
    f.lap_time_s.push_back(lap.lap_time);
    f.set_laps.push_back(SetLapOf(lap.thermal));
  }
  vehicle::Car heavier = car;
  vehicle::RequireVehicle(heavier, "the fall-off");
  heavier.vehicle->chassis.mass += fuel_delta_kg;
  tell(fmt::format("the same laps {:g} kg heavier (the fuel's weight)", fuel_delta_kg));
  const sim::QssResult heavy = sim::RunQssLap(heavier, road, options);
  double sum = 0.0;
  for (int l = 0; l < laps; ++l) sum += heavy.laps[l].lap_time - base.laps[l].lap_time;
  f.fuel_s_per_kg = sum / (laps * fuel_delta_kg);
  tell("the same laps with the grip kept from falling with wear (the heat's part)");
  const sim::QssResult heat = sim::RunQssLap(WithoutGripLossFromWear(car), road, options);
  for (const sim::QssLap& lap : heat.laps) f.heat_only_lap_time_s.push_back(lap.lap_time);
  for (int after : runs.right_stops_after) {
    tell(fmt::format("{} laps on new right-side tyres after {} on the set", laps, after));
    sim::QssOptions rights = options;
    rights.initial = AfterRightSideStop(car, base.laps[after - 1]);
    const sim::QssResult run = sim::RunQssLap(car, road, rights);
    f.right_stop_after_laps.push_back(after);
    f.right_stop_lap_time_s.emplace_back();
    for (const sim::QssLap& lap : run.laps) f.right_stop_lap_time_s.back().push_back(lap.lap_time);
  }
  if (caution.speed > 0.0) {
    // The caution's laps wear nothing to speak of: after it the set is as old as before it.
    sim::QssOptions slowed = options;
    slowed.caution_speed = caution.speed;
    for (int l = 0; l < caution.laps; ++l)
      slowed.caution_laps.push_back(caution.after_green_laps + l);
    tell(fmt::format("the same laps with a {}-lap caution after lap {} (the restart)", caution.laps,
                     caution.after_green_laps));
    const sim::QssResult run = sim::RunQssLap(car, road, slowed);
    for (int j = 0; j < FallOff::kRestartLaps; ++j) {
      f.restart_penalty_s +=
          run.laps[restart + j].lap_time - base.laps[caution.after_green_laps + j].lap_time;
    }
  }
  return f;
}

SideStopCheck CheckRightSideStop(const vehicle::Car& car, std::span<const sim::RoadPoint> road,
                                 sim::QssOptions options, const FallOff& fall_off, int before,
                                 int after) {
  if (!fall_off.HasSides()) throw InputError("right-side stop check: the fall-off has no sides");
  if (before < 1 || after < 1) {
    throw InputError(fmt::format(
        "right-side stop check: {} laps before and {} after; at least 1 each", before, after));
  }
  SideStopCheck out;
  out.before = before;
  out.after = after;
  options.laps = before;
  const sim::QssResult first = sim::RunQssLap(car, road, options);
  options.initial = AfterRightSideStop(car, first.laps.back());
  options.laps = after;
  const sim::QssResult second = sim::RunQssLap(car, road, options);
  double sum = 0.0;
  for (int k = 0; k < after; ++k) {
    const double driven = second.laps[k].lap_time;
    const double model = fall_off.LapTime(before + k, k, fall_off.reference_fuel_kg);
    out.driven_s.push_back(driven);
    out.fall_off_s.push_back(model);
    out.max_abs_difference_s = std::max(out.max_abs_difference_s, std::abs(driven - model));
    sum += driven - model;
  }
  out.mean_difference_s = sum / after;
  return out;
}

}  // namespace hotlap::race
