#pragma once
/// @file
/// The live observer of a whole car (docs/observer.md): per corner a tyre filter (tread, carcass,
/// wear, optional p5 factor) and a brake filter (disc, calliper) of the paper's models
/// (corner_filter.h), or with ObservedModels::kCar, for a gas-and-rim tyre, one wheel filter of
/// the car's own models (wheel_filter.h: rim and disc bulk too, TPMS readings, the gas
/// estimated), fed one sample at a time, with the consistency monitor (consistency.h).
///
/// How to use: construct with the car and a noise model (observer_config.h), then call Step() with
/// every sample in time order: the first sample starts the filters (readings present on it become
/// the starting means, with the sensor's variance; otherwise ObserverStart, then the car file's
/// initial_state); every later one predicts over the interval from the previous sample, with the
/// inputs linear between the two as `hotlap replay` takes them, then corrects with the readings
/// present (NaN = a dropout). Estimate() gives the means and 1-sigma bands after the last Step().

#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "hotlap/common/corner.h"
#include "hotlap/observe/consistency.h"
#include "hotlap/observe/corner_filter.h"
#include "hotlap/observe/observer_config.h"
#include "hotlap/observe/wheel_filter.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::observe {

/// What one corner's models see at a sample, SI (as sim::CornerChannels).
struct CornerInputs {
  double speed = 0.0;       ///< m/s
  double fx = 0.0;          ///< N (< 0 braking)
  double fy = 0.0;          ///< N
  double fz = 0.0;          ///< N
  double slip_angle = 0.0;  ///< rad
  double slip_ratio = 0.0;  ///< 1
  /// The brake's force, N (< 0 braking), where it differs from the tyre's fx (a log's
  /// brake_power column: sim/replay_io.h); NaN: the brake sees fx.
  double brake_fx = std::numeric_limits<double>::quiet_NaN();
};

/// One corner's readings at a sample, K and Pa; NaN where the sensor gave nothing.
struct CornerReadings {
  double tread_temp = std::numeric_limits<double>::quiet_NaN();
  double disc_temp = std::numeric_limits<double>::quiet_NaN();
  double calliper_temp = std::numeric_limits<double>::quiet_NaN();
  double pressure = std::numeric_limits<double>::quiet_NaN();  ///< TPMS hot gauge pressure, Pa
  double gas_temp = std::numeric_limits<double>::quiet_NaN();  ///< TPMS gas temperature, K
};

/// Which models the observer runs: the paper's (the two-mass tyre and the lumped disc, as the
/// fits identify them) or the car's own (its gas-and-rim tyres with their rims and TPMS, its
/// surface-and-bulk discs).
enum class ObservedModels { kPaper, kCar };

/// One sample of the car's stream.
struct ObserverSample {
  double time = 0.0;  ///< s, increasing from sample to sample
  std::array<CornerInputs, 4> inputs;
  double ambient_temp = 298.15;  ///< K (also the brakes' cooling air)
  double track_temp = 313.15;    ///< K
  std::array<CornerReadings, 4> readings;
};

/// Starting temperatures where the first sample has no reading, K; unset: the car file's.
struct ObserverStart {
  std::optional<double> tread_temp, carcass_temp, disc_temp, calliper_temp;
};

/// Means and standard deviations of one corner's states: K, mm, 1.
struct CornerEstimate {
  double tread_temp = 0.0, tread_temp_sd = 0.0;
  double carcass_temp = 0.0, carcass_temp_sd = 0.0;
  double wear = 0.0, wear_sd = 0.0;
  double disc_temp = 0.0, disc_temp_sd = 0.0;
  double calliper_temp = 0.0, calliper_temp_sd = 0.0;
  double p5_scale = 1.0, p5_scale_sd = 0.0;
  /// The car's own models (ObservedModels::kCar on a gas-and-rim tyre): the rim, the disc bulk
  /// (a lumped disc's stays at its start) and the gas; false and zero otherwise.
  bool has_gas = false;
  double rim_temp = 0.0, rim_temp_sd = 0.0;
  double disc_bulk_temp = 0.0, disc_bulk_temp_sd = 0.0;
  double gas_temp = 0.0, gas_temp_sd = 0.0;  ///< K
  double pressure = 0.0, pressure_sd = 0.0;  ///< hot gauge, Pa
};

class CarObserver {
 public:
  /// InputError for ObservedModels::kCar with a noise file without its car_models section.
  CarObserver(const vehicle::Car& car, ObserverConfig config, const ObserverStart& start = {},
              ObservedModels models = ObservedModels::kPaper);

  /// Takes the next sample; returns the disagreement warnings it raised. InputError if its time
  /// does not follow the previous sample's or is not finite, or an input is not finite;
  /// NumericalError if a predicted temperature leaves (0 K, 3000 K).
  std::vector<DisagreementWarning> Step(const ObserverSample& sample);

  /// The estimate after the last Step() (the starting state before the first).
  CornerEstimate Estimate(Corner c) const;
  const SensorMonitor& monitor(Corner c, Sensor s) const {
    return monitors_[CornerIndex(c)][static_cast<int>(s)];
  }
  const ObserverConfig& config() const { return config_; }
  ObservedModels models() const { return models_; }
  /// Whether corner c runs the wheel filter of the car's own models.
  bool observes_gas(Corner c) const { return wheels_[CornerIndex(c)].has_value(); }
  /// Samples taken so far.
  long samples() const { return samples_; }
  /// The last sample's time, s (NaN before the first).
  double time() const {
    return previous_ ? previous_->time : std::numeric_limits<double>::quiet_NaN();
  }

  /// The filters, for tests and benchmarks.
  const TyreFilter& tyre_filter(Corner c) const { return tyres_[CornerIndex(c)]; }
  const BrakeFilter& brake_filter(Corner c) const { return brakes_[CornerIndex(c)]; }

 private:
  void Start(const ObserverSample& first);
  void Correct(const ObserverSample& sample, std::vector<DisagreementWarning>& warnings);
  UpdateOutcome Update(int corner, Sensor s, double reading, double gate_nis);

  ObserverConfig config_;
  ObservedModels models_;
  vehicle::InitialTemperatures car_initial_;
  ObserverStart start_;
  std::vector<TyreFilter> tyres_;
  std::vector<BrakeFilter> brakes_;
  std::array<std::optional<WheelFilter>, 4> wheels_;  ///< the car's own models, where run
  std::array<std::array<SensorMonitor, kAllSensors.size()>, 4> monitors_;
  std::optional<ObserverSample> previous_;
  long samples_ = 0;
};

/// The estimate columns `hotlap observe` writes, canonical units: time_s, then per corner
/// tread_temp_<c>_C, tread_temp_<c>_sd_C, carcass_temp_<c>_C, carcass_temp_<c>_sd_C, wear_<c>_mm,
/// wear_<c>_sd_mm, disc_temp_<c>_C, disc_temp_<c>_sd_C, calliper_temp_<c>_C, calliper_temp_<c>_sd_C
/// and, with the p5 state, p5_scale_<c>, p5_scale_<c>_sd; where the corner runs the car's own
/// models also rim_temp_<c>_C, disc_bulk_temp_<c>_C, gas_temp_<c>_C (each with its _sd_C) and
/// pressure_<c>_kPa, pressure_<c>_sd_kPa.
std::vector<std::string> EstimateColumns(const CarObserver& observer);
/// The values of those columns after the observer's last Step().
std::vector<double> EstimateRow(const CarObserver& observer);

}  // namespace hotlap::observe
