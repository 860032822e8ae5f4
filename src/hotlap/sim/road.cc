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
    road[i] = {s, p.curvature_per_m, p.bank_rad, p.grade_rad, s, 0.0};
  }
  return road;
}

std::vector<RoadPoint> SampleRoadAlongLine(const track::Track& track, const track::RacingLine& line,
                                           double step_m) {
  if (!(step_m > 0.0) || !(step_m <= track.length_m() / 16.0)) {
    throw InputError(
        fmt::format("road step {:g} m must be > 0 and at most a sixteenth of the "
                    "{:.1f} m lap",
                    step_m, track.length_m()));
  }
  const std::vector<track::LinePoint> points = track::SampleLine(track, line, step_m);
  std::vector<RoadPoint> road(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const track::LinePoint& p = points[i];
    road[i] = {p.path_m, p.curvature_per_m, p.bank_rad, p.grade_rad, p.s_m, p.offset_m};
  }
  return road;
}

}  // namespace hotlap::sim
