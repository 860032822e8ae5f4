#pragma once
/// @file
/// The extended Kalman filter of one corner on the car's own models (`hotlap observe --models
/// car`, docs/observer.md): the gas-and-rim tyre and its brake as one wheel, since the rim takes
/// the brake's heat (hub conduction, the disc's radiation) and gives it to the tyre's gas. States:
/// tread, carcass, rim, disc surface, calliper and disc bulk temperatures (K) and the wear (mm);
/// a lumped disc keeps its bulk state at its start with zero variance.
///
/// Readings: the tread, disc and calliper temperatures (each through its sensor's first-order lag
/// where one is given, sensor_lag.h), and the TPMS's hot gauge pressure and gas temperature. The
/// gas is quasi-static, an algebraic function of the carcass and rim temperatures and the speed
/// (tyre::CalcTyreGas), so a TPMS sensor's lag state follows that function linearised at the
/// means (y1 = a y0 + c h(x0) + b h(x1), h(x) ~ h(m) + H (x - m)); the estimate's gas temperature
/// and pressure have bands from the states' covariance (H P H').
///
/// The prediction integrates the wheel as `hotlap replay` does (sim::IntegrateOverSamples of the
/// tyre and brake together, RK4 sub-steps no longer than max_step_s) in ceres::Jet arithmetic
/// seeded with the identity: the exact Jacobian of the discrete map, as TyreFilter's.

#include <array>
#include <memory>

#include <ceres/jet.h>
#include <Eigen/Core>

#include "hotlap/brake/brake_thermal.h"
#include "hotlap/observe/corner_filter.h"
#include "hotlap/observe/observer_config.h"
#include "hotlap/observe/sensor_lag.h"
#include "hotlap/sim/sampled_inputs.h"
#include "hotlap/tyre/compound.h"
#include "hotlap/tyre/tyre_thermal.h"

namespace hotlap::observe {

/// The inflation gas as the filter sees it: means and standard deviations.
struct GasEstimate {
  double gas_temp = 0.0, gas_temp_sd = 0.0;  ///< K
  double pressure = 0.0, pressure_sd = 0.0;  ///< hot gauge, Pa
};

class WheelFilter {
 public:
  static constexpr int kTread = 0, kCarcass = 1, kWear = 2, kRim = 3, kDisc = 4, kCalliper = 5,
                       kBulk = 6, kStates = 7;
  using Jet = ceres::Jet<double, kStates>;

  /// `tyre` must be a gas-and-rim tyre (InputError otherwise); `lag` the temperature sensors'.
  WheelFilter(const tyre::TyreThermalParams<double>& tyre,
              std::shared_ptr<const tyre::TyreCompound> compound,
              const brake::BrakeThermalParams<double>& brake, const ProcessNoise& process,
              const CarModelsNoise& car_models, double max_step_s, const SensorLag& lag);

  /// The states at `speed` (m/s, for the gas); the sensors start settled on them. With a lumped
  /// disc the bulk's variance is set to zero.
  void Reset(const Gaussian<kStates>& start, double speed);
  /// From time[0] to time[1] of the two-sample inputs of the tyre and of the brake (whose fx may
  /// be the brake's own). NumericalError if a temperature leaves (0 K, 3000 K).
  void Predict(const sim::CornerSamples& tyre_in, const sim::CornerSamples& brake_in);

  UpdateOutcome UpdateTread(double reading_K, double sd_K, double gate_nis) {
    return UpdateTemperature(0, reading_K, sd_K, gate_nis);
  }
  UpdateOutcome UpdateDisc(double reading_K, double sd_K, double gate_nis) {
    return UpdateTemperature(1, reading_K, sd_K, gate_nis);
  }
  UpdateOutcome UpdateCalliper(double reading_K, double sd_K, double gate_nis) {
    return UpdateTemperature(2, reading_K, sd_K, gate_nis);
  }
  /// A TPMS reading: hot gauge pressure, Pa (sd Pa), or gas temperature, K (sd K).
  UpdateOutcome UpdatePressure(double reading_Pa, double sd_Pa, double gate_nis) {
    return UpdateScalar(z_, kTpms + kTpmsPressure, reading_Pa, sd_Pa * sd_Pa, gate_nis);
  }
  UpdateOutcome UpdateGasTemp(double reading_K, double sd_K, double gate_nis) {
    return UpdateScalar(z_, kTpms + kTpmsGasTemp, reading_K, sd_K * sd_K, gate_nis);
  }

  /// The model's states (the first kStates of the filter's).
  Gaussian<kStates> estimate() const;
  /// The gas now (at the last sample's speed).
  GasEstimate Gas() const;
  /// The Jacobian of the last Predict() (of the model's states).
  const Eigen::Matrix<double, kStates, kStates>& transition() const { return f_; }

 private:
  // The filter's state: the model's, then what each lagging sensor reads now (y, sensor_lag.h):
  // the tread, disc and calliper sensors (each the state itself where its lag is 0: then read
  // through the state), then the TPMS's pressure and gas temperature. Every update is one
  // scalar update of the whole, so each reading corrects the model and every sensor's y alike.
  static constexpr int kTemperatureSensors = kStates, kTpms = kStates + 3, kAll = kStates + 5;
  static constexpr int kTpmsPressure = 0, kTpmsGasTemp = 1;
  static constexpr std::array<int, 3> kSensorState = {kTread, kDisc, kCalliper};
  using TpmsValues = Eigen::Matrix<double, 2, 1>;
  using TpmsRows = Eigen::Matrix<double, 2, kStates>;

  UpdateOutcome UpdateTemperature(int sensor, double reading, double sd, double gate_nis);
  // The TPMS's readings (pressure, gas temperature) and their rows at the states `mean`, at
  // `speed`.
  void Tpms(const Eigen::Matrix<double, kStates, 1>& mean, double speed, TpmsValues& h,
            TpmsRows& rows) const;

  tyre::TyreThermalParams<Jet> tyre_;
  std::shared_ptr<const tyre::TyreCompound> compound_;
  brake::BrakeThermalParams<Jet> brake_;
  bool bulk_;
  Eigen::Matrix<double, kStates, 1> q_;
  double max_step_s_;
  std::array<double, 3> temperature_lag_s_;
  double tpms_lag_s_;
  double speed_ = 0.0;
  Gaussian<kAll> z_;
  Eigen::Matrix<double, kStates, kStates> f_ = Eigen::Matrix<double, kStates, kStates>::Identity();
};

}  // namespace hotlap::observe
