#pragma once
/// @file
/// Inputs given at sample times and taken as linear between samples, and the loop that
/// integrates one corner's tyre or brake model over them with RK4 sub-steps. Templated on the
/// scalar so fitting can differentiate a whole replay with respect to the parameters.

#include <algorithm>
#include <cmath>
#include <span>

#include "hotlap/brake/brake_thermal.h"
#include "hotlap/common/rk4.h"
#include "hotlap/common/scalar.h"
#include "hotlap/tyre/tyre_thermal.h"

namespace hotlap::sim {

/// One corner's measured inputs at the sample times, SI (K for temperatures). All spans have the
/// length of `time`, which is strictly increasing.
struct CornerSamples {
  std::span<const double> time;
  std::span<const double> speed;
  std::span<const double> fx;
  std::span<const double> fy;
  std::span<const double> fz;
  std::span<const double> slip_angle;
  std::span<const double> slip_ratio;
  std::span<const double> ambient_temp;
  std::span<const double> track_temp;

  /// Tyre input at sample k moved a fraction `f` in [0, 1] towards sample k+1.
  template <Scalar T>
  tyre::TyreInput<T> TyreInputAt(size_t k, double f) const {
    const size_t j = std::min(k + 1, time.size() - 1);
    const auto lerp = [&](std::span<const double> v) { return T(v[k] + f * (v[j] - v[k])); };
    return {lerp(speed), lerp(fx),        lerp(fy),           lerp(fz),
            lerp(slip_angle), lerp(slip_ratio), lerp(ambient_temp), lerp(track_temp)};
  }
  /// Brake input at sample k moved a fraction `f` towards sample k+1 (cooling air = ambient).
  template <Scalar T>
  brake::BrakeInput<T> BrakeInputAt(size_t k, double f) const {
    const size_t j = std::min(k + 1, time.size() - 1);
    const auto lerp = [&](std::span<const double> v) { return T(v[k] + f * (v[j] - v[k])); };
    return {lerp(speed), lerp(fx), lerp(ambient_temp)};
  }
};

/// Number of equal RK4 sub-steps for the interval [t_k, t_k+1] so that none exceeds max_step.
inline int SubStepsFor(double interval, double max_step) {
  return std::max(1, static_cast<int>(std::ceil(interval / max_step - 1e-9)));
}

/// Integrates `derivative(state, input)` over the samples from `state` at time[0]; calls
/// `on_sample(k, state)` for every sample k, the first with the initial state. `input_at(k, f)`
/// gives the input a fraction f of the way from sample k to k+1.
template <class State, class InputAt, class Derivative, class OnSample>
void IntegrateOverSamples(std::span<const double> time, State state, double max_step,
                          InputAt&& input_at, Derivative&& derivative, OnSample&& on_sample) {
  on_sample(size_t{0}, state);
  for (size_t k = 0; k + 1 < time.size(); ++k) {
    const double interval = time[k + 1] - time[k];
    const int n = SubStepsFor(interval, max_step);
    // In-interval time is measured as the fraction of the interval, so the inputs at the RK4
    // stages are exact linear interpolations.
    const auto f = [&](double fraction, const State& x) {
      return derivative(x, input_at(k, fraction));
    };
    const double fraction_step = 1.0 / n;
    for (int i = 0; i < n; ++i) {
      // Rk4Step in the fraction variable: scale the derivative by the interval length.
      state = Rk4Step([&](double fr, const State& x) { return interval * f(fr, x); },
                      i * fraction_step, state, fraction_step);
    }
    on_sample(k + 1, state);
  }
}

/// Integrates one tyre over the samples; `on_sample(k, state)` as above.
template <Scalar T, class OnSample>
void IntegrateTyre(const tyre::TyreThermalParams<T>& params, const tyre::TyreCompound& compound,
                   const CornerSamples& in, const tyre::TyreState<T>& initial, double max_step,
                   OnSample&& on_sample) {
  IntegrateOverSamples(
      in.time, initial, max_step,
      [&](size_t k, double f) { return in.TyreInputAt<T>(k, f); },
      [&](const tyre::TyreState<T>& x, const tyre::TyreInput<T>& u) {
        return tyre::CalcTyreDerivatives(params, compound, x, u);
      },
      on_sample);
}

/// Integrates one brake over the samples; `on_sample(k, state)` as above.
template <Scalar T, class OnSample>
void IntegrateBrake(const brake::BrakeThermalParams<T>& params, const CornerSamples& in,
                    const brake::BrakeState<T>& initial, double max_step, OnSample&& on_sample) {
  IntegrateOverSamples(
      in.time, initial, max_step, [&](size_t k, double f) { return in.BrakeInputAt<T>(k, f); },
      [&](const brake::BrakeState<T>& x, const brake::BrakeInput<T>& u) {
        return brake::CalcBrakeDerivatives(params, x, u);
      },
      on_sample);
}

}  // namespace hotlap::sim
