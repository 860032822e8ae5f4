#pragma once
// Closed test roads for the quasi-steady-state lap's tests: a banked circle and a simple oval, at
// about 1 m spacing.

#include <cmath>
#include <vector>

#include "hotlap/common/units.h"
#include "hotlap/sim/qss_lap.h"

namespace hotlap::sim::testing {

// A closed circle of radius `radius`, banked `bank_deg`, about 1 m spacing.
inline std::vector<RoadPoint> Circle(double radius, double bank_deg) {
  const int n = static_cast<int>(std::round(2.0 * kPi * radius));
  const double ds = 2.0 * kPi * radius / n;
  std::vector<RoadPoint> road(n);
  for (int i = 0; i < n; ++i) road[i] = {i * ds, 1.0 / radius, DegToRad(bank_deg), 0.0};
  return road;
}

// A simple oval: straights of `straight` m joined by two 180-degree arcs of radius `radius` with
// linear-curvature transitions of `transition` m each side, banked 24 deg in the turns and 3 deg
// on the straights (the banking ramps with the curvature).
inline std::vector<RoadPoint> Oval(double straight, double radius, double transition) {
  const double arc = (kPi - transition / radius) * radius;
  const std::vector<double> lengths = {straight, transition, arc, transition,
                                       straight, transition, arc, transition};
  double total = 0.0;
  for (double l : lengths) total += l;
  const int n = static_cast<int>(std::round(total));
  const double ds = total / n;
  std::vector<RoadPoint> road(n);
  for (int i = 0; i < n; ++i) {
    double x = i * ds;
    size_t seg = 0;
    while (seg + 1 < lengths.size() && x >= lengths[seg]) x -= lengths[seg++];
    double share = 0.0;  // of the turn's curvature
    if (seg % 4 == 1) share = x / transition;
    if (seg % 4 == 2) share = 1.0;
    if (seg % 4 == 3) share = 1.0 - x / transition;
    road[i] = {i * ds, share / radius, DegToRad(3.0 + 21.0 * share), 0.0};
  }
  return road;
}

}  // namespace hotlap::sim::testing
