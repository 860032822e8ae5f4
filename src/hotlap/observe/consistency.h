#pragma once
/// @file
/// Consistency monitoring of the observer (docs/observer.md, "Consistency"): per corner and
/// sensor, the count of readings used, rejected by the innovation gate and missing, the mean
/// normalised innovation squared (NIS) against its chi-square bounds, and a running mean of the
/// NIS that flags a disagreement between the model and the car when it stays high for longer than
/// a set time (a sensor fault, or a car that is not the model any more).

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "hotlap/common/corner.h"

namespace hotlap::observe {

/// The measured channels the observer reads.
/// The temperature sensors, then the TPMS's (read where the car's own models are observed).
enum class Sensor { kTread, kDisc, kCalliper, kPressure, kGasTemp };
inline constexpr std::array<Sensor, 5> kAllSensors = {
    Sensor::kTread, Sensor::kDisc, Sensor::kCalliper, Sensor::kPressure, Sensor::kGasTemp};
/// "tread_temp", "disc_temp", "calliper_temp", "pressure", "gas_temp": the telemetry quantity
/// of the sensor.
std::string_view SensorQuantity(Sensor s);

/// The two-sided 95% bounds of the mean of n independent chi-square(1) values, i.e. of
/// chi-square(n) / n (Wilson-Hilferty approximation, within 0.5% of the exact quantiles for
/// n >= 10). {0, inf} for n = 0.
std::pair<double, double> MeanNisBounds95(long n);

/// A disagreement that lasted longer than ObserverConfig::disagree_after_s.
struct DisagreementWarning {
  Corner corner = Corner::kFrontLeft;
  Sensor sensor = Sensor::kTread;
  double since_s = 0.0;      ///< log time the running mean NIS rose above the threshold, s
  double time_s = 0.0;       ///< log time of the warning, s
  double nis_average = 0.0;  ///< the running mean NIS then
  std::string message;       ///< one line, naming the corner, the sensor and the times
};

/// One sensor of one corner.
class SensorMonitor {
 public:
  /// Counters.
  long readings = 0;       ///< cells with a value (the first sample's, which start the filter, too)
  long used = 0;           ///< readings that corrected the state
  long rejected = 0;       ///< readings beyond the innovation gate
  long missing = 0;        ///< empty cells (dropouts) after the first sample
  double nis_sum = 0.0;    ///< sum of the NIS of the used readings
  long disagreements = 0;  ///< warnings raised
  double disagree_time_s = 0.0;  ///< total time the running mean was above the threshold, s

  /// Mean NIS of the used readings (NaN before any).
  double MeanNis() const;
  /// MeanNisBounds95(used).
  std::pair<double, double> Bounds95() const { return MeanNisBounds95(used); }
  /// More than kMaxRejectedFraction of the readings were beyond the gate. A consistent filter's
  /// 5-sigma gate rejects 5.7e-7 of them; a sensor that drifted or broke is rejected on and on,
  /// and the used readings (those before) can still look consistent.
  static constexpr double kMaxRejectedFraction = 0.01;
  bool GateRejectsTooMany() const;
  /// The mean NIS of the used readings lies within its 95% bounds and the gate did not reject
  /// too many (GateRejectsTooMany).
  bool Consistent() const;
  /// The running mean NIS (1 before any reading).
  double nis_average() const { return average_; }

  /// A reading at log time `time_s` with normalised innovation squared `nis`, used or rejected.
  /// Returns a warning when the running mean has been above `threshold` for longer than `after_s`
  /// (once per such stretch).
  std::optional<double> Record(double time_s, double nis, bool was_used, double window_s,
                               double threshold, double after_s);

 private:
  double average_ = 1.0;
  std::optional<double> last_time_;
  std::optional<double> above_since_;
  bool warned_ = false;
};

}  // namespace hotlap::observe
