#include "hotlap/ocp/optimal_output.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "hotlap/common/units.h"
#include "hotlap/ocp/channel_units.h"
#include "hotlap/track/track_point.h"

namespace hotlap::ocp {

using internal::Celsius;
using internal::Scaled;

sim::ColumnSet OptimalLapColumns(const OptimalLapRun& run, const track::Track& track) {
  const LapSolution& s = run.solution;
  sim::ColumnSet out;
  const auto add = [&](std::string name, std::vector<double> v) {
    out.names.push_back(std::move(name));
    out.values.push_back(std::move(v));
  };
  std::vector<double> x, y;
  for (size_t k = 0; k < s.distance.size(); ++k) {
    const Eigen::Vector3d p = track::PointAtOffset(track.At(s.distance[k]), s.n[k]);
    x.push_back(p[0]);
    y.push_back(p[1]);
  }
  add("distance_m", s.distance);
  add("time_s", s.time);
  add("speed_mps", s.u);
  add("lateral_speed_mps", s.v);
  add("yaw_rate_radps", s.r);
  add("offset_m", s.n);
  add("heading_error_deg", Scaled(s.xi, 180.0 / kPi));
  add("steer_deg", Scaled(s.steer, 180.0 / kPi));
  if (!s.pedal.empty()) add("pedal", s.pedal);
  add("drive_power_W", s.drive_power);
  add("brake_force_N", s.brake_force);
  add("x_m", x);
  add("y_m", y);
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    const CornerTrace& t = s.corners[i];
    const std::string_view n = CornerName(c);
    add(fmt::format("speed_{}_mps", n), t.speed);
    add(fmt::format("fx_{}_N", n), t.fx);
    add(fmt::format("fy_{}_N", n), t.fy);
    add(fmt::format("fz_{}_N", n), t.fz);
    add(fmt::format("slip_angle_{}_deg", n), Scaled(t.slip_angle, 180.0 / kPi));
    add(fmt::format("slip_ratio_{}", n), t.slip_ratio);
    add(fmt::format("tread_temp_{}_C", n), Celsius(t.tread_temp));
    add(fmt::format("carcass_temp_{}_C", n), Celsius(t.carcass_temp));
    add(fmt::format("wear_{}_mm", n), t.wear);
    add(fmt::format("disc_temp_{}_C", n), Celsius(t.disc_temp));
    add(fmt::format("calliper_temp_{}_C", n), Celsius(t.calliper_temp));
    add(fmt::format("brake_power_{}_W", n), t.brake_power);
    // The wheel states (a car with a gas-and-rim tyre or a surface-and-bulk disc).
    if (!t.rim_temp.empty()) add(fmt::format("rim_temp_{}_C", n), Celsius(t.rim_temp));
    if (!t.disc_bulk_temp.empty()) {
      add(fmt::format("disc_bulk_temp_{}_C", n), Celsius(t.disc_bulk_temp));
    }
    if (!t.gas_temp.empty()) {
      add(fmt::format("gas_temp_{}_C", n), Celsius(t.gas_temp));
      add(fmt::format("pressure_{}_kPa", n), Scaled(t.pressure, 1e-3));
      add(fmt::format("rolling_resistance_{}", n), t.rolling_resistance);
    }
    if (!run.exact.time.empty()) {
      add(fmt::format("tread_temp_{}_exact_C", n), Celsius(run.exact.corners[i].tread_temp));
      add(fmt::format("disc_temp_{}_exact_C", n), Celsius(run.exact.corners[i].disc_temp));
    }
  }
  return out;
}

OptimalLapFigures CalcOptimalLapFigures(const OptimalLapRun& run, double wheel_power) {
  const LapSolution& s = run.solution;
  OptimalLapFigures f;
  f.lap_time_s = s.lap_time;
  if (s.u.empty()) return f;
  f.top_speed_mps = *std::max_element(s.u.begin(), s.u.end());
  f.min_speed_mps = *std::min_element(s.u.begin(), s.u.end());
  for (int c = 0; c < 4; ++c) {
    const CornerTrace& t = s.corners[c];
    f.peak_disc_temp_C[c] =
        KelvinToCelsius(*std::max_element(t.disc_temp.begin(), t.disc_temp.end()));
    f.peak_tread_temp_C[c] =
        KelvinToCelsius(*std::max_element(t.tread_temp.begin(), t.tread_temp.end()));
    f.wear_mm[c] = t.wear.back() - t.wear.front();
  }
  f.max_front_disc_temp_C = std::max(f.peak_disc_temp_C[0], f.peak_disc_temp_C[1]);
  // Brake work, and the part of it done against the engine.
  const size_t n = std::min(s.time.size(), s.drive_power.size());
  const auto brake_power = [&](size_t k) {
    double sum = 0.0;
    for (const CornerTrace& t : s.corners) sum += t.brake_power[k];
    return sum;
  };
  for (size_t k = 0; k + 1 < n; ++k) {
    const double dt = s.time[k + 1] - s.time[k];
    for (const size_t j : {k, k + 1}) {
      const double e = 0.5 * dt * brake_power(j);
      f.brake_energy_J += e;
      if (s.drive_power[j] > 0.02 * wheel_power) f.brake_energy_under_drive_J += e;
    }
    if (dt > 0.0) {
      if (k + 1 < s.pedal.size()) {
        f.max_pedal_rate_per_s =
            std::max(f.max_pedal_rate_per_s, std::abs(s.pedal[k + 1] - s.pedal[k]) / dt);
      }
      f.max_steer_rate_radps =
          std::max(f.max_steer_rate_radps, std::abs(s.steer[k + 1] - s.steer[k]) / dt);
    }
  }
  return f;
}

}  // namespace hotlap::ocp
