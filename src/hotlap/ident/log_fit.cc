#include "hotlap/ident/log_fit.h"

#include <cmath>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"

namespace hotlap::ident {

InitialStateMode ParseInitialStateMode(const std::string& text) {
  if (text == "fitted") return InitialStateMode::kFitted;
  if (text == "measured") return InitialStateMode::kMeasured;
  throw InputError(fmt::format("initial state '{}': expected fitted or measured", text));
}

MeasuredChannel TemperatureChannel(const LoggedChannel& logged,
                                   const std::vector<double>& weights) {
  MeasuredChannel ch;
  ch.name = logged.quantity;
  ch.unit = "\u00b0C";
  ch.display_offset = -kZeroCelsius;
  ch.values = logged.values;
  ch.weights = weights;
  ch.prior_sigma = 1.0;
  ch.min_sigma = 0.01;
  return ch;
}

FitParameter InitialTemperatureParameter(const std::string& key, const std::string& label) {
  return {.key = key,
          .label = label,
          .unit = "\u00b0C",
          .lower = 200.0,
          .upper = 1500.0,
          .scale = 10.0,
          .role = ParameterRole::kNuisance,
          .display_offset = -kZeroCelsius};
}

double StartingTemperature(const LoggedChannel& logged, std::span<const double> time,
                           InitialStateMode mode, double fallback) {
  if (!logged.usable) return fallback;
  if (mode == InitialStateMode::kFitted) {
    const double v = RobustFirstValue(time, logged.values);
    return std::isfinite(v) ? v : fallback;
  }
  for (double v : logged.values) {
    if (std::isfinite(v)) return v;
  }
  return fallback;
}

double LogUniform(std::mt19937_64& rng, double lo, double hi) {
  const double u = static_cast<double>(rng() >> 11) * 0x1.0p-53;
  return std::exp(std::log(lo) + u * (std::log(hi) - std::log(lo)));
}

void AddLagWarnings(const FitResult& fit, double modelled_lag_s, std::vector<std::string>* out,
                    std::string_view option) {
  for (const ChannelStats& st : fit.channels) {
    if (!std::isfinite(st.apparent_lag) || !std::isfinite(st.apparent_lag_std_error)) continue;
    if (st.apparent_lag > 0.02 && st.apparent_lag > 3.0 * st.apparent_lag_std_error) {
      // One linearised step from a fit that left the lag out: it sees part of a large lag (a
      // disc's 0.2 s as 0.07-0.14 s), so the advice is to refit and look again.
      out->push_back(fmt::format(
          "{}: the measurements trail the model as a sensor lag of at least about {:.2f} s{} "
          "would (+/- {:.3f} s); if the sensor lags, refit with {} {:.2f} and look again",
          st.name, st.apparent_lag, modelled_lag_s > 0.0 ? " beyond the modelled one" : "",
          st.apparent_lag_std_error, option, modelled_lag_s + st.apparent_lag));
    }
  }
}

void AddMisfitWarnings(const FitResult& fit, std::vector<std::string>* out) {
  for (const ChannelStats& st : fit.channels) {
    if (st.samples < 20 || !(st.autocorrelation > 0.9)) continue;
    out->push_back(fmt::format(
        "{}: the residuals follow one another (lag-one autocorrelation {:.2f}, RMS {:.3g}): the "
        "model misses something in this channel (a sensor lag, an input, a held parameter), and "
        "the intervals assume it does not: read them as too narrow",
        st.name, st.autocorrelation, st.rms));
  }
}

}  // namespace hotlap::ident
