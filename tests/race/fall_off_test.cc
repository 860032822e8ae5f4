// The fall-off from the car's own laps: the Gen-7-like car's tuned wear at Darlington against the
// public figure (Goodyear: 2 to 3 s over a fuel run), the heat's part beside the wear's, and what
// is refused.

#include "hotlap/race/fall_off.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/ocp/min_curvature_line.h"
#include "hotlap/sim/road.h"
#include "hotlap/track/track_io.h"
#include "test_util.h"

namespace hotlap::race {
namespace {

TEST(FallOffTest, SixtyLapsAtDarlingtonLoseTwoToThreeAndAHalfSecondsFromTheWear) {
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  const track::Track track = track::LoadTrack("darlington");
  // As `hotlap race` drives it: the minimum-curvature line, 2 m road.
  const std::vector<sim::RoadPoint> road = sim::SampleRoadAlongLine(
      track, ocp::MinimumCurvatureLine(track, {.step_m = 2.0, .margin_m = 1.5}), 2.0);
  sim::QssOptions o;
  o.track_length = track.length_m();
  o.ambient_temp = CelsiusToKelvin(25.0);
  o.track_temp = CelsiusToKelvin(40.0);
  o.initial = sim::CarStartState(car);  // new tyres from pit-out
  // A caution of six laps at 65 s a lap after 20 green laps.
  const FallOff f =
      FallOffFromQss(car, road, o, 60, 25.0,
                     {.caution = {.after_green_laps = 20, .laps = 6, .speed = 2198.0 / 65.0},
                      .right_stops_after = {15, 30, 45, 60}});
  ASSERT_EQ(f.lap_time_s.size(), 60u);
  ASSERT_EQ(f.heat_only_lap_time_s.size(), 60u);
  EXPECT_GE(f.Spread(), 2.0);
  EXPECT_LE(f.Spread(), 3.5);
  // The fastest lap comes once the tyres are warm, early in the run, not at its end.
  const auto fastest = std::min_element(f.lap_time_s.begin(), f.lap_time_s.end());
  EXPECT_LT(fastest - f.lap_time_s.begin(), 15);
  // The heat settles: without grip lost to wear the set holds its time (the carcasses no longer
  // climb lap after lap), so the fall-off is the wear's.
  EXPECT_LT(f.HeatOnlySpread(), 0.05);
  EXPECT_LT(f.heat_only_lap_time_s.back(), f.lap_time_s.back() - 2.0);
  EXPECT_GT(f.fuel_s_per_kg, 0.0);
  // Behind the pace car the treads cool below the compound's window: the laps after it are
  // slower, by some seconds over three laps, not by a lap's worth.
  EXPECT_GT(f.restart_penalty_s, 0.5);
  EXPECT_LT(f.restart_penalty_s, 8.0);
  // Right-side stops: new right tyres on old left ones are slower than a new set of the same age
  // (the old lefts' lost grip) and faster than the old set run on (the rights' lost grip).
  ASSERT_EQ(f.right_stop_lap_time_s.size(), 4u);
  for (size_t i = 0; i < 4; ++i) {
    ASSERT_EQ(f.right_stop_lap_time_s[i].size(), 60u);
    const int after = f.right_stop_after_laps[i];
    for (int k = 5; k < 60; ++k) {
      EXPECT_GT(f.right_stop_lap_time_s[i][k], f.lap_time_s[k]) << after << " " << k;
      if (after + k < 60) {
        EXPECT_LT(f.right_stop_lap_time_s[i][k], f.lap_time_s[after + k]);
      }
    }
  }
  // A right-side stop between two of them, driven: the interpolated two-age times hold it within
  // a few hundredths a lap over the 60 laps after it (0.025 s measured).
  const SideStopCheck check = CheckRightSideStop(car, road, o, f, 22, 60);
  ASSERT_EQ(check.driven_s.size(), 60u);
  EXPECT_LT(check.max_abs_difference_s, 0.06);
  EXPECT_LT(std::abs(check.mean_difference_s), 0.02);
}

TEST(FallOffTest, WithoutGripLossFromWearHoldsEveryCompoundAtOne) {
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  const vehicle::Car held = WithoutGripLossFromWear(car);
  for (int k = 0; k < 4; ++k) {
    EXPECT_LT(car.tyres[k].compound->grip_vs_wear.Evaluate(2.0), 0.95) << k;
    EXPECT_EQ(held.tyres[k].compound->grip_vs_wear.Evaluate(2.0), 1.0) << k;
    EXPECT_EQ(held.tyres[k].compound->grip.Evaluate(CelsiusToKelvin(60.0)),
              car.tyres[k].compound->grip.Evaluate(CelsiusToKelvin(60.0)))
        << k;
  }
}

TEST(FallOffTest, WithoutAHeatOnlyTableItsSpreadIsZeroAndShortRunsAreRefused) {
  FallOff f;
  for (int a = 0; a < 20; ++a) f.lap_time_s.push_back(30.0 + 0.05 * a);
  EXPECT_EQ(f.HeatOnlySpread(), 0.0);
  f.heat_only_lap_time_s = {31.0, 30.2, 30.1, 30.15};
  EXPECT_NEAR(f.HeatOnlySpread(), 0.05, 1e-12);
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  EXPECT_THROW(FallOffFromQss(car, {}, {}, 1, 25.0), InputError);
  // A caution run that leaves fewer than the restart's laps of the table after it.
  EXPECT_THROW(FallOffFromQss(car, {}, {}, 10, 25.0,
                              {.caution = {.after_green_laps = 5, .laps = 4, .speed = 30.0}}),
               InputError);
  EXPECT_THROW(FallOffFromQss(car, {}, {}, 10, 25.0, {.fuel_delta_kg = 0.0}), InputError);
  // Right-side stops outside the table or out of order.
  EXPECT_THROW(FallOffFromQss(car, {}, {}, 10, 25.0, {.right_stops_after = {5, 11}}), InputError);
  EXPECT_THROW(FallOffFromQss(car, {}, {}, 10, 25.0, {.right_stops_after = {6, 4}}), InputError);
  EXPECT_THROW(CheckRightSideStop(car, {}, {}, f, 5, 5), InputError);  // no right-side stops
}

}  // namespace
}  // namespace hotlap::race
