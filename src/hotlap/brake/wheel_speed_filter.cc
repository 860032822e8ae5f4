#include "hotlap/brake/wheel_speed_filter.h"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "hotlap/common/enum_names.h"

namespace hotlap::brake {

constexpr EnumNames<WheelSpeedFilterKind, 3> kWheelSpeedFilterKinds{
    {{{WheelSpeedFilterKind::kNone, "none"},
      {WheelSpeedFilterKind::kNotch, "notch"},
      {WheelSpeedFilterKind::kLowPass, "low-pass"}}}};

const char* WheelSpeedFilterKindName(WheelSpeedFilterKind kind) {
  return kWheelSpeedFilterKinds.Name(kind);
}

WheelSpeedFilterParams ReadWheelSpeedFilterParams(YamlReader& y, double period_s) {
  WheelSpeedFilterParams p;
  const std::string kind = y.String("kind");
  const std::optional<WheelSpeedFilterKind> found = kWheelSpeedFilterKinds.Find(kind);
  if (!found) {
    y.Fail("kind", fmt::format("'{}' is not a filter ({})", kind, kWheelSpeedFilterKinds.List()));
  }
  p.kind = *found;
  if (p.kind == WheelSpeedFilterKind::kNone) {
    y.Finish();
    return p;
  }
  const double nyquist = 0.5 / period_s;
  p.frequency_hz = y.Number("frequency_hz", Range{0.0, nyquist, false, false, "Hz"});
  p.quality = y.Number("quality", Range::Positive(""));
  y.Finish();
  return p;
}

WheelSpeedFilter::WheelSpeedFilter(const WheelSpeedFilterParams& params, double period_s) {
  if (params.kind == WheelSpeedFilterKind::kNone) return;
  active_ = true;
  // The RBJ audio-EQ cookbook's biquads, normalised by a0.
  const double w0 = 2.0 * std::numbers::pi * params.frequency_hz * period_s;
  const double c = std::cos(w0), alpha = std::sin(w0) / (2.0 * params.quality);
  const double a0 = 1.0 + alpha;
  if (params.kind == WheelSpeedFilterKind::kNotch) {
    b0_ = 1.0 / a0;
    b1_ = -2.0 * c / a0;
    b2_ = 1.0 / a0;
  } else {
    b0_ = 0.5 * (1.0 - c) / a0;
    b1_ = (1.0 - c) / a0;
    b2_ = 0.5 * (1.0 - c) / a0;
  }
  a1_ = -2.0 * c / a0;
  a2_ = (1.0 - alpha) / a0;
}

double WheelSpeedFilter::Step(double x) {
  if (!active_) return x;
  if (!started_) {
    // At rest at x: y = x for ever if x stays (unit gain at zero frequency).
    z1_ = x - b0_ * x;
    z2_ = b2_ * x - a2_ * x;
    started_ = true;
  }
  const double y = b0_ * x + z1_;
  z1_ = b1_ * x - a1_ * y + z2_;
  z2_ = b2_ * x - a2_ * y;
  return y;
}

}  // namespace hotlap::brake
