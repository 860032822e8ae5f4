#include "hotlap/sim/lap_report.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "hotlap/common/units.h"
#include "hotlap/report/html_report.h"

namespace hotlap::sim {

namespace {

// Lap by lap: each corner's lap means (do the temperatures and pressures settle?) and the last
// lap's energy audit (docs/lap-simulation.md, "Heat over a run").
void AddRunSettling(report::HtmlReport& page, const StintSummary& stint) {
  page.AddHeading("Heat over the run");
  std::vector<double> lap_numbers;
  for (size_t l = 0; l < stint.laps.size(); ++l) lap_numbers.push_back(static_cast<double>(l + 1));
  const auto per_lap = [&](const char* title, const char* label, const char* unit,
                           double CornerLapMeans::*member, double scale, double offset) {
    report::LineChart chart{.title = title,
                            .x_axis = {.label = "lap", .unit = ""},
                            .y_axis = {.label = label, .unit = unit}};
    for (Corner c : kAllCorners) {
      std::vector<double> y;
      for (const LapFigures& f : stint.laps) {
        y.push_back(scale * (f.means[CornerIndex(c)].*member) + offset);
      }
      chart.series.push_back(
          {.label = std::string(CornerName(c)), .x = lap_numbers, .y = y, .corner = c});
    }
    page.AddLineChart(chart);
  };
  per_lap("Lap mean tread temperature", "tread", "\u00b0C", &CornerLapMeans::tread, 1.0,
          -kZeroCelsius);
  per_lap("Lap mean carcass temperature", "carcass", "\u00b0C", &CornerLapMeans::carcass, 1.0,
          -kZeroCelsius);
  const LapFigures& last = stint.laps.back();
  if (last.means[0].gas > 0.0) {
    per_lap("Lap mean gas temperature", "gas", "\u00b0C", &CornerLapMeans::gas, 1.0, -kZeroCelsius);
    per_lap("Lap mean hot pressure (gauge)", "pressure", "psi", &CornerLapMeans::pressure,
            1.0 / kPsi, 0.0);
    per_lap("Rolling circumference at the lap's hot pressure", "rollout", "mm",
            &CornerLapMeans::rolling_radius, 2e3 * kPi, 0.0);
  }
  if (last.means[0].disc_bulk > 0.0) {
    per_lap("Lap mean disc bulk temperature", "disc bulk", "\u00b0C", &CornerLapMeans::disc_bulk,
            1.0, -kZeroCelsius);
  }
  std::vector<std::vector<std::string>> rows;
  for (Corner c : kAllCorners) {
    const CornerEnergyAudit& a = last.audit[CornerIndex(c)];
    const double kw = a.duration_s > 0.0 ? 1e-3 / a.duration_s : 0.0;
    const TyreEnergies& t = a.tyre;
    rows.push_back(
        {std::string(CornerName(c)), fmt::format("{:.2f}", kw * t[kSlidingWork]),
         fmt::format("{:.2f}", kw * t[kRollingWork]), fmt::format("{:.2f}", kw * t[kTreadHeat]),
         fmt::format("{:.2f}", kw * t[kCarcassHeat]), fmt::format("{:.3f}", a.HeatOverWork()),
         fmt::format("{:.2f}", kw * (t[kTreadConvection] + t[kTreadRadiation])),
         fmt::format("{:.2f}", kw * t[kTrackConduction]),
         fmt::format("{:.2f}", kw * (t[kSidewallConvection] + t[kSidewallRadiation])),
         fmt::format("{:.2f}", kw * t[kCarcassToGas]), fmt::format("{:.2f}", kw * t[kBrakeToRim]),
         fmt::format("{:.2f}", kw * a.brake[kBrakeWork]),
         fmt::format("{:.1e}", std::max({std::abs(a.TyreClosure()), std::abs(a.RimClosure()),
                                         std::abs(a.BrakeClosure())}))});
  }
  page.AddTable(
      {.title = fmt::format("Energy audit of lap {} (mean kW; docs/models.md)", stint.laps.size()),
       .header = {"corner", "sliding work", "rolling work", "tread heat Q1", "carcass heat Q2",
                  "heat / work", "tread to air", "to track", "sidewalls to air",
                  "carcass to gas and rim", "brake to rim", "brake work", "largest closure"},
       .rows = rows});
}

}  // namespace

void WriteLapReport(const std::filesystem::path& path, const LapReportSettings& a,
                    const vehicle::Car& car, const track::Track& track, const ColumnSet& columns,
                    const StintSummary& stint) {
  std::vector<std::vector<std::string>> lap_rows, corner_rows;
  for (size_t l = 0; l < stint.laps.size(); ++l) {
    const LapFigures& f = stint.laps[l];
    lap_rows.push_back({std::to_string(l + 1), fmt::format("{:.3f}", f.lap_time_s),
                        fmt::format("{:.2f}", f.top_speed), fmt::format("{:.2f}", f.min_speed)});
  }
  for (Corner c : kAllCorners) {
    const StintCorner& s = stint.corners[CornerIndex(c)];
    corner_rows.push_back({std::string(CornerName(c)),
                           fmt::format("{:.1f}", KelvinToCelsius(s.peak_tread_temp)),
                           fmt::format("{:.1f}", KelvinToCelsius(s.peak_carcass_temp)),
                           fmt::format("{:.1f}", KelvinToCelsius(s.peak_disc_temp)),
                           fmt::format("{:.1f}", KelvinToCelsius(s.peak_calliper_temp)),
                           fmt::format("{:.5f}", s.wear_per_lap_mm)});
  }
  report::HtmlReport page(fmt::format("hotlap lap: {} on {}", car.name, track.name()));
  page.AddMetadata("method", "quasi-steady-state (docs/lap-simulation.md)");
  page.AddMetadata("line", a.line);
  page.AddMetadata("car", car.path.string());
  if (!car.overrides.empty()) page.AddMetadata("overrides", vehicle::OverridesText(car.overrides));
  page.AddMetadata("track", fmt::format("{} ({:.1f} m)", track.name(), track.length_m()));
  page.AddMetadata("laps", std::to_string(a.laps));
  page.AddMetadata("air / track", fmt::format("{:g} / {:g} \u00b0C", a.ambient_C, a.track_C));
  page.AddMetadata("version", HOTLAP_VERSION);
  page.AddHeading("Summary");
  page.AddTable(
      {.title = "Laps", .header = {"lap", "time s", "top m/s", "min m/s"}, .rows = lap_rows});
  page.AddTable({.title = "Per corner over the stint: peak temperatures and wear",
                 .header = {"corner", "tread \u00b0C", "carcass \u00b0C", "disc \u00b0C",
                            "calliper \u00b0C", "wear mm/lap"},
                 .rows = corner_rows});
  std::vector<std::vector<std::string>> zone_rows;
  for (const BrakingZone& z : stint.braking_zones) {
    zone_rows.push_back({std::to_string(z.lap), fmt::format("{:.0f}", z.start_m),
                         fmt::format("{:.0f}", z.end_m), fmt::format("{:.1f}", z.entry_speed),
                         fmt::format("{:.1f}", z.exit_speed), fmt::format("{:.2f}", z.peak_decel)});
  }
  page.AddTable(
      {.title = "Braking zones",
       .header = {"lap", "from m", "to m", "entry m/s", "exit m/s", "peak decel m/s\u00b2"},
       .rows = zone_rows});

  const auto col = [&](const std::string& name) -> const std::vector<double>& {
    const auto it = std::find(columns.names.begin(), columns.names.end(), name);
    return columns.values[static_cast<size_t>(it - columns.names.begin())];
  };
  const std::vector<double>& distance = col("distance_m");
  page.AddHeading("Track");
  page.AddMapChart({.title = "Track map coloured by speed",
                    .x_axis = {.label = "x", .unit = "m"},
                    .y_axis = {.label = "y", .unit = "m"},
                    .value_axis = {.label = "speed", .unit = "m/s"},
                    .x = col("x_m"),
                    .y = col("y_m"),
                    .value = col("speed_mps")});
  page.AddHeading("Car");
  page.AddLineChart({.title = "Speed",
                     .x_axis = {.label = "distance", .unit = "m"},
                     .y_axis = {.label = "speed", .unit = "m/s"},
                     .series = {{.label = "speed", .x = distance, .y = col("speed_mps")}},
                     .x_link = "distance",
                     .width = report::ChartWidth::kFullRow});
  page.AddLineChart(
      {.title = "Accelerations",
       .x_axis = {.label = "distance", .unit = "m"},
       .y_axis = {.label = "acceleration", .unit = "m/s\u00b2"},
       .series = {{.label = "longitudinal", .x = distance, .y = col("accel_long_mps2")},
                  {.label = "lateral (in the road plane)",
                   .x = distance,
                   .y = col("accel_lat_mps2")}},
       .x_link = "distance"});
  const auto corners_chart = [&](const char* title, const char* label, const char* unit,
                                 const char* pattern) {
    report::LineChart c{.title = title,
                        .x_axis = {.label = "distance", .unit = "m"},
                        .y_axis = {.label = label, .unit = unit},
                        .x_link = "distance"};
    for (Corner corner : kAllCorners) {
      c.series.push_back({.label = std::string(CornerName(corner)),
                          .x = distance,
                          .y = col(fmt::format(fmt::runtime(pattern), CornerName(corner))),
                          .corner = corner});
    }
    page.AddLineChart(c);
  };
  corners_chart("Normal loads", "Fz", "N", "fz_{}_N");
  page.AddHeading("Tyres");
  corners_chart("Tread temperature", "tread", "\u00b0C", "tread_temp_{}_C");
  corners_chart("Carcass temperature", "carcass", "\u00b0C", "carcass_temp_{}_C");
  corners_chart("Wear", "wear", "mm", "wear_{}_mm");
  corners_chart("Grip factor g(T) h(wear)", "grip factor", "", "grip_factor_{}");
  corners_chart("Slip angle", "slip angle", "deg", "slip_angle_{}_deg");
  corners_chart("Slip ratio", "slip ratio", "", "slip_ratio_{}");
  const auto has = [&](const std::string& name) {
    return std::find(columns.names.begin(), columns.names.end(), name) != columns.names.end();
  };
  if (has("gas_temp_fl_C")) {
    corners_chart("Inflation gas temperature", "gas", "\u00b0C", "gas_temp_{}_C");
    corners_chart("Hot pressure (gauge)", "pressure", "kPa", "pressure_{}_kPa");
    corners_chart("Rim temperature", "rim", "\u00b0C", "rim_temp_{}_C");
  }
  AddRunSettling(page, stint);
  page.AddHeading("Brakes");
  corners_chart("Disc temperature", "disc", "\u00b0C", "disc_temp_{}_C");
  if (has("disc_bulk_temp_fl_C")) {
    corners_chart("Disc bulk temperature", "disc bulk", "\u00b0C", "disc_bulk_temp_{}_C");
  }
  corners_chart("Calliper temperature", "calliper", "\u00b0C", "calliper_temp_{}_C");
  corners_chart("Braking power", "braking power", "W", "brake_power_{}_W");
  page.Write(path);
}

}  // namespace hotlap::sim
