#pragma once
/// @file
/// The ABS unit's wheel-speed filter (docs/abs.md, "Wheel-speed filter"; docs/fe-tyre.md): the
/// controller's wheel speed passed through a second-order digital filter at the controller's
/// period before the controller differentiates it, as a production ABS filters its wheel-speed
/// signal for the wheel's torsional modes. On the FE tyre the brake acts on the rim, which is
/// tied to the belt and tread through the sidewalls' torsional compliance; the torque's ramp
/// rings that rim-against-belt mode (50-60 Hz) and the rim, where the sensor is, decelerates by
/// several g before the slip builds, tripping -a early. A notch at that mode removes it; the
/// rigid wheel of the lumped model has no such mode.
///
///   brake::WheelSpeedFilter f(params, period_s);
///   const double omega_seen = f.Step(omega_measured);   // once per controller tick
///
/// A biquad (direct form II transposed) with unit gain at zero frequency, started at rest at its
/// first input (no transient from a steady signal). kNone passes the signal unchanged.

#include <string>

#include "hotlap/common/yaml_reader.h"

namespace hotlap::brake {

enum class WheelSpeedFilterKind {
  kNone,     ///< the signal as measured
  kNotch,    ///< a notch at frequency_hz with quality `quality` (bandwidth f / Q)
  kLowPass,  ///< second-order low-pass (Butterworth at quality 1/sqrt 2) at frequency_hz
};

struct WheelSpeedFilterParams {
  WheelSpeedFilterKind kind = WheelSpeedFilterKind::kNone;
  double frequency_hz = 0.0;  ///< the notch's centre or the low-pass corner, Hz
  double quality = 0.0;       ///< Q (> 0)
};

/// "none", "notch", "low-pass".
const char* WheelSpeedFilterKindName(WheelSpeedFilterKind kind);

/// Reads a `wheel_speed_filter` mapping: kind (none | notch | low-pass), frequency_hz and
/// quality (both needed unless kind is none). The frequency must lie below the Nyquist
/// frequency of `period_s`; InputError naming the field otherwise.
WheelSpeedFilterParams ReadWheelSpeedFilterParams(YamlReader& y, double period_s);

/// The filter's state.
class WheelSpeedFilter {
 public:
  WheelSpeedFilter() = default;
  WheelSpeedFilter(const WheelSpeedFilterParams& params, double period_s);

  /// The filtered value of the next sample.
  double Step(double x);
  /// Back to "not started".
  void Reset() { started_ = false; }

  /// The state, for checkpoints: started, and the two delay elements.
  bool started() const { return started_; }
  double z1() const { return z1_; }
  double z2() const { return z2_; }
  void SetState(bool started, double z1, double z2) {
    started_ = started;
    z1_ = z1;
    z2_ = z2;
  }

 private:
  bool active_ = false, started_ = false;
  double b0_ = 1.0, b1_ = 0.0, b2_ = 0.0, a1_ = 0.0, a2_ = 0.0;
  double z1_ = 0.0, z2_ = 0.0;
};

}  // namespace hotlap::brake
