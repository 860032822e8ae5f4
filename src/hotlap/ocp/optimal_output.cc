#include "hotlap/ocp/optimal_output.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "hotlap/common/units.h"
#include "hotlap/track/track_point.h"

namespace hotlap::ocp {

namespace {

std::vector<double> Celsius(std::vector<double> k) {
  for (double& x : k) x = KelvinToCelsius(x);
  return k;
}

std::vector<double> Scaled(std::vector<double> v, double s) {
  for (double& x : v) x *= s;
  return v;
}

}  // namespace

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

void AddOptimalLapCharts(report::HtmlReport& page, const std::vector<const OptimalLapRun*>& runs,
                         const std::vector<std::string>& labels, const track::Track& track) {
  const auto style = [](size_t r) {
    return r == 0 ? report::LineStyle::kSolid : report::LineStyle::kDashed;
  };
  const std::vector<std::string> colours = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e"};
  {
    const OptimalLapRun& first = *runs.front();
    std::vector<double> x, y;
    for (size_t k = 0; k < first.solution.distance.size(); ++k) {
      const Eigen::Vector3d p =
          track::PointAtOffset(track.At(first.solution.distance[k]), first.solution.n[k]);
      x.push_back(p[0]);
      y.push_back(p[1]);
    }
    page.AddHeading("Track");
    page.AddMapChart({.title = "Optimal line coloured by speed (" + labels.front() + ")",
                      .x_axis = {.label = "x", .unit = "m"},
                      .y_axis = {.label = "y", .unit = "m"},
                      .value_axis = {.label = "speed", .unit = "m/s"},
                      .x = x,
                      .y = y,
                      .value = first.solution.u});
  }
  page.AddHeading("Car");
  const auto chart = [&](const std::string& title, const std::string& label,
                         const std::string& unit,
                         const std::function<std::vector<double>(const LapSolution&)>& get,
                         report::ChartWidth width = report::ChartWidth::kCell) {
    report::LineChart c{.title = title,
                        .x_axis = {.label = "distance", .unit = "m"},
                        .y_axis = {.label = label, .unit = unit},
                        .x_link = "distance",
                        .width = width};
    for (size_t r = 0; r < runs.size(); ++r) {
      c.series.push_back({.label = labels[r],
                          .x = runs[r]->solution.distance,
                          .y = get(runs[r]->solution),
                          .colour = colours[r % colours.size()],
                          .style = style(r)});
    }
    page.AddLineChart(c);
  };
  chart(
      "Speed", "speed", "m/s", [](const LapSolution& s) { return s.u; },
      report::ChartWidth::kFullRow);
  chart("Drive power", "power", "kW",
        [](const LapSolution& s) { return Scaled(s.drive_power, 1e-3); });
  chart("Braking force", "brake force", "kN",
        [](const LapSolution& s) { return Scaled(s.brake_force, 1e-3); });
  chart("Lateral offset (left +)", "offset", "m", [](const LapSolution& s) { return s.n; });
  chart("Steer", "steer", "deg", [](const LapSolution& s) { return Scaled(s.steer, 180.0 / kPi); });
  chart("Pedal (drive +, brake -)", "pedal", "", [](const LapSolution& s) { return s.pedal; });
  // The paper's Figures 14 and 15: the front and the rear tyres apart, each run overlaid.
  page.AddHeading("Tyres and brakes");
  const std::vector<Corner> front = {Corner::kFrontLeft, Corner::kFrontRight};
  const std::vector<Corner> rear = {Corner::kRearLeft, Corner::kRearRight};
  const auto corner_chart = [&](const std::string& title, const std::string& label,
                                const std::string& unit, std::vector<double> CornerTrace::*field,
                                bool celsius, const std::vector<Corner>& corners) {
    report::LineChart c{.title = title,
                        .x_axis = {.label = "distance", .unit = "m"},
                        .y_axis = {.label = label, .unit = unit},
                        .x_link = "distance"};
    for (size_t r = 0; r < runs.size(); ++r) {
      for (Corner corner : corners) {
        std::vector<double> v = runs[r]->solution.corners[CornerIndex(corner)].*field;
        if (celsius) v = Celsius(v);
        c.series.push_back({.label = fmt::format("{} {}", CornerName(corner), labels[r]),
                            .x = runs[r]->solution.distance,
                            .y = std::move(v),
                            .corner = corner,
                            .style = style(r)});
      }
    }
    page.AddLineChart(c);
  };
  const std::vector<Corner> all(kAllCorners.begin(), kAllCorners.end());
  corner_chart("Front tread temperature", "tread", "\u00b0C", &CornerTrace::tread_temp, true,
               front);
  corner_chart("Rear tread temperature", "tread", "\u00b0C", &CornerTrace::tread_temp, true, rear);
  corner_chart("Front carcass temperature", "carcass", "\u00b0C", &CornerTrace::carcass_temp, true,
               front);
  corner_chart("Rear carcass temperature", "carcass", "\u00b0C", &CornerTrace::carcass_temp, true,
               rear);
  corner_chart("Front disc temperature", "disc", "\u00b0C", &CornerTrace::disc_temp, true, front);
  corner_chart("Rear disc temperature", "disc", "\u00b0C", &CornerTrace::disc_temp, true, rear);
  corner_chart("Wear", "wear", "mm", &CornerTrace::wear, false, all);
  corner_chart("Normal load", "Fz", "N", &CornerTrace::fz, false, all);
  corner_chart("Slip angle", "slip angle", "rad", &CornerTrace::slip_angle, false, all);
}

}  // namespace hotlap::ocp
