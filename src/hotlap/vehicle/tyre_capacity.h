#pragma once
/// @file
/// A tyre's force capacity against load: the peak longitudinal force (driving and braking) and
/// the peak lateral force (to the left and to the right) of its force model in pure slip, at the
/// corner's camber and pressure, tabulated over load and interpolated. The quasi-steady-state lap
/// uses them as a friction ellipse per corner.
///
/// The peaks are found numerically (a scan then golden-section refinement), so any force model
/// works. Forces here are the model's own, before the grip factor g(T) h(wear).

#include <vector>

#include "hotlap/vehicle/vehicle_params.h"

namespace hotlap::vehicle {

/// Peak pure-slip forces at one load, N (all >= 0).
struct TyrePeaks {
  double drive = 0.0;  ///< largest Fx > 0 over slip ratio
  double brake = 0.0;  ///< largest -Fx over slip ratio
  double left = 0.0;   ///< largest Fy > 0 over slip angle
  double right = 0.0;  ///< largest -Fy over slip angle
};

class TyreCapacity {
 public:
  /// Tabulates the corner's tyre at loads 0..max_load_N in `points` steps, at `speed` m/s.
  TyreCapacity(const CornerSetup& corner, double max_load_N, int points, double speed);

  /// Peaks at load `fz` (linear interpolation; 0 at or below zero load; linear extrapolation of
  /// the last interval above the table).
  TyrePeaks At(double fz) const;

  double max_load() const { return max_load_; }

 private:
  double max_load_;
  double step_;
  std::vector<TyrePeaks> table_;
};

/// The peaks of one corner's tyre at one load (what the table stores).
TyrePeaks FindTyrePeaks(const CornerSetup& corner, double fz, double speed);

}  // namespace hotlap::vehicle
