#include "hotlap/observe/corner_filter.h"

#include <cmath>
#include <type_traits>
#include <utility>

#include <fmt/format.h>

#include "hotlap/common/error.h"

namespace hotlap::observe {

namespace {

// The state-independent terms of one input, computed once in double (as replay does) and lifted
// into Jet arithmetic with zero derivative parts: the terms do not depend on the state, so the
// Jacobian needs no derivatives through them. p5 enters the state-dependent part only through
// tread_to_carcass (000:20), which is multiplied by the p5 factor state.
// Only the terms CalcTyreDerivatives reads beside the state are lifted (the heat flows and the
// wear rate from terms, tyre_thermal.cc); tests/observe/corner_filter_test.cc checks the
// prediction against replay, so a model that starts reading another term fails there.
template <class J>
tyre::TyreInputTerms<J> Lift(const tyre::TyreInputTerms<double>& t, const J& p5_scale) {
  tyre::TyreInputTerms<J> j;
  j.input.ambient_temp = J(t.input.ambient_temp);
  j.input.track_temp = J(t.input.track_temp);
  j.q1 = J(t.q1);
  j.q2 = J(t.q2);
  j.convection_factor = J(t.convection_factor);
  j.track_conductance = J(t.track_conductance);
  j.tread_to_carcass = t.tread_to_carcass * p5_scale;
  j.tread_radiation = J(t.tread_radiation);
  j.sidewall_radiation = J(t.sidewall_radiation);
  j.ambient_temp4 = J(t.ambient_temp4);
  j.inv_tread_capacity = J(t.inv_tread_capacity);
  j.inv_carcass_capacity = J(t.inv_carcass_capacity);
  j.wear_rate_factor = J(t.wear_rate_factor);
  return j;
}

template <class J>
brake::BrakeInputTerms<J> Lift(const brake::BrakeInputTerms<double>& t) {
  brake::BrakeInputTerms<J> j;
  j.input = {J(t.input.speed), J(t.input.fx), J(t.input.cooling_air_temp)};
  j.power = J(t.power);
  j.disc_at_speed = {J(t.disc_at_speed.a), J(t.disc_at_speed.b)};
  j.calliper_at_speed = {J(t.calliper_at_speed.a), J(t.calliper_at_speed.b)};
  j.cooling_air_temp4 = J(t.cooling_air_temp4);
  j.constants.pad_conductance = J(t.constants.pad_conductance);
  j.constants.disc_radiation = J(t.constants.disc_radiation);
  j.constants.calliper_radiation = J(t.constants.calliper_radiation);
  j.constants.inv_disc_capacity = J(t.constants.inv_disc_capacity);
  j.constants.inv_calliper_capacity = J(t.constants.inv_calliper_capacity);
  return j;
}

void CheckTemperature(double temp, const char* what, double time) {
  if (!(temp > 0.0 && temp < 3000.0)) {
    throw NumericalError(fmt::format(
        "observer diverged: predicted {} temperature is {:g} K at t = {:g} s; check the inputs "
        "(forces, speeds) and the parameters",
        what, temp, time));
  }
}

}  // namespace

TyreFilter::TyreFilter(const tyre::TyreThermalParams<double>& params,
                       std::shared_ptr<const tyre::TyreCompound> compound,
                       const ProcessNoise& process, const P5Scale& p5_scale, double max_step_s)
    : with_p5_(p5_scale.estimate),
      params_(params),
      params_jet2_(params.Cast<Jet2>()),
      params_jet5_(params.Cast<Jet5>()),
      constants_(tyre::CalcTyreConstants(params)),
      compound_(std::move(compound)),
      max_step_s_(max_step_s) {
  const double p5_sigma = with_p5_ ? p5_scale.random_walk_per_sqrt_s : 0.0;
  q_ << process.tread_temp, process.carcass_temp, process.wear, p5_sigma * p5_sigma;
}

tyre::TyreInputTerms<double> TyreFilter::StartTerms(const tyre::TyreInput<double>& in) {
  const tyre::TyreInput<double>& e = end_terms_.input;
  if (have_end_terms_ && e.speed == in.speed && e.fx == in.fx && e.fy == in.fy && e.fz == in.fz &&
      e.slip_angle == in.slip_angle && e.slip_ratio == in.slip_ratio &&
      e.ambient_temp == in.ambient_temp && e.track_temp == in.track_temp) {
    return end_terms_;
  }
  return tyre::CalcTyreInputTerms<double>(params_, constants_, *compound_, in, nullptr);
}

void TyreFilter::Predict(const sim::CornerSamples& in) {
  if (with_p5_) {
    PredictWith<Jet5>(in, params_jet5_);
  } else {
    PredictWith<Jet2>(in, params_jet2_);
  }
}

template <class J>
void TyreFilter::PredictWith(const sim::CornerSamples& in, const tyre::TyreThermalParams<J>& p) {
  constexpr bool kFull = std::is_same_v<J, Jet5>;
  // The Jet slot of each state; the p5 factor only in the full path.
  constexpr int kSlots = kFull ? kStates : 2;
  // Terms in double (for the next stage's series, as replay) and lifted.
  struct Terms {
    tyre::TyreInputTerms<double> value;
    tyre::TyreInputTerms<J> jet;
  };
  const J p5_scale = kFull ? J(x_.mean(kP5Scale), kP5Scale) : J(1.0);
  const auto terms_at = [&](size_t k, double f, const Terms* near) {
    Terms t;
    const tyre::TyreInput<double> input = in.TyreInputAt<double>(k, f);
    t.value = k == 0 && f == 0.0
                  ? StartTerms(input)
                  : tyre::CalcTyreInputTerms(params_, constants_, *compound_, input,
                                             near != nullptr ? &near->value : nullptr);
    t.jet = Lift<J>(t.value, p5_scale);
    return t;
  };
  const auto derivative = [&](const tyre::TyreState<J>& x, const Terms& t) {
    return tyre::CalcTyreDerivatives(p, *compound_, x, t.jet);
  };
  const tyre::TyreState<J> start{J(x_.mean(kTread), kTread), J(x_.mean(kCarcass), kCarcass),
                                 kFull ? J(x_.mean(kWear), kWear) : J(x_.mean(kWear))};
  tyre::TyreState<J> end = start;
  // The last stage's terms are kept for the next interval's start.
  const auto terms_kept = [&](size_t k, double f, const Terms* near) {
    Terms t = terms_at(k, f, near);
    if (k == 1) end_terms_ = t.value;
    return t;
  };
  sim::IntegrateOverSamples(in, start, max_step_s_, terms_kept, derivative,
                            [&](size_t k, const tyre::TyreState<J>& x) {
                              if (k == 1) end = x;
                            });
  have_end_terms_ = true;
  const J* rows[3] = {&end.tread_temp, &end.carcass_temp, &end.wear};
  f_.setIdentity();
  for (int i = 0; i < 3; ++i) {
    x_.mean(i) = rows[i]->a;
    for (int j = 0; j < kSlots; ++j) {
      if (kFull || j < 2) f_(i, j) = rows[i]->v[j];
    }
  }
  CheckTemperature(x_.mean(kTread), "tread", in.time[1]);
  CheckTemperature(x_.mean(kCarcass), "carcass", in.time[1]);
  const double dt = in.time[1] - in.time[0];
  x_.cov = f_ * x_.cov * f_.transpose();
  x_.cov.diagonal() += q_ * dt;
}

BrakeFilter::BrakeFilter(const brake::BrakeThermalParams<double>& params,
                         const ProcessNoise& process, double max_step_s)
    : params_(params),
      params_jet_(params.Cast<Jet2>()),
      constants_(brake::CalcBrakeConstants(params)),
      max_step_s_(max_step_s) {
  q_ << process.disc_temp, process.calliper_temp;
}

void BrakeFilter::Predict(const sim::CornerSamples& in) {
  using J = Jet2;
  const auto terms_at = [&](size_t k, double f, const brake::BrakeInputTerms<J>*) {
    const brake::BrakeInput<double> input = in.BrakeInputAt<double>(k, f);
    const brake::BrakeInput<double>& e = end_terms_.input;
    // The start is the last interval's end when the inputs are the same (consecutive samples).
    if (k == 0 && f == 0.0 && have_end_terms_ && e.speed == input.speed && e.fx == input.fx &&
        e.cooling_air_temp == input.cooling_air_temp) {
      return Lift<J>(end_terms_);
    }
    const brake::BrakeInputTerms<double> t = brake::CalcBrakeInputTerms(params_, constants_, input);
    if (k == 1) end_terms_ = t;
    return Lift<J>(t);
  };
  const auto derivative = [&](const brake::BrakeState<J>& x, const brake::BrakeInputTerms<J>& t) {
    return brake::CalcBrakeDerivatives(params_jet_, x, t);
  };
  const brake::BrakeState<J> start{J(x_.mean(kDisc), kDisc), J(x_.mean(kCalliper), kCalliper)};
  brake::BrakeState<J> end = start;
  sim::IntegrateOverSamples(in, start, max_step_s_, terms_at, derivative,
                            [&](size_t k, const brake::BrakeState<J>& x) {
                              if (k == 1) end = x;
                            });
  have_end_terms_ = true;
  const J* rows[2] = {&end.disc_temp, &end.calliper_temp};
  for (int i = 0; i < kStates; ++i) {
    x_.mean(i) = rows[i]->a;
    for (int j = 0; j < kStates; ++j) f_(i, j) = rows[i]->v[j];
  }
  CheckTemperature(x_.mean(kDisc), "disc", in.time[1]);
  CheckTemperature(x_.mean(kCalliper), "calliper", in.time[1]);
  const double dt = in.time[1] - in.time[0];
  x_.cov = f_ * x_.cov * f_.transpose();
  x_.cov.diagonal() += q_ * dt;
}

}  // namespace hotlap::observe
