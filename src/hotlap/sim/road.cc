#include "hotlap/sim/road.h"

#include <cmath>

#include <fmt/format.h>

#include "hotlap/common/error.h"

namespace hotlap::sim {

std::vector<RoadPoint> SampleRoad(const track::Track& track, double step_m) {
  const double length = track.length_m();
  if (!(step_m > 0.0) || !(step_m <= length / 16.0)) {
    throw InputError(
        fmt::format("road step {:g} m must be > 0 and at most a sixteenth of the "
                    "{:.1f} m lap",
                    step_m, length));
  }
  const int n = static_cast<int>(std::round(length / step_m));
  std::vector<RoadPoint> road(n);
  for (int i = 0; i < n; ++i) {
    const double s = length * i / n;
    const track::TrackPoint p = track.At(s);
    road[i] = {s, p.curvature_per_m, p.bank_rad, p.grade_rad};
  }
  return road;
}

}  // namespace hotlap::sim
