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
void LiftInto(const tyre::TyreInputTerms<double>& t, const J& p5_scale,
              tyre::TyreInputTerms<J>& j) {
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
}

// The state-independent, input-dependent brake terms lifted into `j`, whose parameter-only
// constants are already set (LiftConstants).
template <class J>
void LiftInto(const brake::BrakeInputTerms<double>& t, brake::BrakeInputTerms<J>& j) {
  j.input = {J(t.input.speed), J(t.input.fx), J(t.input.cooling_air_temp)};
  j.power = J(t.power);
  j.disc_at_speed = {J(t.disc_at_speed.a), J(t.disc_at_speed.b)};
  j.calliper_at_speed = {J(t.calliper_at_speed.a), J(t.calliper_at_speed.b)};
  j.cooling_air_temp4 = J(t.cooling_air_temp4);
}

template <class J>
void LiftConstants(const brake::BrakeConstants<double>& c, brake::BrakeInputTerms<J>& j) {
  j.constants.pad_conductance = J(c.pad_conductance);
  j.constants.disc_radiation = J(c.disc_radiation);
  j.constants.calliper_radiation = J(c.calliper_radiation);
  j.constants.inv_disc_capacity = J(c.inv_disc_capacity);
  j.constants.inv_calliper_capacity = J(c.inv_calliper_capacity);
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

namespace {

// The filters' states are the paper's (docs/observer.md): a gas-and-rim tyre is observed as its
// paper part, a bulk disc as the lumped one.
tyre::TyreThermalParams<double> PaperPart(tyre::TyreThermalParams<double> p) {
  p.model = tyre::TyreThermalModel::kPaper;
  return p;
}
brake::BrakeThermalParams<double> LumpedPart(brake::BrakeThermalParams<double> p) {
  p.disc_model = brake::DiscModel::kLumped;
  return p;
}

}  // namespace

TyreFilter::TyreFilter(const tyre::TyreThermalParams<double>& params,
                       std::shared_ptr<const tyre::TyreCompound> compound,
                       const ProcessNoise& process, const P5Scale& p5_scale, double max_step_s,
                       double tread_lag_s)
    : with_p5_(p5_scale.estimate),
      params_(PaperPart(params)),
      params_jet2_(params_.Cast<Jet2>()),
      params_jet5_(params_.Cast<Jet5>()),
      constants_(tyre::CalcTyreConstants(params_)),
      compound_(std::move(compound)),
      max_step_s_(max_step_s),
      lag_({kTread}, {tread_lag_s}) {
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
  // Terms in double (for the next stage's series, as replay) and lifted, in the slot ring.
  using Terms = TermHandle<J>;
  std::array<TermSlot<J>, 4>* slots;
  if constexpr (kFull) {
    slots = &slots5_;
  } else {
    slots = &slots2_;
  }
  const J p5_scale = kFull ? J(x_.mean(kP5Scale), kP5Scale) : J(1.0);
  const auto terms_at = [&](size_t k, double f, const Terms* near) {
    TermSlot<J>& slot = (*slots)[next_slot_];
    next_slot_ = (next_slot_ + 1) % 4;
    const tyre::TyreInput<double> input = in.TyreInputAt<double>(k, f);
    slot.value = k == 0 && f == 0.0
                     ? StartTerms(input)
                     : tyre::CalcTyreInputTerms(params_, constants_, *compound_, input,
                                                near != nullptr ? &near->slot->value : nullptr);
    LiftInto(slot.value, p5_scale, slot.jet);
    // The last stage's terms are kept for the next interval's start.
    if (k == 1) end_terms_ = slot.value;
    return Terms{&slot};
  };
  const auto derivative = [&](const tyre::TyreState<J>& x, const Terms& t) {
    return tyre::CalcTyreDerivatives(p, *compound_, x, t.slot->jet);
  };
  const tyre::TyreState<J> start{J(x_.mean(kTread), kTread), J(x_.mean(kCarcass), kCarcass),
                                 kFull ? J(x_.mean(kWear), kWear) : J(x_.mean(kWear))};
  tyre::TyreState<J> end = start;
  sim::IntegrateOverSamples(in, start, max_step_s_, terms_at, derivative,
                            [&](size_t k, const tyre::TyreState<J>& x) {
                              if (k == 1) end = x;
                            });
  have_end_terms_ = true;
  // The states at the interval's start, for the sensor lag (only with one).
  const Gaussian<kStates> before = lag_.Active() ? x_ : Gaussian<kStates>{};
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
  if (lag_.Active()) {
    const Eigen::Matrix<double, kStates, 1> q_dt = q_ * dt;
    lag_.Predict(before, f_, x_.mean, q_dt, dt);
  }
  if constexpr (kFull) {
    x_.cov = (f_ * x_.cov * f_.transpose()).eval();
  } else {
    // Without the p5 state its row and column of P stay zero: the 3x3 block alone.
    const Eigen::Matrix3d f3 = f_.topLeftCorner<3, 3>();
    x_.cov.topLeftCorner<3, 3>() = (f3 * x_.cov.topLeftCorner<3, 3>() * f3.transpose()).eval();
  }
  x_.cov.diagonal() += q_ * dt;
}

BrakeFilter::BrakeFilter(const brake::BrakeThermalParams<double>& params,
                         const ProcessNoise& process, double max_step_s, double disc_lag_s,
                         double calliper_lag_s)
    : params_(LumpedPart(params)),
      params_jet_(params_.Cast<Jet2>()),
      constants_(brake::CalcBrakeConstants(params_)),
      max_step_s_(max_step_s),
      lag_({kDisc, kCalliper}, {disc_lag_s, calliper_lag_s}) {
  q_ << process.disc_temp, process.calliper_temp;
  for (brake::BrakeInputTerms<Jet2>& slot : slots_) LiftConstants(constants_, slot);
}

void BrakeFilter::Predict(const sim::CornerSamples& in) {
  using J = Jet2;
  // Handles into the slot ring (as the tyre's); the parameter-only constants were lifted once.
  struct Terms {
    const brake::BrakeInputTerms<J>* slot = nullptr;
  };
  const auto terms_at = [&](size_t k, double f, const Terms*) {
    brake::BrakeInputTerms<J>& slot = slots_[next_slot_];
    next_slot_ = (next_slot_ + 1) % 4;
    const brake::BrakeInput<double> input = in.BrakeInputAt<double>(k, f);
    const brake::BrakeInput<double>& e = end_terms_.input;
    // The start is the last interval's end when the inputs are the same (consecutive samples).
    const bool reuse = k == 0 && f == 0.0 && have_end_terms_ && e.speed == input.speed &&
                       e.fx == input.fx && e.cooling_air_temp == input.cooling_air_temp;
    const brake::BrakeInputTerms<double> t =
        reuse ? end_terms_ : brake::CalcBrakeInputTerms(params_, constants_, input);
    if (k == 1) end_terms_ = t;
    LiftInto(t, slot);
    return Terms{&slot};
  };
  const auto derivative = [&](const brake::BrakeState<J>& x, const Terms& t) {
    return brake::CalcBrakeDerivatives(params_jet_, x, *t.slot);
  };
  const brake::BrakeState<J> start{J(x_.mean(kDisc), kDisc), J(x_.mean(kCalliper), kCalliper)};
  brake::BrakeState<J> end = start;
  sim::IntegrateOverSamples(in, start, max_step_s_, terms_at, derivative,
                            [&](size_t k, const brake::BrakeState<J>& x) {
                              if (k == 1) end = x;
                            });
  have_end_terms_ = true;
  const Gaussian<kStates> before = lag_.Active() ? x_ : Gaussian<kStates>{};
  const J* rows[2] = {&end.disc_temp, &end.calliper_temp};
  for (int i = 0; i < kStates; ++i) {
    x_.mean(i) = rows[i]->a;
    for (int j = 0; j < kStates; ++j) f_(i, j) = rows[i]->v[j];
  }
  CheckTemperature(x_.mean(kDisc), "disc", in.time[1]);
  CheckTemperature(x_.mean(kCalliper), "calliper", in.time[1]);
  const double dt = in.time[1] - in.time[0];
  if (lag_.Active()) {
    const Eigen::Matrix<double, kStates, 1> q_dt = q_ * dt;
    lag_.Predict(before, f_, x_.mean, q_dt, dt);
  }
  x_.cov = f_ * x_.cov * f_.transpose();
  x_.cov.diagonal() += q_ * dt;
}

}  // namespace hotlap::observe
