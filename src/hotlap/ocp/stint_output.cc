#include "hotlap/ocp/stint_output.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "hotlap/common/csv.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/units.h"
#include "hotlap/ocp/optimal_output.h"
#include "hotlap/report/html_report.h"

namespace hotlap::ocp {
namespace {

namespace fs = std::filesystem;

nlohmann::json LapJson(const StintLap& l) {
  nlohmann::json corners;
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    corners[std::string(CornerName(c))] = {
        {"peak_tread_temp_C", RoundSignificant(KelvinToCelsius(l.peak_tread_temp_K[i]))},
        {"peak_carcass_temp_C", RoundSignificant(KelvinToCelsius(l.peak_carcass_temp_K[i]))},
        {"peak_disc_temp_C", RoundSignificant(KelvinToCelsius(l.peak_disc_temp_K[i]))},
        {"min_tread_temp_C", RoundSignificant(KelvinToCelsius(l.min_tread_temp_K[i]))},
        {"min_carcass_temp_C", RoundSignificant(KelvinToCelsius(l.min_carcass_temp_K[i]))},
        {"min_disc_temp_C", RoundSignificant(KelvinToCelsius(l.min_disc_temp_K[i]))},
        {"wear_mm", RoundSignificant(l.wear_end_mm[i])}};
    nlohmann::json& j = corners[std::string(CornerName(c))];
    if (l.end_pressure_Pa[i] != 0.0) {
      j["mean_gas_temp_C"] = RoundSignificant(KelvinToCelsius(l.mean_gas_temp_K[i]));
      j["end_pressure_kPa"] = RoundSignificant(1e-3 * l.end_pressure_Pa[i]);
    }
    if (l.has_audit) j["energy_audit"] = sim::AuditJson(l.audit[i]);
  }
  return {{"lap", l.lap},
          {"lap_time_s", RoundSignificant(l.time_s)},
          {"top_speed_mps", RoundSignificant(l.top_speed_mps)},
          {"mass_kg", RoundSignificant(l.mass_kg)},
          {"fuel_burnt_kg", RoundSignificant(l.fuel_burnt_kg)},
          {"fuel_end_kg", RoundSignificant(l.fuel_end_kg)},
          {"corners", corners}};
}

std::string Status(const StintResult& r) { return r.ok() ? "converged" : "failed"; }

}  // namespace

sim::ColumnSet StintColumns(const StintResult& result, const track::Track& track) {
  const track::Track stint_track = track.Repeated(static_cast<int>(result.laps.size()));
  sim::ColumnSet columns = OptimalLapColumns(result.run, stint_track);
  const auto at = std::find(columns.names.begin(), columns.names.end(), "distance_m");
  const size_t d = static_cast<size_t>(at - columns.names.begin());
  std::vector<double> lap, lap_distance;
  const double length = track.length_m();
  const int laps = static_cast<int>(result.laps.size());
  for (double s : columns.values.at(d)) {
    const int i = std::clamp(static_cast<int>(std::floor(s / length + 1e-9)), 0, laps - 1);
    lap.push_back(i + 1);
    lap_distance.push_back(s - i * length);
  }
  columns.names.insert(columns.names.begin() + d + 1, {"lap", "lap_distance_m"});
  columns.values.insert(columns.values.begin() + d + 1, {lap, lap_distance});
  return columns;
}

namespace {

// Gas-and-rim tyres: each lap's hot pressures and gas temperatures, and each tyre's heat over the
// car's work on it with the worst balance of the lap's audit (empty for the paper's tyres).
std::string StintHeatText(const StintResult& r) {
  if (r.laps.empty() || r.laps.front().end_pressure_Pa[0] == 0.0) return "";
  std::string t =
      fmt::format("{:>4} {:>27} {:>23} {:>23} {:>9}\n", "lap", "hot pressure psi fl..rr",
                  "mean gas degC", "tyre heat / work", "balance");
  for (const StintLap& l : r.laps) {
    std::string psi, gas, ratio;
    double worst = 0.0;
    for (int c = 0; c < 4; ++c) {
      psi += fmt::format(" {:6.1f}", l.end_pressure_Pa[c] / kPsi);
      gas += fmt::format(" {:5.0f}", KelvinToCelsius(l.mean_gas_temp_K[c]));
      ratio += fmt::format(" {:5.2f}", l.has_audit ? l.audit[c].HeatOverWork() : std::nan(""));
      for (double closure :
           {l.audit[c].TyreClosure(), l.audit[c].RimClosure(), l.audit[c].BrakeClosure()}) {
        worst = std::max(worst, std::abs(closure));
      }
    }
    t += fmt::format("{:>4} {:>27} {:>23} {:>23} {:>9.1e}\n", l.lap, psi, gas, ratio, worst);
  }
  return t;
}

}  // namespace

std::string StintText(const StintResult& r) {
  std::string t = fmt::format("{:>4} {:>9} {:>9} {:>7} {:>23} {:>23} {:>23} {:>31} {:>6}\n", "lap",
                              "time s", "greedy s", "top m/s", "tread peak degC fl..rr",
                              "carcass peak degC", "disc peak degC", "wear mm fl..rr", "fuel kg");
  for (size_t i = 0; i < r.laps.size(); ++i) {
    const StintLap& l = r.laps[i];
    const auto four = [](const std::array<double, 4>& v, bool kelvin, const char* format) {
      std::string s;
      for (double x : v) {
        s += fmt::format(fmt::runtime(format), kelvin ? KelvinToCelsius(x) : x);
      }
      return s;
    };
    t += fmt::format(
        "{:>4} {:>9.3f} {:>9.3f} {:>7.2f} {:>23} {:>23} {:>23} {:>31} {:>7.2f}\n", l.lap, l.time_s,
        i < r.greedy_laps.size() ? r.greedy_laps[i].time_s : std::nan(""), l.top_speed_mps,
        four(l.peak_tread_temp_K, true, " {:5.0f}"), four(l.peak_carcass_temp_K, true, " {:5.0f}"),
        four(l.peak_disc_temp_K, true, " {:5.0f}"), four(l.wear_end_mm, false, " {:7.4f}"),
        l.fuel_end_kg);
  }
  t += fmt::format(
      "total {:.3f} s as one problem, {:.3f} s greedy (lap by lap): managing the stint gains "
      "{:.3f} s\n",
      r.total_time_s, r.greedy_total_time_s, r.greedy_total_time_s - r.total_time_s);
  t += StintHeatText(r);
  return t;
}

nlohmann::json StintJson(const StintResult& r, const StintOptions& o, const std::string& track_name,
                         const vehicle::Car& car, double wall_time_s) {
  nlohmann::json laps = nlohmann::json::array(), greedy = nlohmann::json::array();
  for (const StintLap& l : r.laps) laps.push_back(LapJson(l));
  for (const StintLap& l : r.greedy_laps) greedy.push_back(LapJson(l));
  const SolveResult& s = r.run.solution.solve;
  return {
      {"command", "stint"},
      {"track", track_name},
      {"car", car.name},
      {"overrides", vehicle::OverridesJson(car.overrides)},
      {"laps_count", o.laps},
      {"wear_scale", o.wear_scale},
      {"fuel_kg", o.fuel_kg},
      {"bsfc_g_per_kWh", RoundSignificant(o.bsfc_kg_per_J * 3.6e9)},
      {"front_disc_limit_C", o.lap.front_disc_limit
                                 ? nlohmann::json(KelvinToCelsius(*o.lap.front_disc_limit))
                                 : nlohmann::json()},
      {"mesh_step_m", RoundSignificant(r.run.solution.distance.size() > 1
                                           ? r.run.solution.distance[1] - r.run.solution.distance[0]
                                           : 0.0)},
      {"laps", laps},
      {"greedy_laps", greedy},
      {"total_time_s", RoundSignificant(r.total_time_s)},
      {"greedy_total_time_s", RoundSignificant(r.greedy_total_time_s)},
      {"managing_gain_s", RoundSignificant(r.greedy_total_time_s - r.total_time_s)},
      {"fuel_plan_error_kg", RoundSignificant(r.fuel_plan_error_kg)},
      {"solve_time_s", RoundSignificant(r.solve_time_s)},
      {"greedy_solve_time_s", RoundSignificant(r.greedy_solve_time_s)},
      {"ipopt_iterations", r.ipopt_iterations},
      {"greedy_laps_resumed", r.greedy_laps_resumed},
      {"resumed_from_iteration", r.resumed_from_iteration},
      {"status", Status(r)},
      {"message", s.message},
      {"constraint_violation", RoundSignificant(s.primal_infeasibility)},
      {"variables", r.run.solution.variables},
      {"constraints", r.run.solution.constraints},
      {"wall_time_s", RoundSignificant(wall_time_s)}};
}

namespace {

void WriteStintCsv(const fs::path& csv, const sim::ColumnSet& columns, const StintResult& r,
                   const StintOptions& o, const vehicle::Car& car, const track::Track& track) {
  std::vector<std::pair<std::string, std::string>> metadata = {
      {"source", fmt::format("hotlap {} stint", HOTLAP_VERSION)},
      {"track", track.name()},
      {"car", car.path.string()},
      {"laps", std::to_string(o.laps)},
      {"wear_scale", fmt::format("{:g}", o.wear_scale)},
      {"fuel_kg", fmt::format("{:g}", o.fuel_kg)},
      {"status", r.run.solution.solve.message}};
  if (!car.overrides.empty()) {
    metadata.emplace_back("overrides", vehicle::OverridesText(car.overrides));
  }
  WriteCsv(csv, metadata, columns.names, columns.values);
}

// The page's metadata, the laps' table and what managing the stint gains.
void AddStintSummary(report::HtmlReport& page, const StintResult& r, const StintOptions& o,
                     const vehicle::Car& car, const track::Track& track) {
  page.AddMetadata("car", car.path.string());
  page.AddMetadata("track", fmt::format("{} ({:.1f} m a lap)", track.name(), track.length_m()));
  page.AddMetadata("wear", fmt::format("rate x {:g} (accelerated wear)", o.wear_scale));
  page.AddMetadata("fuel", o.fuel_kg > 0.0 ? fmt::format("{:g} kg at the start, {:g} g/kWh",
                                                         o.fuel_kg, o.bsfc_kg_per_J * 3.6e9)
                                           : std::string("not burnt (mass constant)"));
  page.AddMetadata("solver", fmt::format("{} after {} iterations, {:.1f} s (greedy laps {:.1f} s)",
                                         r.run.solution.solve.message, r.ipopt_iterations,
                                         r.solve_time_s, r.greedy_solve_time_s));
  page.AddMetadata("version", HOTLAP_VERSION);
  page.AddHeading("Laps");
  report::Table table{.title = "",
                      .header = {"lap", "time, s", "greedy, s", "top speed, m/s",
                                 "peak disc fl, degC", "wear fl, mm", "fuel, kg"}};
  for (size_t i = 0; i < r.laps.size(); ++i) {
    const StintLap& l = r.laps[i];
    table.rows.push_back(
        {std::to_string(l.lap), fmt::format("{:.3f}", l.time_s),
         fmt::format("{:.3f}", r.greedy_laps.at(i).time_s), fmt::format("{:.2f}", l.top_speed_mps),
         fmt::format("{:.1f}", KelvinToCelsius(l.peak_disc_temp_K[0])),
         fmt::format("{:.4f}", l.wear_end_mm[0]), fmt::format("{:.2f}", l.fuel_end_kg)});
  }
  table.rows.push_back({"total", fmt::format("{:.3f}", r.total_time_s),
                        fmt::format("{:.3f}", r.greedy_total_time_s), "", "", "", ""});
  page.AddTable(table);
  page.AddText(fmt::format(
      "The stint solved as one problem looks ahead: it may give time early to have tyres and "
      "brakes for later. The greedy driver solves each lap on its own from where the last one "
      "left the car. Managing the stint gains {:.3f} s over {} laps.",
      r.greedy_total_time_s - r.total_time_s, o.laps));
}

template <class Field>
std::vector<double> PerLap(const std::vector<StintLap>& laps, Field field) {
  std::vector<double> y;
  for (const StintLap& l : laps) y.push_back(field(l));
  return y;
}

// A figure of each corner, lap by lap.
template <class Field>
void AddCornerChart(report::HtmlReport& page, const std::vector<StintLap>& laps,
                    const std::vector<double>& lap_numbers, const char* title, const char* quantity,
                    const char* unit, Field field) {
  report::LineChart chart{.title = title,
                          .x_axis = {.label = "lap", .integer_ticks = true},
                          .y_axis = {quantity, unit}};
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    chart.series.push_back({.label = std::string(CornerName(c)),
                            .x = lap_numbers,
                            .y = PerLap(laps, [&](const StintLap& l) { return field(l, i); }),
                            .corner = c});
  }
  page.AddLineChart(chart);
}

// Each corner's lowest (dashed) and highest (solid) temperature over each lap: the window it
// works in, lap by lap.
template <class Low, class High>
void AddEnvelopeChart(report::HtmlReport& page, const std::vector<StintLap>& laps,
                      const std::vector<double>& lap_numbers, const char* title,
                      const char* quantity, Low low, High high) {
  report::LineChart chart{.title = title,
                          .x_axis = {.label = "lap", .integer_ticks = true},
                          .y_axis = {quantity, "degC"}};
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    const std::string name(CornerName(c));
    chart.series.push_back(
        {.label = name + " highest",
         .x = lap_numbers,
         .y = PerLap(laps, [&](const StintLap& l) { return KelvinToCelsius(high(l)[i]); }),
         .corner = c});
    chart.series.push_back(
        {.label = name + " lowest",
         .x = lap_numbers,
         .y = PerLap(laps, [&](const StintLap& l) { return KelvinToCelsius(low(l)[i]); }),
         .corner = c,
         .style = report::LineStyle::kDashed});
  }
  page.AddLineChart(chart);
}

// Lap by lap: the lap times (stint and greedy), each corner's temperature windows and wear.
void AddLapCharts(report::HtmlReport& page, const StintResult& r) {
  std::vector<double> lap_numbers;
  for (const StintLap& l : r.laps) lap_numbers.push_back(l.lap);
  report::LineChart times{.title = "Lap time, lap by lap",
                          .x_axis = {.label = "lap", .integer_ticks = true},
                          .y_axis = {"lap time", "s"}};
  times.series.push_back({.label = "stint (one problem)",
                          .x = lap_numbers,
                          .y = PerLap(r.laps, [](const StintLap& l) { return l.time_s; })});
  times.series.push_back({.label = "greedy (lap by lap)",
                          .x = lap_numbers,
                          .y = PerLap(r.greedy_laps, [](const StintLap& l) { return l.time_s; }),
                          .style = report::LineStyle::kDashed});
  page.AddLineChart(times);
  AddEnvelopeChart(
      page, r.laps, lap_numbers, "Tread temperature per lap, lowest and highest", "tread",
      [](const StintLap& l) { return l.min_tread_temp_K; },
      [](const StintLap& l) { return l.peak_tread_temp_K; });
  AddEnvelopeChart(
      page, r.laps, lap_numbers, "Carcass temperature per lap, lowest and highest", "carcass",
      [](const StintLap& l) { return l.min_carcass_temp_K; },
      [](const StintLap& l) { return l.peak_carcass_temp_K; });
  AddEnvelopeChart(
      page, r.laps, lap_numbers, "Disc temperature per lap, lowest and highest", "disc",
      [](const StintLap& l) { return l.min_disc_temp_K; },
      [](const StintLap& l) { return l.peak_disc_temp_K; });
  AddCornerChart(page, r.laps, lap_numbers, "Cumulative wear", "wear", "mm",
                 [](const StintLap& l, int i) { return l.wear_end_mm[i]; });
}

// The channels over the stint: speed and the carcass temperatures.
void AddChannelCharts(report::HtmlReport& page, const sim::ColumnSet& columns) {
  const auto column = [&](const char* name) -> const std::vector<double>& {
    const auto it = std::find(columns.names.begin(), columns.names.end(), name);
    return columns.values.at(static_cast<size_t>(it - columns.names.begin()));
  };
  const std::vector<double>& d = column("distance_m");
  report::LineChart speed{.title = "Speed over the stint",
                          .x_axis = {"distance", "m"},
                          .y_axis = {"speed", "m/s"},
                          .x_link = "stint",
                          .width = report::ChartWidth::kFullRow};
  speed.series.push_back({.label = "speed", .x = d, .y = column("speed_mps")});
  page.AddLineChart(speed);
  report::LineChart temps{.title = "Temperatures over the stint",
                          .x_axis = {"distance", "m"},
                          .y_axis = {"temperature", "degC"},
                          .x_link = "stint",
                          .width = report::ChartWidth::kFullRow};
  for (Corner c : kAllCorners) {
    const std::string n(CornerName(c));
    temps.series.push_back({.label = "carcass " + n,
                            .x = d,
                            .y = column(("carcass_temp_" + n + "_C").c_str()),
                            .corner = c});
  }
  page.AddLineChart(temps);
}

}  // namespace

std::vector<fs::path> WriteStintFiles(const fs::path& out, const StintResult& r,
                                      const StintOptions& o, const vehicle::Car& car,
                                      const track::Track& track) {
  fs::create_directories(out);
  const fs::path csv = out / "stint.csv", html = out / "stint.html";
  const sim::ColumnSet columns = StintColumns(r, track);
  WriteStintCsv(csv, columns, r, o, car, track);
  report::HtmlReport page(
      fmt::format("hotlap stint: {} laps of {} with {}", o.laps, track.name(), car.name));
  AddStintSummary(page, r, o, car, track);
  AddLapCharts(page, r);
  AddChannelCharts(page, columns);
  page.Write(html);
  return {csv, html};
}

}  // namespace hotlap::ocp
