#include "hotlap/abs/abs_output.h"

#include <limits>
#include <optional>

#include <fmt/format.h>

#include "hotlap/common/csv.h"
#include "hotlap/common/units.h"

namespace hotlap::sim {

namespace {

std::string Figure(const std::optional<double>& x, const char* format) {
  return x ? fmt::format(fmt::runtime(format), *x) : std::string("-");
}

}  // namespace

void WriteAbsCsv(const std::filesystem::path& path, const AbsConfig& config, const AbsEvent& event,
                 const AbsRunResult& run) {
  const AbsHistory& h = run.history;
  const auto scaled = [](const std::vector<double>& v, double k, double shift = 0.0) {
    std::vector<double> out(v.size());
    for (size_t i = 0; i < v.size(); ++i) out[i] = v[i] * k + shift;
    return out;
  };
  std::vector<double> state(h.size()), locked(h.size());
  for (size_t i = 0; i < h.size(); ++i) {
    state[i] = h.state[i] < 0 ? std::numeric_limits<double>::quiet_NaN() : h.state[i];
    locked[i] = h.locked[i];
  }
  const std::vector<std::string> names = {
      "time_s",         "distance_m",      "driver_pressure_MPa", "pressure_target_MPa",
      "pressure_MPa",   "brake_torque_Nm", "speed_mps",           "wheel_speed_mps",
      "omega_radps",    "lambda",          "slip_ratio",          "fx_N",
      "road_friction",  "abs_state",       "wheel_locked",        "disc_temp_C",
      "calliper_temp_C"};
  const std::vector<std::vector<double>> values = {h.time,
                                                   h.distance,
                                                   scaled(h.driver_pressure, 1e-6),
                                                   scaled(h.pressure_target, 1e-6),
                                                   scaled(h.pressure, 1e-6),
                                                   h.brake_torque,
                                                   h.speed,
                                                   scaled(h.wheel_speed, config.plant.wheel.radius),
                                                   h.wheel_speed,
                                                   h.lambda,
                                                   h.transient_slip,
                                                   h.fx,
                                                   h.friction,
                                                   state,
                                                   locked,
                                                   scaled(h.disc_temp, 1.0, -kZeroCelsius),
                                                   scaled(h.calliper_temp, 1.0, -kZeroCelsius)};
  std::vector<std::pair<std::string, std::string>> metadata = {
      {"source", fmt::format("hotlap {} abs", HOTLAP_VERSION)},
      {"config", config.path.string()},
      {"surface", event.surface},
      {"abs", event.control == AbsControl::kAbs ? "on" : "off"},
      {"abs_state",
       "0 initialise, 1 hold, 2 increase, 3 fast_increase, 4 decrease, "
       "5 step_increase, 6 step_decrease, 7 exit; empty without ABS"}};
  WriteCsv(path, metadata, names, values);
}

std::vector<std::pair<std::string, std::string>> AbsSummaryRows(const AbsMetrics& m,
                                                                bool with_abs) {
  return {
      {"stopped", m.stopped ? fmt::format("yes, at {:.3f} s after {:.3f} m", *m.stop_time_s,
                                          *m.stopping_distance_m)
                            : fmt::format("no: {:.3f} m/s after {:.3f} m in {:.3f} s",
                                          m.final_speed_mps, m.distance_m, m.end_time_s)},
      {"control cycles", with_abs ? fmt::format("{} ({:.2f} per second)", m.cycles, m.cycles_per_s)
                                  : std::string("no ABS")},
      {"max lambda after the first cycle", Figure(m.max_lambda_after_first_cycle, "{:.4f}")},
      {"time with lambda < 0.135 after the first cycle",
       m.fraction_time_lambda_below_0_135
           ? fmt::format("{:.1f} %", 100.0 * *m.fraction_time_lambda_below_0_135)
           : std::string("-")},
      {"max lambda above the exit speed", fmt::format("{:.4f}", m.max_lambda)},
      {"wheel locked above the exit speed", m.wheel_locked ? "yes" : "no"},
      {"peak disc / calliper temperature",
       fmt::format("{:.1f} / {:.1f} \u00b0C", KelvinToCelsius(m.peak_disc_temp_K),
                   KelvinToCelsius(m.peak_calliper_temp_K))},
      {"energy: kinetic lost + drum work",
       fmt::format("{:.1f} J", m.energy.kinetic_lost_J + m.energy.drum_work_J)},
      {"energy: brake + tyre slip + rolling",
       fmt::format("{:.1f} + {:.1f} + {:.1f} J (closure error {:.2e})", m.energy.brake_J,
                   m.energy.tyre_slip_J, m.energy.rolling_resistance_J, m.energy.closure_error)},
  };
}

std::vector<std::string> AbsScenarioLines(const std::vector<AbsComparisonRun>& comparison,
                                          const AbsStopSeries& series) {
  std::vector<std::string> lines = {
      "scenarios (to standstill):   surface   ABS m   locked m   ratio"};
  for (size_t i = 0; i + 1 < comparison.size(); i += 2) {
    const AbsMetrics& abs = comparison[i].metrics;
    const AbsMetrics& locked = comparison[i + 1].metrics;
    lines.push_back(fmt::format(
        "{:>38} {:>7} {:>10} {:>7}", comparison[i].surface,
        Figure(abs.stopping_distance_m, "{:.2f}"), Figure(locked.stopping_distance_m, "{:.2f}"),
        abs.stopping_distance_m && locked.stopping_distance_m
            ? fmt::format("{:.3f}", *abs.stopping_distance_m / *locked.stopping_distance_m)
            : std::string("-")));
  }
  lines.push_back(fmt::format("stop series: peak disc temperature {:.1f} degC after {} stops",
                              KelvinToCelsius(series.stops.back().peak_disc_temp_K),
                              series.stops.size()));
  return lines;
}

}  // namespace hotlap::sim
