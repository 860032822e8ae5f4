#include "hotlap/ocp/optimal_lap_charts.h"

#include <cmath>

#include <fmt/format.h>

#include "hotlap/common/units.h"
#include "hotlap/ocp/channel_units.h"
#include "hotlap/track/track_point.h"

namespace hotlap::ocp {

using internal::Celsius;
using internal::Scaled;

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
