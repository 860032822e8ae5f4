#include "hotlap/common/telemetry_limits.h"
#include "hotlap/common/special_values.h"

#include <limits>
#include <numbers>

namespace hotlap {
namespace {

constexpr double kAbsoluteZero = 0.0;     // K
constexpr double kHottest = 2273.15;      // K: 2000 degC, above a carbon disc's peak in a stop
constexpr double kFastest = 150.0;        // m/s: 540 km/h, above any circuit car's top speed
constexpr double kHeaviest = 100000.0;    // N: 10 t on one wheel, ten times a Cup car's corner
constexpr double kLoadNoise = 500.0;      // N: a load signal's offset with the wheel in the air
constexpr double kSpeedNoise = 0.5;       // m/s: a speed signal's noise at standstill
constexpr double kLockedSlipNoise = 0.1;  // slip ratio past -1 from two speed signals' lag
constexpr double kVacuum = -101325.0;     // Pa gauge: no tyre holds less than a vacuum
constexpr double kBurst = 2.0e6;          // Pa: 290 psi, several times any racing tyre's

}  // namespace

std::optional<ChannelLimits> LimitsOf(std::string_view quantity) {
  const double half_pi = std::numbers::pi / 2.0;
  if (quantity == "speed") {
    return ChannelLimits{-kSpeedNoise, 0.0, kFastest, "standstill (speed signal noise)",
                         "a speed is not negative, and none is above 150 m/s (540 km/h)"};
  }
  if (quantity == "fz") {
    return ChannelLimits{-kLoadNoise, 0.0, kHeaviest, "a wheel in the air (no load)",
                         "a tyre's vertical load is not negative, and none is above 100 kN"};
  }
  if (quantity == "slip_angle") {
    return ChannelLimits{-half_pi, -half_pi, half_pi, "", "a slip angle is within +-90 degrees"};
  }
  if (quantity == "slip_ratio") {
    return ChannelLimits{-1.0 - kLockedSlipNoise, -1.0, kInf, "a locked wheel (slip ratio -1)",
                         "a slip ratio is not below -1 (a locked wheel)"};
  }
  if (quantity.size() > 5 && quantity.substr(quantity.size() - 5) == "_temp") {
    return ChannelLimits{kAbsoluteZero, kAbsoluteZero, kHottest, "",
                         "a temperature is above absolute zero and below 2000 degC"};
  }
  if (quantity == "rolling_radius") {
    return ChannelLimits{std::numeric_limits<double>::min(), std::numeric_limits<double>::min(),
                         2.0, "", "a rolling radius is positive and below 2 m"};
  }
  if (quantity == "pressure") {
    return ChannelLimits{kVacuum, kVacuum, kBurst, "",
                         "a tyre's gauge pressure is above a vacuum (-101.3 kPa) and below 2000 "
                         "kPa"};
  }
  if (quantity == "brake_power") {
    return ChannelLimits{0.0, 0.0, kInf, "", "a brake's power is not negative"};
  }
  return std::nullopt;
}

bool IsRefused(std::string_view quantity, double value) {
  const std::optional<ChannelLimits> limits = LimitsOf(quantity);
  return limits && (value < limits->refuse_below || value > limits->refuse_above);
}

}  // namespace hotlap
