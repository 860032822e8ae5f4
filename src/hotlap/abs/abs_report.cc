#include "hotlap/abs/abs_report.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "hotlap/brake/abs_controller.h"
#include "hotlap/common/units.h"
#include "hotlap/report/html_report.h"

namespace hotlap::sim {

namespace {

std::vector<double> Scaled(const std::vector<double>& v, double scale, double shift = 0.0) {
  std::vector<double> out(v.size());
  for (size_t i = 0; i < v.size(); ++i) out[i] = v[i] * scale + shift;
  return out;
}

const char* kSurfaceColours[] = {"#4e79a7", "#f28e2b", "#59a14f", "#e15759",
                                 "#76b7b2", "#edc948", "#b07aa1", "#9c755f"};

std::string StateLegend() {
  std::string s;
  for (int k = 0; k <= 7; ++k) {
    if (k > 0) s += ", ";
    s += fmt::format("{} {}", k, brake::AbsStateName(static_cast<brake::AbsState>(k)));
  }
  return s;
}

void AddEventCharts(report::HtmlReport& page, const AbsRunResult& run, const AbsConfig& config,
                    bool with_abs) {
  const AbsHistory& h = run.history;
  const auto chart = [&](const char* title, const char* label, const char* unit) {
    return report::LineChart{.title = title,
                             .x_axis = {.label = "time", .unit = "s"},
                             .y_axis = {.label = label, .unit = unit},
                             .x_link = "time"};
  };
  report::LineChart pressure = chart("Brake pressure", "pressure", "MPa");
  pressure.series.push_back({.label = "driver",
                             .x = h.time,
                             .y = Scaled(h.driver_pressure, 1e-6),
                             .style = report::LineStyle::kDotted});
  pressure.series.push_back({.label = "target (delayed)",
                             .x = h.time,
                             .y = Scaled(h.pressure_target, 1e-6),
                             .style = report::LineStyle::kDashed});
  pressure.series.push_back(
      {.label = "wheel cylinder", .x = h.time, .y = Scaled(h.pressure, 1e-6)});
  page.AddLineChart(pressure);

  report::LineChart torque = chart("Brake torque", "torque", "N m");
  torque.series.push_back({.label = "brake torque", .x = h.time, .y = h.brake_torque});
  page.AddLineChart(torque);

  report::LineChart speeds = chart("Speeds", "speed", "m/s");
  speeds.series.push_back({.label = "Vx", .x = h.time, .y = h.speed});
  speeds.series.push_back(
      {.label = "omega R_l", .x = h.time, .y = Scaled(h.wheel_speed, config.plant.wheel.radius)});
  page.AddLineChart(speeds);

  report::LineChart slip = chart("Braking slip", "lambda", "");
  slip.series.push_back({.label = "lambda", .x = h.time, .y = h.lambda});
  slip.series.push_back({.label = "0.135 (002 Fig. 10)",
                         .x = {h.time.front(), h.time.back()},
                         .y = {kPaperSlipLimit, kPaperSlipLimit},
                         .colour = "#e15759",
                         .style = report::LineStyle::kDashed});
  page.AddLineChart(slip);

  report::LineChart fx = chart("Longitudinal tyre force", "Fx", "N");
  fx.series.push_back({.label = "Fx", .x = h.time, .y = h.fx});
  page.AddLineChart(fx);

  if (with_abs) {
    report::LineChart state = chart("Controller state", "state", "");
    state.y_axis.min = -0.5;
    state.y_axis.max = 7.5;
    std::vector<double> y(h.state.begin(), h.state.end());
    state.series.push_back({.label = "state", .x = h.time, .y = y});
    page.AddLineChart(state);
  }

  report::LineChart temps = chart("Brake temperatures", "temperature", "\u00b0C");
  temps.series.push_back(
      {.label = "disc surface", .x = h.time, .y = Scaled(h.disc_temp, 1.0, -kZeroCelsius)});
  temps.series.push_back({.label = "calliper",
                          .x = h.time,
                          .y = Scaled(h.calliper_temp, 1.0, -kZeroCelsius),
                          .style = report::LineStyle::kDashed});
  page.AddLineChart(temps);
}

void AddScenarios(report::HtmlReport& page, const std::vector<AbsComparisonRun>& runs,
                  const AbsStopSeries& series) {
  page.AddHeading("Scenarios: ABS against locked wheels");
  page.AddText(
      "Each surface braked from the same speed to standstill, with the ABS and with the driver's "
      "pressure alone (the wheel locks). Split: the friction changes along the road "
      "(docs/abs.md).");
  report::Table table{.title = "Stops to standstill",
                      .header = {"surface", "ABS m", "locked m", "ABS / locked", "ABS s",
                                 "locked s", "cycles/s", "max lambda", "wheel locked (ABS)"}};
  report::LineChart speed{.title = "Vx: ABS solid, locked dashed",
                          .x_axis = {.label = "time", .unit = "s"},
                          .y_axis = {.label = "Vx", .unit = "m/s"},
                          .x_link = "scenario",
                          .width = report::ChartWidth::kFullRow};
  for (size_t i = 0; i + 1 < runs.size(); i += 2) {
    const AbsComparisonRun& abs = runs[i];
    const AbsComparisonRun& locked = runs[i + 1];
    const auto metres = [](const AbsMetrics& m) {
      return m.stopping_distance_m ? fmt::format("{:.2f}", *m.stopping_distance_m)
                                   : std::string("not stopped");
    };
    const auto seconds = [](const AbsMetrics& m) {
      return m.stop_time_s ? fmt::format("{:.3f}", *m.stop_time_s) : std::string("-");
    };
    std::string ratio = "-";
    if (abs.metrics.stopping_distance_m && locked.metrics.stopping_distance_m) {
      ratio = fmt::format("{:.3f}",
                          *abs.metrics.stopping_distance_m / *locked.metrics.stopping_distance_m);
    }
    table.rows.push_back(
        {abs.surface, metres(abs.metrics), metres(locked.metrics), ratio, seconds(abs.metrics),
         seconds(locked.metrics), fmt::format("{:.2f}", abs.metrics.cycles_per_s),
         fmt::format("{:.3f}", abs.metrics.max_lambda), abs.metrics.wheel_locked ? "yes" : "no"});
    const std::string colour = kSurfaceColours[(i / 2) % 8];
    speed.series.push_back({.label = abs.surface + " ABS",
                            .x = abs.run.history.time,
                            .y = abs.run.history.speed,
                            .colour = colour});
    speed.series.push_back({.label = locked.surface + " locked",
                            .x = locked.run.history.time,
                            .y = locked.run.history.speed,
                            .colour = colour,
                            .style = report::LineStyle::kDashed});
  }
  page.AddTable(table);
  page.AddLineChart(speed);

  page.AddHeading("Scenarios: a series of stops");
  report::Table stops{.title = "Each stop",
                      .header = {"stop", "starts s", "stop m", "peak disc \u00b0C"}};
  for (size_t k = 0; k < series.stops.size(); ++k) {
    const AbsMetrics& m = series.stops[k];
    stops.rows.push_back({std::to_string(k + 1), fmt::format("{:.1f}", series.stop_start_s[k]),
                          m.stopping_distance_m ? fmt::format("{:.2f}", *m.stopping_distance_m)
                                                : std::string("not stopped"),
                          fmt::format("{:.1f}", KelvinToCelsius(m.peak_disc_temp_K))});
  }
  page.AddTable(stops);
  report::LineChart temps{.title = "Brake temperatures over the series",
                          .x_axis = {.label = "time", .unit = "s"},
                          .y_axis = {.label = "temperature", .unit = "\u00b0C"},
                          .x_link = "series",
                          .width = report::ChartWidth::kFullRow};
  temps.series.push_back({.label = "disc surface",
                          .x = series.time,
                          .y = Scaled(series.disc_temp, 1.0, -kZeroCelsius)});
  temps.series.push_back({.label = "calliper",
                          .x = series.time,
                          .y = Scaled(series.calliper_temp, 1.0, -kZeroCelsius),
                          .style = report::LineStyle::kDashed});
  page.AddLineChart(temps);
}

}  // namespace

void WriteAbsReport(const AbsReportInputs& in, const std::filesystem::path& path) {
  const AbsConfig& config = *in.config;
  const AbsEvent& event = *in.event;
  const bool with_abs = event.control == AbsControl::kAbs;
  report::HtmlReport page(fmt::format("hotlap abs: {} on '{}'{}", config.name, event.surface,
                                      with_abs ? "" : " without ABS"));
  page.AddMetadata("configuration", config.path.string());
  if (!config.overrides.empty()) {
    std::string set;
    for (const YamlOverride& o : config.overrides) {
      set += fmt::format("{}{}={}", set.empty() ? "" : ", ", o.field, o.value);
    }
    page.AddMetadata("overrides", set);
  }
  page.AddMetadata("tyre",
                   fmt::format("{} ({})", config.plant.tyre.name, config.plant.tyre.path.string()));
  page.AddMetadata("brake", fmt::format("{} ({})", config.brake.name, config.brake.path.string()));
  page.AddMetadata(
      "event",
      fmt::format("{:.3f} m/s, at most {:g} s, vehicle {}", event.initial_speed_mps,
                  event.duration_s,
                  event.vehicle == AbsVehicleMode::kFree ? "free (quarter car)" : "held (drum)"));
  page.AddMetadata("channels", in.csv);

  page.AddHeading("Summary");
  report::Table summary{.title = "", .header = {"figure", "value"}};
  for (const auto& [k, v] : in.summary) summary.rows.push_back({k, v});
  page.AddTable(summary);

  page.AddHeading("Braking event");
  if (with_abs) page.AddText("Controller states: " + StateLegend() + ".");
  AddEventCharts(page, *in.run, config, with_abs);
  if (in.comparison != nullptr && in.series != nullptr) {
    AddScenarios(page, *in.comparison, *in.series);
  }
  page.Write(path);
}

}  // namespace hotlap::sim
