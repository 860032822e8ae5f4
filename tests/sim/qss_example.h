#pragma once
// A hand-made stint of quasi-steady-state laps (five samples a lap, one braking zone each, the
// thermal histories rising lap by lap), for the tests of what is reported of a stint.

#include "hotlap/common/units.h"
#include "hotlap/sim/qss_lap.h"

namespace hotlap::sim::testing {

// Lap `l` (0-based) of the stint: peaks rise by 10 K a lap, wear by 0.01 mm a lap, and the rear
// right is 5 K hotter than the others.
inline QssLap MakeExampleQssLap(int l) {
  QssLap lap;
  lap.distance = lap.centre_distance = {0.0, 25.0, 50.0, 75.0, 100.0};
  lap.time = {0.0, 0.5, 1.1, 1.8, 2.3};
  lap.speed = {50.0, 48.0, 30.0, 35.0, 50.0 + l};
  lap.accel_long = {0.0, -20.0, -15.0, 5.0, 3.0};
  lap.lap_time = 2.3 + 0.1 * l;
  lap.slip_points_not_reached = l;
  lap.max_force_deficit = 100.0 * l;
  lap.thermal.time = lap.time;
  for (int k = 0; k < 4; ++k) {
    CornerHistory& h = lap.thermal.corners[k];
    const double base = CelsiusToKelvin(80.0) + 10.0 * l + (k == 3 ? 5.0 : 0.0);
    h.tread_temp = {base, base + 2.0, base + 1.0, base, base};
    h.carcass_temp = {base - 20.0, base - 19.0, base - 18.0, base - 18.0, base - 18.0};
    h.disc_temp = {base + 300.0, base + 400.0, base + 350.0, base + 320.0, base + 310.0};
    h.calliper_temp = {base + 50.0, base + 50.0, base + 51.0, base + 51.0, base + 51.0};
    h.wear = {0.01 * l, 0.01 * l, 0.01 * l + 0.005, 0.01 * l + 0.008, 0.01 * (l + 1)};
  }
  return lap;
}

inline QssResult MakeExampleQssResult(int laps) {
  QssResult result;
  for (int l = 0; l < laps; ++l) result.laps.push_back(MakeExampleQssLap(l));
  return result;
}

}  // namespace hotlap::sim::testing
