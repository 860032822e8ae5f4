#pragma once
/// @file
/// Extended Kalman filters of one corner's tyre (tread, carcass, wear and an optional factor on
/// p5) and brake (disc, calliper), on the very models and integrator `hotlap replay` uses.
///
/// How to use: Reset() with the starting mean and covariance, then for every new sample call
/// Predict() over the interval from the previous sample (a two-sample sim::CornerSamples: inputs
/// linear between them, as replay takes them) and Update() with each reading that is present.
///
/// The prediction integrates the state with sim::IntegrateOverSamples (RK4 sub-steps no longer
/// than max_step_s, split where an input the model takes |x| or max(x, 0) of changes sign), in
/// ceres::Jet arithmetic seeded with the identity: the Jet parts of the result are the exact
/// Jacobian F = d x(t1) / d x(t0) of that discrete map (no finite differences, no linearised
/// continuous-time model). The covariance follows P <- F P F' + Q dt (ProcessNoise: continuous
/// white noise on the derivatives, added over the interval to first order in dt; docs/observer.md).
///
/// Sensor lag: with a time constant > 0 a sensor's reading is taken as a first-order lag of its
/// state (sensor_lag.h), carried as an extra state beside the model's; with 0 (the default) the
/// reading is the state itself. A lagging sensor taken as unlagged trails the state by its time
/// constant, which shows as disagreement.

#include <algorithm>
#include <array>
#include <memory>

#include <Eigen/Core>

#include "hotlap/brake/brake_thermal.h"
#include "hotlap/observe/observer_config.h"
#include "hotlap/observe/sensor_lag.h"
#include "hotlap/sim/sampled_inputs.h"
#include "hotlap/tyre/compound.h"
#include "hotlap/tyre/tyre_thermal.h"

namespace hotlap::observe {

/// What a scalar reading did to the filter.
struct UpdateOutcome {
  bool used = false;        ///< the state was corrected with it
  bool rejected = false;    ///< beyond the innovation gate: not used
  double innovation = 0.0;  ///< reading minus prediction, K
  double nis = 0.0;         ///< normalised innovation squared, innovation^2 / S (chi-square, 1 dof)
};

/// Mean and covariance of N states.
template <int N>
struct Gaussian {
  Eigen::Matrix<double, N, 1> mean = Eigen::Matrix<double, N, 1>::Zero();
  Eigen::Matrix<double, N, N> cov = Eigen::Matrix<double, N, N>::Zero();
};

/// The Kalman update for a reading `z` of state `index` (H = e_index') with variance `r`: rejected
/// when the normalised innovation squared exceeds gate_nis, else x += k nu, P -= S k k' with
/// k = P e_index / S: the rank-one form, symmetric by construction, and for a scalar reading the
/// same as the Joseph form (P - k k' S = (I - k H) P (I - k H)' + r k k') to rounding.
template <int N>
UpdateOutcome UpdateScalar(Gaussian<N>& g, int index, double z, double r, double gate_nis) {
  UpdateOutcome out;
  const double s = g.cov(index, index) + r;
  out.innovation = z - g.mean(index);
  out.nis = out.innovation * out.innovation / s;
  if (!(out.nis <= gate_nis)) {
    out.rejected = true;
    return out;
  }
  const Eigen::Matrix<double, N, 1> k = g.cov.col(index) / s;
  g.mean += k * out.innovation;
  g.cov.noalias() -= (s * k) * k.transpose();
  // The read state's variance cannot go below zero however the rounding falls.
  g.cov(index, index) = std::max(g.cov(index, index), 0.0);
  out.used = true;
  return out;
}

/// The tyre filter: states tread temperature K, carcass temperature K, wear mm, p5 factor 1.
/// Without the p5 state (P5Scale::estimate false) the factor stays exactly 1 with zero variance.
class TyreFilter {
 public:
  static constexpr int kTread = 0, kCarcass = 1, kWear = 2, kP5Scale = 3, kStates = 4;

  /// `tread_lag_s`: the tread sensor's time constant (0: no lag).
  TyreFilter(const tyre::TyreThermalParams<double>& params,
             std::shared_ptr<const tyre::TyreCompound> compound, const ProcessNoise& process,
             const P5Scale& p5_scale, double max_step_s, double tread_lag_s = 0.0);

  /// The states; a lagging sensor starts settled (reading its state).
  void Reset(const Gaussian<kStates>& start) {
    x_ = start;
    lag_.Reset(x_);
  }
  /// From samples.time[0] to samples.time[1] (two samples). NumericalError if a temperature leaves
  /// (0 K, 3000 K).
  void Predict(const sim::CornerSamples& samples);
  /// A tread temperature reading, K, with standard deviation sd_K.
  UpdateOutcome UpdateTread(double reading_K, double sd_K, double gate_nis) {
    if (lag_.Active()) return lag_.Update<UpdateOutcome>(x_, 0, reading_K, sd_K * sd_K, gate_nis);
    return UpdateScalar(x_, kTread, reading_K, sd_K * sd_K, gate_nis);
  }
  const Gaussian<kStates>& estimate() const { return x_; }
  /// The tread sensor's lag state (Active() false without a lag).
  const SensorLags<kStates, 1>& lag() const { return lag_; }
  /// The Jacobian of the last Predict().
  const Eigen::Matrix<double, kStates, kStates>& transition() const { return f_; }

 private:
  // Predict in Jet arithmetic of type J: Jet2 (tread, carcass) without the p5 state, Jet5 (tread,
  // carcass, wear, p5) with it. Wear enters no derivative (000:7-8, 23), so its column of F is
  // e_wear either way; tests check this against the Jet5 path.
  template <class J>
  void PredictWith(const sim::CornerSamples& samples, const tyre::TyreThermalParams<J>& params);
  // The input terms at the start of the interval: the last interval's end terms when its inputs
  // are those (consecutive samples), as replay reuses them; computed otherwise.
  tyre::TyreInputTerms<double> StartTerms(const tyre::TyreInput<double>& input);

  // The input terms of one stage, in double and lifted into J. The integrator holds at most three
  // stages' terms at a time (start, middle, end) and creates them in turn, so four slots used
  // round robin never overwrite a live one; the integrator passes small handles instead of
  // copying the terms.
  template <class J>
  struct TermSlot {
    tyre::TyreInputTerms<double> value;
    tyre::TyreInputTerms<J> jet;
  };
  template <class J>
  struct TermHandle {
    const TermSlot<J>* slot = nullptr;
  };
  std::array<TermSlot<Jet2>, 4> slots2_;
  std::array<TermSlot<Jet5>, 4> slots5_;
  int next_slot_ = 0;

  bool with_p5_;
  tyre::TyreThermalParams<double> params_;
  tyre::TyreThermalParams<Jet2> params_jet2_;
  tyre::TyreThermalParams<Jet5> params_jet5_;
  tyre::TyreConstants<double> constants_;
  bool have_end_terms_ = false;
  tyre::TyreInputTerms<double> end_terms_;
  std::shared_ptr<const tyre::TyreCompound> compound_;
  Eigen::Matrix<double, kStates, 1> q_;  // continuous intensities
  double max_step_s_;
  Gaussian<kStates> x_;
  Eigen::Matrix<double, kStates, kStates> f_ = Eigen::Matrix<double, kStates, kStates>::Identity();
  SensorLags<kStates, 1> lag_;
};

/// The brake filter: states disc temperature K, calliper temperature K.
class BrakeFilter {
 public:
  static constexpr int kDisc = 0, kCalliper = 1, kStates = 2;

  /// `disc_lag_s`, `calliper_lag_s`: the sensors' time constants (0: no lag).
  BrakeFilter(const brake::BrakeThermalParams<double>& params, const ProcessNoise& process,
              double max_step_s, double disc_lag_s = 0.0, double calliper_lag_s = 0.0);

  void Reset(const Gaussian<kStates>& start) {
    x_ = start;
    lag_.Reset(x_);
  }
  /// As TyreFilter::Predict.
  void Predict(const sim::CornerSamples& samples);
  UpdateOutcome UpdateDisc(double reading_K, double sd_K, double gate_nis) {
    if (lag_.Active()) return lag_.Update<UpdateOutcome>(x_, 0, reading_K, sd_K * sd_K, gate_nis);
    return UpdateScalar(x_, kDisc, reading_K, sd_K * sd_K, gate_nis);
  }
  UpdateOutcome UpdateCalliper(double reading_K, double sd_K, double gate_nis) {
    if (lag_.Active()) return lag_.Update<UpdateOutcome>(x_, 1, reading_K, sd_K * sd_K, gate_nis);
    return UpdateScalar(x_, kCalliper, reading_K, sd_K * sd_K, gate_nis);
  }
  const Gaussian<kStates>& estimate() const { return x_; }
  /// The disc (0) and calliper (1) sensors' lag states (Active() false without a lag).
  const SensorLags<kStates, 2>& lag() const { return lag_; }
  const Eigen::Matrix<double, kStates, kStates>& transition() const { return f_; }

 private:
  brake::BrakeThermalParams<double> params_;
  brake::BrakeThermalParams<Jet2> params_jet_;
  brake::BrakeConstants<double> constants_;
  bool have_end_terms_ = false;
  brake::BrakeInputTerms<double> end_terms_;
  // The lifted terms of the stages, used round robin (as TyreFilter's).
  std::array<brake::BrakeInputTerms<Jet2>, 4> slots_;
  int next_slot_ = 0;
  Eigen::Matrix<double, kStates, 1> q_;
  double max_step_s_;
  Gaussian<kStates> x_;
  Eigen::Matrix<double, kStates, kStates> f_ = Eigen::Matrix<double, kStates, kStates>::Identity();
  SensorLags<kStates, 2> lag_;
};

}  // namespace hotlap::observe
