#pragma once
/// @file
/// Inputs given at sample times and taken as linear between samples, and the loop that
/// integrates one corner's tyre or brake model over them with RK4 sub-steps. Templated on the
/// scalar so fitting can differentiate a whole replay with respect to the parameters.

#include <algorithm>
#include <array>
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
    return {lerp(speed),      lerp(fx),         lerp(fy),           lerp(fz),
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

/// Number of equal RK4 sub-steps for a stretch of `length` so that none exceeds max_step.
inline int SubStepsFor(double length, double max_step) {
  return std::max(1, static_cast<int>(std::ceil(length / max_step - 1e-9)));
}

/// Fractions in (0, 1), sorted, where an input that the models take |x| or max(x, 0) of crosses
/// zero between samples k and k+1 (speed, fx, fy, slip angle, slip ratio). The models' right-hand
/// sides have a kink there, which would cost RK4 its order; the integrator steps onto it instead.
struct Kinks {
  std::array<double, 10> at{};
  int count = 0;

  /// Inserts `fraction` in order, once (a kink two sample sets share is one kink).
  void Add(double fraction) {
    for (int i = 0; i < count; ++i) {
      if (at[i] == fraction) return;
    }
    if (count == static_cast<int>(at.size())) return;
    int i = count++;
    for (; i > 0 && at[i - 1] > fraction; --i) at[i] = at[i - 1];
    at[i] = fraction;
  }
};

/// The kinks of `in` between samples k and k+1; with `also`, those of its inputs too (a tyre and
/// its brake integrated together: the brake's force may cross zero elsewhere).
inline Kinks KinksBetween(const CornerSamples& in, size_t k, const CornerSamples* also = nullptr) {
  Kinks kinks;
  const size_t j = k + 1;
  for (const CornerSamples* s : {&in, also}) {
    if (s == nullptr) continue;
    for (std::span<const double> v : {s->speed, s->fx, s->fy, s->slip_angle, s->slip_ratio}) {
      const double a = v[k], b = v[j];
      const bool crosses = (a < 0.0 && b > 0.0) || (a > 0.0 && b < 0.0);
      if (crosses) kinks.Add(a / (a - b));
    }
  }
  return kinks;
}

/// Integrates `derivative(state, terms)` over the samples from `state` at time[0]; calls
/// `on_sample(k, state)` for every sample k, the first with the initial state.
/// `terms_at(k, f, near)` gives the model's input terms a fraction f of the way from sample k to
/// k+1, and may reuse parts of `near` (the previous stage's terms, or null). Each interval is
/// split at the kinks of `samples` and every piece is covered by RK4 steps no longer than
/// max_step; the input terms are computed once per distinct stage time (a step's end is the next
/// step's start, across samples too). With `also_kinks`, its kinks are stepped onto as well.
template <class State, class TermsAt, class Derivative, class OnSample>
void IntegrateOverSamples(const CornerSamples& samples, State state, double max_step,
                          TermsAt&& terms_at, Derivative&& derivative, OnSample&& on_sample,
                          const CornerSamples* also_kinks = nullptr) {
  const std::span<const double> time = samples.time;
  on_sample(size_t{0}, state);
  auto start = terms_at(size_t{0}, 0.0, nullptr);
  for (size_t k = 0; k + 1 < time.size(); ++k) {
    const double interval = time[k + 1] - time[k];
    // Time inside the interval is measured as the fraction of it, so the inputs at the RK4 stages
    // are exact linear interpolations; the derivative is scaled by the interval length.
    const auto f = [&](const State& x, const auto& terms) {
      return interval * derivative(x, terms);
    };
    const Kinks kinks = KinksBetween(samples, k, also_kinks);
    double from = 0.0;
    for (int piece = 0; piece <= kinks.count; ++piece) {
      const double to = piece < kinks.count ? kinks.at[piece] : 1.0;
      if (to <= from) continue;
      const double length = (to - from) * interval;
      const int n = length <= max_step ? 1 : SubStepsFor(length, max_step);
      const double step = (to - from) / n;
      for (int i = 0; i < n; ++i) {
        const double a = from + i * step;
        const auto middle = terms_at(k, a + 0.5 * step, &start);
        const bool last = i + 1 == n;
        // The interval's end is exactly sample k+1, which starts the next interval.
        auto end = last && to == 1.0 ? terms_at(k + 1, 0.0, &middle)
                                     : terms_at(k, last ? to : a + step, &middle);
        state = Rk4StepWithInputs(f, state, step, start, middle, end);
        start = std::move(end);
      }
      from = to;
    }
    on_sample(k + 1, state);
  }
}

/// A state with energy accumulators (J) integrated beside it by the same Runge-Kutta stages, so
/// that the accumulated heat flows are exactly the integrator's own (sim/energy_audit.h).
template <class State, size_t N>
struct WithEnergies {
  State x;
  std::array<double, N> e{};

  friend WithEnergies operator+(const WithEnergies& a, const WithEnergies& b) {
    WithEnergies r{a.x + b.x, {}};
    for (size_t i = 0; i < N; ++i) r.e[i] = a.e[i] + b.e[i];
    return r;
  }
  friend WithEnergies operator*(double k, const WithEnergies& a) {
    WithEnergies r{k * a.x, {}};
    for (size_t i = 0; i < N; ++i) r.e[i] = k * a.e[i];
    return r;
  }
};

/// A tyre and its brake integrated together (the gas-and-rim tyre's rim takes the brake's heat).
template <Scalar T>
struct WheelState {
  tyre::TyreState<T> tyre;
  brake::BrakeState<T> brake;

  friend WheelState operator+(const WheelState& a, const WheelState& b) {
    return {a.tyre + b.tyre, a.brake + b.brake};
  }
  friend WheelState operator*(double k, const WheelState& a) { return {k * a.tyre, k * a.brake}; }
};

/// Integrates one tyre over the samples; `on_sample(k, state)` as above.
template <Scalar T, class OnSample>
void IntegrateTyre(const tyre::TyreThermalParams<T>& params, const tyre::TyreCompound& compound,
                   const CornerSamples& in, const tyre::TyreState<T>& initial, double max_step,
                   OnSample&& on_sample) {
  const tyre::TyreConstants<T> constants = tyre::CalcTyreConstants(params);
  IntegrateOverSamples(
      in, initial, max_step,
      [&](size_t k, double f, const tyre::TyreInputTerms<T>* near) {
        return tyre::CalcTyreInputTerms(params, constants, compound, in.TyreInputAt<T>(k, f), near);
      },
      [&](const tyre::TyreState<T>& x, const tyre::TyreInputTerms<T>& terms) {
        return tyre::CalcTyreDerivatives(params, compound, x, terms);
      },
      on_sample);
}

/// Integrates one brake over the samples; `on_sample(k, state)` as above.
template <Scalar T, class OnSample>
void IntegrateBrake(const brake::BrakeThermalParams<T>& params, const CornerSamples& in,
                    const brake::BrakeState<T>& initial, double max_step, OnSample&& on_sample) {
  const brake::BrakeConstants<T> constants = brake::CalcBrakeConstants(params);
  IntegrateOverSamples(
      in, initial, max_step,
      [&](size_t k, double f, const brake::BrakeInputTerms<T>*) {
        return brake::CalcBrakeInputTerms(params, constants, in.BrakeInputAt<T>(k, f));
      },
      [&](const brake::BrakeState<T>& x, const brake::BrakeInputTerms<T>& terms) {
        return brake::CalcBrakeDerivatives(params, x, terms);
      },
      on_sample);
}

}  // namespace hotlap::sim
