#pragma once
/// @file
/// Replay: run all four tyre and all four brake models over a logged lap (or stint) and return
/// the temperature, wear and brake-power histories at the log's sample times.
///
/// Inputs are taken as linear between samples; each sample interval is integrated with RK4
/// sub-steps no longer than ReplayOptions::max_step_s, which keeps the integration error far
/// below 0.05 degC at any logging rate (tests/sim/replay_test.cc checks 10 Hz to 1 kHz).

#include <array>
#include <optional>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "hotlap/common/corner.h"
#include "hotlap/sim/energy_audit.h"
#include "hotlap/sim/sampled_inputs.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::sim {

/// One corner's measured channels at the sample times, SI.
struct CornerChannels {
  std::vector<double> speed;       ///< m/s
  std::vector<double> fx, fy, fz;  ///< N
  std::vector<double> slip_angle;  ///< rad
  std::vector<double> slip_ratio;  ///< 1
  /// Braking force of this corner's brake, N, signed as fx (< 0 braking), when it differs from
  /// the tyre's fx: e.g. two wheels on a locked axle share one brake torque while their tyres'
  /// forces differ; from a log, its brake_power column (replay_io.h). Empty: the brake sees fx.
  std::vector<double> brake_fx;
};

/// Everything a replay needs from a log, gaps already filled, SI (K for temperatures).
struct ReplayInputs {
  std::vector<double> time;  ///< s, strictly increasing
  std::array<CornerChannels, 4> corners;
  std::vector<double> ambient_temp;
  std::vector<double> track_temp;
};

/// A corner's inputs as CornerSamples (spans into `inputs`, which must outlive them).
CornerSamples CornerSamplesOf(const ReplayInputs& inputs, Corner corner);

/// The same for the corner's brake: fx is the brake's own force (CornerChannels::brake_fx) where
/// the inputs have it, as the replay takes it. InputError if brake_fx is not as long as time.
CornerSamples BrakeSamplesOf(const ReplayInputs& inputs, Corner corner);

/// Starting state of every corner, K and mm (the rims and disc bulks are read by the models that
/// have them).
struct ReplayInitialState {
  std::array<tyre::TyreState<double>, 4> tyres;
  std::array<brake::BrakeState<double>, 4> brakes;
};

/// The car's own starting temperatures (car.yaml's initial_state), no wear.
ReplayInitialState CarStartState(const vehicle::Car& car);

struct ReplayOptions {
  double max_step_s = 0.02;        ///< longest RK4 sub-step
  bool record_heat_flows = false;  ///< also return q1..q7 of every tyre
  /// Sample indices (increasing, inside the run) where a new stretch of the energy audit starts;
  /// empty: one stretch, the whole run.
  std::vector<size_t> audit_starts;
};

/// Histories of one corner at the sample times (K, mm, W, Pa).
struct CornerHistory {
  std::vector<double> tread_temp, carcass_temp, wear, grip_factor;
  std::vector<double> disc_temp, calliper_temp, brake_power;
  std::array<std::vector<double>, 7> heat_flows;  ///< q1..q7, when recorded
  /// The gas-and-rim tyre's: rim and gas temperatures (K), hot gauge pressure (Pa), rolling
  /// resistance coefficient; empty for the paper's tyre.
  std::vector<double> rim_temp, gas_temp, pressure, rolling_resistance;
  /// The liner's gas (K) and hot gauge pressure (Pa), where the tyre has a liner.
  std::vector<double> liner_gas_temp, liner_pressure;
  /// The surface-and-bulk disc's bulk, K; empty for the lumped disc.
  std::vector<double> disc_bulk_temp;
};

struct ReplayResult {
  std::vector<double> time;
  std::array<CornerHistory, 4> corners;
  /// The energy audit of each stretch (ReplayOptions::audit_starts), per corner.
  std::vector<std::array<CornerEnergyAudit, 4>> audits;
};

/// The channels only some models have (the gas-and-rim tyre's, the bulk disc's), each with its
/// column name pattern ({} is the corner), in file order: gas_temp_{}_C, rim_temp_{}_C,
/// pressure_{}_kPa (hot gauge), rolling_resistance_{}, liner_gas_temp_{}_C, liner_pressure_{}_kPa,
/// disc_bulk_temp_{}_C. A history whose member is empty has no such channel.
std::span<const std::pair<std::string_view, std::vector<double> CornerHistory::*>> ModelChannels();
/// A model channel's SI value in its column's unit (degC, kPa, 1).
double ModelChannelValue(std::vector<double> CornerHistory::*member, double si);

/// The state of every corner at sample k of a run (as a next run would start from it).
ReplayInitialState StateAt(const ReplayResult& result, size_t k);
/// The state at the run's last sample.
ReplayInitialState EndState(const ReplayResult& result);

/// Checks sizes and values (InputError naming the channel and sample if something is off), then
/// integrates. Throws NumericalError if a temperature leaves [0 K, 3000 K].
ReplayResult RunReplay(const vehicle::Car& car, const ReplayInputs& inputs,
                       const ReplayInitialState& initial, const ReplayOptions& options);

/// The inputs resampled onto a uniform grid at rate_hz (linear interpolation, so the result is
/// again a valid piecewise-linear log), repeated `laps` times back to back with period (last -
/// first time + one original sample spacing). InputError if rate_hz <= 0 or laps < 1 or fewer than
/// 2 samples.
///
/// With laps == 1 the grid covers [first, last] time: floor((last - first) * rate_hz) + 1 samples
/// at first + k / rate_hz. With laps > 1 each lap has floor(period * rate_hz) samples at
/// first + l * period + k / rate_hz, taking the values at first + k / rate_hz (held at the last
/// sample past the end of the log). Also InputError if the channels and times differ in length or
/// are not finite, the times are not strictly increasing, or the result would have fewer than 2
/// samples.
ReplayInputs ResampleReplayInputs(const ReplayInputs& in, double rate_hz, int laps = 1);

/// Peak, time-weighted mean and final value of one history (trapezoidal time average).
struct HistoryStats {
  double peak = 0.0;
  double mean = 0.0;
  double final = 0.0;
};
HistoryStats CalcHistoryStats(const std::vector<double>& time, const std::vector<double>& values);

/// What a replay did to one corner: its temperatures' statistics (K), the wear at the end (mm),
/// the lowest grip factor and the brake's work over the run (trapezoid of the brake power, J).
struct CornerReplaySummary {
  HistoryStats tread, carcass, disc, calliper;
  /// The gas-and-rim tyre's gas, rim and hot gauge pressure (Pa); the bulk disc's bulk; all zero
  /// where the models have none.
  HistoryStats gas, rim, pressure, disc_bulk;
  double final_wear_mm = 0.0;
  double min_grip_factor = 0.0;
  double brake_energy_J = 0.0;
};

/// The four corners' summaries (fl, fr, rl, rr) of a replay, as `hotlap replay` prints them.
std::array<CornerReplaySummary, 4> SummarizeReplay(const ReplayResult& result);

}  // namespace hotlap::sim
