#pragma once
/// @file
/// Shared by the fitting tests: a small oval road for the lap simulation, the gen7 car, and
/// "true" parameters a fixed fraction away from the car's.

#include <cmath>
#include <vector>

#include "hotlap/common/units.h"
#include "hotlap/sim/qss_lap.h"
#include "hotlap/sim/synth.h"
#include "hotlap/vehicle/car.h"
#include "test_util.h"

namespace hotlap::test {

/// An oval: straights of `straight` m joined by two 180-degree turns of radius `radius` with
/// linear-curvature transitions of `transition` m each side, banked 24 deg in the turns and 3 deg
/// on the straights (the banking follows the curvature), about 1 m spacing.
inline std::vector<sim::RoadPoint> OvalRoad(double straight = 350.0, double radius = 180.0,
                                            double transition = 80.0) {
  const double arc = (kPi - transition / radius) * radius;
  const std::vector<double> lengths = {straight, transition, arc, transition,
                                       straight, transition, arc, transition};
  double total = 0.0;
  for (double l : lengths) total += l;
  const int n = static_cast<int>(std::round(total));
  const double ds = total / n;
  std::vector<sim::RoadPoint> road(n);
  for (int i = 0; i < n; ++i) {
    double x = i * ds;
    size_t seg = 0;
    while (seg + 1 < lengths.size() && x >= lengths[seg]) x -= lengths[seg++];
    double share = 0.0;
    if (seg % 4 == 1) share = x / transition;
    if (seg % 4 == 2) share = 1.0;
    if (seg % 4 == 3) share = 1.0 - x / transition;
    road[i] = {i * ds, share / radius, DegToRad(3.0 + 21.0 * share), 0.0};
  }
  return road;
}

/// The shipped gen7 car.
inline vehicle::Car Gen7Car() { return vehicle::LoadCar(Gen7Dir() / "car.yaml"); }

}  // namespace hotlap::test
