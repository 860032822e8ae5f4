#include "hotlap/sim/replay_report.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "hotlap/common/json_output.h"
#include "hotlap/common/units.h"
#include "hotlap/report/html_report.h"

namespace hotlap::sim {

namespace {

nlohmann::json StatsJson(const HistoryStats& s, bool kelvin) {
  const double shift = kelvin ? kZeroCelsius : 0.0;
  return {{"peak", RoundSignificant(s.peak - shift)},
          {"mean", RoundSignificant(s.mean - shift)},
          {"final", RoundSignificant(s.final - shift)}};
}

}  // namespace

std::string TemperatureStatsText(const HistoryStats& s) {
  return fmt::format("{:.1f}/{:.1f}/{:.1f}", KelvinToCelsius(s.peak), KelvinToCelsius(s.mean),
                     KelvinToCelsius(s.final));
}

std::string ReplayHeatText(const ReplayResult& result,
                           const std::array<CornerReplaySummary, 4>& summaries) {
  if (summaries[0].gas.peak <= 0.0 && summaries[0].disc_bulk.peak <= 0.0) return "";
  std::string out = fmt::format("{:<6} {:>23} {:>23} {:>23} {:>23} {:>8} {:>8} {:>9} {:>9}\n",
                                "corner", "gas degC pk/mean/end", "rim degC", "hot kPa",
                                "disc bulk degC", "work kW", "heat kW", "heat/work", "closure");
  for (Corner c : kAllCorners) {
    const int k = CornerIndex(c);
    const CornerReplaySummary& s = summaries[k];
    const auto temps = [](const HistoryStats& h) {
      return h.peak > 0.0 ? TemperatureStatsText(h) : std::string("-");
    };
    const std::string kpa = s.pressure.peak > 0.0
                                ? fmt::format("{:.0f}/{:.0f}/{:.0f}", 1e-3 * s.pressure.peak,
                                              1e-3 * s.pressure.mean, 1e-3 * s.pressure.final)
                                : std::string("-");
    const CornerEnergyAudit& a = result.audits.front()[k];
    const double kw = a.duration_s > 0.0 ? 1e-3 / a.duration_s : 0.0;
    out += fmt::format("{:<6} {:>23} {:>23} {:>23} {:>23} {:>8.2f} {:>8.2f} {:>9.3f} {:>9.1e}\n",
                       CornerName(c), temps(s.gas), temps(s.rim), kpa, temps(s.disc_bulk),
                       kw * a.MechanicalWork(), kw * a.GeneratedHeat(), a.HeatOverWork(),
                       std::max({std::abs(a.TyreClosure()), std::abs(a.RimClosure()),
                                 std::abs(a.BrakeClosure())}));
  }
  return out;
}

nlohmann::json ReplayJson(const ReplayResult& result,
                          const std::array<CornerReplaySummary, 4>& summaries,
                          const std::string& telemetry, const vehicle::Car& car,
                          const std::string& out_csv) {
  nlohmann::json corners;
  for (Corner c : kAllCorners) {
    const CornerReplaySummary& s = summaries[CornerIndex(c)];
    corners[std::string(CornerName(c))] = {
        {"tread_temp_C", StatsJson(s.tread, true)},
        {"carcass_temp_C", StatsJson(s.carcass, true)},
        {"disc_temp_C", StatsJson(s.disc, true)},
        {"calliper_temp_C", StatsJson(s.calliper, true)},
        {"wear_mm", RoundSignificant(s.final_wear_mm)},
        {"min_grip_factor", RoundSignificant(s.min_grip_factor)},
        {"brake_energy_J", RoundSignificant(s.brake_energy_J)},
    };
    nlohmann::json& j = corners[std::string(CornerName(c))];
    if (s.gas.peak > 0.0) {
      j["gas_temp_C"] = StatsJson(s.gas, true);
      j["rim_temp_C"] = StatsJson(s.rim, true);
      j["pressure_kPa"] = {{"peak", RoundSignificant(1e-3 * s.pressure.peak)},
                           {"mean", RoundSignificant(1e-3 * s.pressure.mean)},
                           {"final", RoundSignificant(1e-3 * s.pressure.final)}};
    }
    if (s.disc_bulk.peak > 0.0) j["disc_bulk_temp_C"] = StatsJson(s.disc_bulk, true);
    // The whole log's audit (the stretches of a replay with audit starts are the library's).
    if (!result.audits.empty())
      j["energy_audit"] = AuditJson(result.audits.front()[CornerIndex(c)]);
  }
  return {
      {"command", "replay"},
      {"telemetry", telemetry},
      {"car", car.name},
      {"overrides", vehicle::OverridesJson(car.overrides)},
      {"out", out_csv},
      {"samples", result.time.size()},
      {"duration_s", RoundSignificant(result.time.back() - result.time.front())},
      {"corners", corners},
  };
}

void WriteReplayReport(const std::filesystem::path& path, const std::string& telemetry,
                       const std::string& out_csv, const vehicle::Car& car,
                       const std::vector<std::pair<std::string, std::string>>& log_metadata,
                       const ReplayResult& result,
                       const std::array<CornerReplaySummary, 4>& summaries) {
  std::vector<std::vector<std::string>> rows;
  for (Corner c : kAllCorners) {
    const CornerReplaySummary& s = summaries[CornerIndex(c)];
    rows.push_back({std::string(CornerName(c)), TemperatureStatsText(s.tread),
                    TemperatureStatsText(s.carcass), TemperatureStatsText(s.disc),
                    TemperatureStatsText(s.calliper), fmt::format("{:.4f}", s.final_wear_mm),
                    fmt::format("{:.3f}", s.min_grip_factor),
                    fmt::format("{:.1f}", s.brake_energy_J / 1e3)});
  }
  report::HtmlReport page("hotlap replay: " + std::filesystem::path(telemetry).filename().string());
  page.AddMetadata("telemetry", telemetry);
  page.AddMetadata("car", car.name + " (" + car.path.string() + ")");
  if (!car.overrides.empty()) page.AddMetadata("overrides", vehicle::OverridesText(car.overrides));
  page.AddMetadata("samples", std::to_string(result.time.size()));
  page.AddMetadata("duration", fmt::format("{:.2f} s", result.time.back() - result.time.front()));
  for (const auto& [key, value] : log_metadata) page.AddMetadata("log " + key, value);
  page.AddMetadata("channels", out_csv);

  page.AddHeading("Summary");
  page.AddTable({.title = "Per corner: peak / time-weighted mean / final",
                 .header = {"corner", "tread \u00b0C", "carcass \u00b0C", "disc \u00b0C",
                            "calliper \u00b0C", "wear mm", "min grip", "brake energy kJ"},
                 .rows = rows});

  // One chart per quantity, the four corners in their fixed colours, all on one linked time axis.
  const auto chart = [&](const char* title, const char* label, const char* unit,
                         std::vector<double> CornerHistory::*channel, double scale, double shift) {
    report::LineChart c{.title = title,
                        .x_axis = {.label = "time", .unit = "s"},
                        .y_axis = {.label = label, .unit = unit},
                        .x_link = "time"};
    for (Corner corner : kAllCorners) {
      std::vector<double> y = result.corners[CornerIndex(corner)].*channel;
      for (double& v : y) v = v * scale + shift;
      c.series.push_back({.label = std::string(CornerName(corner)),
                          .x = result.time,
                          .y = std::move(y),
                          .corner = corner});
    }
    page.AddLineChart(c);
  };
  page.AddHeading("Tyres");
  chart("Tread temperature", "tread", "\u00b0C", &CornerHistory::tread_temp, 1.0, -kZeroCelsius);
  chart("Carcass temperature", "carcass", "\u00b0C", &CornerHistory::carcass_temp, 1.0,
        -kZeroCelsius);
  chart("Wear", "wear", "mm", &CornerHistory::wear, 1.0, 0.0);
  chart("Grip factor", "grip factor", "", &CornerHistory::grip_factor, 1.0, 0.0);
  page.AddHeading("Brakes");
  chart("Disc temperature", "disc", "\u00b0C", &CornerHistory::disc_temp, 1.0, -kZeroCelsius);
  chart("Calliper temperature", "calliper", "\u00b0C", &CornerHistory::calliper_temp, 1.0,
        -kZeroCelsius);
  chart("Braking power", "braking power", "kW", &CornerHistory::brake_power, 1e-3, 0.0);
  page.Write(path);
}

}  // namespace hotlap::sim
