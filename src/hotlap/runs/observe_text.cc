#include "hotlap/runs/observe_text.h"

#include <iterator>

#include <fmt/format.h>

#include "hotlap/common/units.h"

namespace hotlap::runs {

namespace {

void AppendEstimates(std::string& out, const observe::CarObserver& observer) {
  auto it = std::back_inserter(out);
  fmt::format_to(it, "{:<6} {:>16} {:>16} {:>20} {:>16} {:>16}\n", "corner", "tread degC",
                 "carcass degC", "wear mm", "disc degC", "calliper degC");
  for (Corner c : kAllCorners) {
    const observe::CornerEstimate e = observer.Estimate(c);
    fmt::format_to(
        it, "{:<6} {:>16} {:>16} {:>20} {:>16} {:>16}\n", CornerName(c),
        fmt::format("{:.2f} +- {:.2f}", KelvinToCelsius(e.tread_temp), e.tread_temp_sd),
        fmt::format("{:.2f} +- {:.2f}", KelvinToCelsius(e.carcass_temp), e.carcass_temp_sd),
        fmt::format("{:.5f} +- {:.5f}", e.wear, e.wear_sd),
        fmt::format("{:.1f} +- {:.1f}", KelvinToCelsius(e.disc_temp), e.disc_temp_sd),
        fmt::format("{:.1f} +- {:.1f}", KelvinToCelsius(e.calliper_temp), e.calliper_temp_sd));
  }
}

// The car's own models' further states and the gas, where a corner runs them.
void AppendGas(std::string& out, const observe::CarObserver& observer) {
  auto it = std::back_inserter(out);
  bool header = false;
  for (Corner c : kAllCorners) {
    if (!observer.observes_gas(c)) continue;
    if (!header) {
      fmt::format_to(it, "{:<6} {:>16} {:>18} {:>16} {:>16}\n", "corner", "gas degC",
                     "hot pressure kPa", "rim degC", "disc bulk degC");
      header = true;
    }
    const observe::CornerEstimate e = observer.Estimate(c);
    fmt::format_to(
        it, "{:<6} {:>16} {:>18} {:>16} {:>16}\n", CornerName(c),
        fmt::format("{:.2f} +- {:.2f}", KelvinToCelsius(e.gas_temp), e.gas_temp_sd),
        fmt::format("{:.2f} +- {:.2f}", 1e-3 * e.pressure, 1e-3 * e.pressure_sd),
        fmt::format("{:.2f} +- {:.2f}", KelvinToCelsius(e.rim_temp), e.rim_temp_sd),
        fmt::format("{:.1f} +- {:.1f}", KelvinToCelsius(e.disc_bulk_temp), e.disc_bulk_temp_sd));
  }
}

void AppendConsistency(std::string& out, const observe::CarObserver& observer) {
  auto it = std::back_inserter(out);
  fmt::format_to(it, "{:<6} {:<14} {:>8} {:>8} {:>8} {:>8} {:>9} {:>19} {}\n", "corner", "sensor",
                 "readings", "used", "rejected", "missing", "mean NIS", "95% bounds", "");
  for (Corner c : kAllCorners) {
    for (observe::Sensor s : observe::kAllSensors) {
      const observe::SensorMonitor& m = observer.monitor(c, s);
      if (m.readings == 0) continue;
      const auto [lo, hi] = m.Bounds95();
      fmt::format_to(it, "{:<6} {:<14} {:>8} {:>8} {:>8} {:>8} {:>9.3f} {:>19} {}\n", CornerName(c),
                     observe::SensorQuantity(s), m.readings, m.used, m.rejected, m.missing,
                     m.MeanNis(), fmt::format("[{:.3f}, {:.3f}]", lo, hi),
                     m.Consistent()           ? "consistent"
                     : m.GateRejectsTooMany() ? "INCONSISTENT (too many rejected)"
                                              : "INCONSISTENT");
    }
  }
}

}  // namespace

std::string ObserveRunText(const ObserveRun& run, const vehicle::Car& car) {
  const observe::CarObserver& observer = *run.observer;
  const observe::ObserverConfig& config = observer.config();
  const observe::ObserveSummary& s = run.summary;
  std::string out =
      fmt::format("hotlap observe: {} ({} samples, {:.2f} s of log) with car '{}', noise {}\n",
                  s.telemetry, observer.samples(), s.duration_s, car.name, config.source);
  fmt::format_to(std::back_inserter(out),
                 "sensor lag: tread {:g} s, disc {:g} s, calliper {:g} s (from {})\n",
                 config.sensor_lag.tread_temp, config.sensor_lag.disc_temp,
                 config.sensor_lag.calliper_temp, s.sensor_lag_from);
  if (observer.models() == observe::ObservedModels::kCar && config.car_models) {
    fmt::format_to(std::back_inserter(out), "TPMS lag: {:g} s (from {})\n",
                   config.car_models->tpms_lag_s, s.tpms_lag_from);
  }
  AppendEstimates(out, observer);
  AppendGas(out, observer);
  AppendConsistency(out, observer);
  fmt::format_to(std::back_inserter(out),
                 "{} disagreement warning(s); wrote {} in {:.3f} s ({:.0f} times real time)\n",
                 s.warnings.size(), s.out == "-" ? "standard output" : s.out, s.wall_time_s,
                 s.wall_time_s > 0.0 ? s.duration_s / s.wall_time_s : 0.0);
  return out;
}

}  // namespace hotlap::runs
