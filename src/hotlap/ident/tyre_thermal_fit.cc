#include "hotlap/ident/tyre_thermal_fit.h"
#include "hotlap/common/special_values.h"

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <utility>

#include <fmt/format.h>

#include <Eigen/Dense>

#include "hotlap/common/error.h"
#include "hotlap/ident/bounded_least_squares.h"
#include "hotlap/ident/jet_predictor.h"
#include "hotlap/sim/synth_sensor.h"

namespace hotlap::ident {

namespace {

// Every parameter of the tyre model over a log; the fits free a subset.
enum Index : int { kP1, kP2, kP3, kP4, kP5, kWp1, kWp2, kTread0, kCarcass0, kWear0, kCount };
// Its channels.
enum Channel : int { kTread, kCarcass, kWear };

// The tyre model over one corner's logged inputs: the replay's integration (sampled_inputs.h),
// the sensor lag on the temperatures, the wear offset.
class TyreLogModel {
 public:
  TyreLogModel(const tyre::TyreFile& tyre, const sim::CornerSamples& samples, double max_step,
               double lag)
      : tyre_(tyre), samples_(samples), max_step_(max_step), lag_(lag) {}

  size_t num_samples() const { return samples_.time.size(); }
  int num_channels() const { return 3; }

  template <Scalar T, class Emit>
  void Run(std::span<const T> x, Emit&& emit) const {
    tyre::TyreThermalParams<T> p = tyre_.params.Cast<T>();
    p.p1 = x[kP1];
    p.p2 = x[kP2];
    p.p3 = x[kP3];
    p.p4 = x[kP4];
    p.p5 = x[kP5];
    p.wear_coeff = x[kWp1];
    p.wear_exponent = x[kWp2];
    sim::FirstOrderLag<T> tread_sensor(lag_), carcass_sensor(lag_);
    const tyre::TyreState<T> start{x[kTread0], x[kCarcass0], T(0.0)};
    sim::IntegrateTyre<T>(p, *tyre_.compound, samples_, start, max_step_,
                          [&](size_t k, const tyre::TyreState<T>& s) {
                            const double t = samples_.time[k];
                            emit(kTread, k, tread_sensor.Next(t, s.tread_temp));
                            emit(kCarcass, k, carcass_sensor.Next(t, s.carcass_temp));
                            emit(kWear, k, T(x[kWear0] + s.wear));
                          });
  }

 private:
  const tyre::TyreFile& tyre_;
  sim::CornerSamples samples_;
  double max_step_;
  double lag_;
};

// The wear law over the log at fixed thermal parameters, as the sum over the RK4 stages of the
// thermal integration: the wear never feeds back into the temperatures, so its integral is
// sum_i c_i wp1 w(T_t,i) (Q1_i / Q_ref)^wp2 with the stages' weights c_i, temperatures and
// sliding powers fixed. Recorded once from the replay's own integrator (an extra state that
// counts time gives the weights: stage 2 of a step starts half a step after stage 1), it equals
// the full integration to rounding at a small fraction of its cost.
class WearQuadratureModel {
 public:
  WearQuadratureModel(const tyre::TyreFile& tyre, const sim::CornerSamples& samples,
                      const std::vector<double>& all, double max_step) {
    tyre::TyreThermalParams<double> p = tyre.params;
    for (int i = kP1; i <= kP5; ++i) TyreFitFields()[i]->Of(p) = all[i];
    const tyre::TyreConstants<double> constants = tyre::CalcTyreConstants(p);
    const tyre::TyreCompound& compound = *tyre.compound;
    std::vector<double> clock;  // the time state on entry to each stage, s
    sim::IntegrateOverSamples(
        samples, tyre::TyreState<double>{all[kTread0], all[kCarcass0], 0.0}, max_step,
        [&](size_t k, double f, const tyre::TyreInputTerms<double>* near) {
          return tyre::CalcTyreInputTerms(p, constants, compound, samples.TyreInputAt<double>(k, f),
                                          near);
        },
        [&](const tyre::TyreState<double>& x, const tyre::TyreInputTerms<double>& terms) {
          tyre::TyreState<double> dx = tyre::CalcTyreDerivatives(p, compound, x, terms);
          clock.push_back(x.wear);
          rate_.push_back(compound.wear_rate.Evaluate(x.tread_temp));
          log_power_.push_back(terms.q1 > 0.0 ? std::log(terms.q1 / compound.wear_reference_power)
                                              : -std::numeric_limits<double>::infinity());
          dx.wear = 1.0;
          return dx;
        },
        [&](size_t, const tyre::TyreState<double>&) { end_of_sample_.push_back(clock.size()); });
    // Stages come four to a step in order; the clock gives the step (s) and so the weights.
    weight_.resize(clock.size());
    constexpr double kRk4[4] = {1.0, 2.0, 2.0, 1.0};
    for (size_t g = 0; g + 3 < clock.size(); g += 4) {
      const double step = 2.0 * (clock[g + 1] - clock[g]);
      for (int i = 0; i < 4; ++i) weight_[g + i] = step * kRk4[i] / 6.0;
    }
  }
  size_t num_samples() const { return end_of_sample_.size(); }
  int num_channels() const { return 3; }

  template <Scalar T, class Emit>
  void Run(std::span<const T> x, Emit&& emit) const {
    using std::exp;
    T sum(0.0);
    size_t stage = 0;
    for (size_t k = 0; k < end_of_sample_.size(); ++k) {
      for (; stage < end_of_sample_[k]; ++stage) {
        if (std::isfinite(log_power_[stage])) {
          sum += weight_[stage] * rate_[stage] * exp(x[kWp2] * log_power_[stage]);
        }
      }
      emit(kWear, k, T(x[kWear0] + x[kWp1] * sum));
    }
  }

 private:
  std::vector<double> weight_, rate_, log_power_;
  std::vector<size_t> end_of_sample_;
};

// The gas stage's parameters: the gas path's conductances (GasFitFields order), the rim's
// starting temperature. Its channels: the TPMS's.
enum GasIndex : int { kCarcassGas, kGasRim, kRimAir, kRim0, kGasCount };
enum GasChannel : int { kPressure, kGasTemp };

// The car's own gas-and-rim tyre over one corner's logged inputs, integrated with its brake as
// sim/replay.cc does (the rim takes the brake's heat, which depends on the rim's temperature),
// the TPMS lag on the pressure and gas temperature. The tread and carcass start where the thermal
// stage's data say; the brake where the log's first disc and calliper samples say.
class GasLogModel {
 public:
  GasLogModel(const tyre::TyreFile& tyre, const TyreCornerData& d, double tread0, double carcass0,
              double max_step, double lag)
      : tyre_(tyre),
        samples_(d.samples),
        brake_samples_(d.brake_samples),
        brake_(d.brake),
        brake_start_(d.brake_start),
        tread0_(tread0),
        carcass0_(carcass0),
        max_step_(max_step),
        lag_(lag) {}

  size_t num_samples() const { return samples_.time.size(); }
  int num_channels() const { return 2; }

  template <Scalar T, class Emit>
  void Run(std::span<const T> x, Emit&& emit) const {
    tyre::TyreThermalParams<T> p = tyre_.params.Cast<T>();
    p.carcass_gas_conductance = x[kCarcassGas];
    p.gas_rim_conductance = x[kGasRim];
    p.rim_air_conductance = x[kRimAir];
    sim::FirstOrderLag<T> pressure_sensor(lag_), gas_sensor(lag_);
    const auto on_sample = [&](size_t k, const tyre::TyreState<T>& s) {
      const double t = samples_.time[k];
      const tyre::TyreGas<T> gas =
          tyre::CalcTyreGas(p, s.carcass_temp, s.rim_temp, T(samples_.speed[k]));
      emit(kPressure, k, pressure_sensor.Next(t, gas.pressure));
      emit(kGasTemp, k, gas_sensor.Next(t, gas.gas_temp));
    };
    const tyre::TyreState<T> start{T(tread0_), T(carcass0_), T(0.0), x[kRim0]};
    if (brake_ == nullptr) {
      sim::IntegrateTyre<T>(p, *tyre_.compound, samples_, start, max_step_, on_sample);
    } else {
      IntegrateWithBrake(p, start, on_sample);
    }
  }

 private:
  // The tyre and its brake together (sim/replay.cc, CornerReplay::RunTogether).
  template <Scalar T, class OnSample>
  void IntegrateWithBrake(const tyre::TyreThermalParams<T>& p, const tyre::TyreState<T>& start,
                          OnSample&& on_sample) const {
    const brake::BrakeThermalParams<T> bp = brake_->Cast<T>();
    const tyre::TyreConstants<T> tyre_constants = tyre::CalcTyreConstants(p);
    const brake::BrakeConstants<T> brake_constants = brake::CalcBrakeConstants(bp);
    const tyre::TyreCompound& compound = *tyre_.compound;
    using Terms = std::pair<tyre::TyreInputTerms<T>, brake::BrakeInputTerms<T>>;
    const brake::BrakeState<T> brake_start{T(brake_start_.disc_temp), T(brake_start_.calliper_temp),
                                           T(brake_start_.bulk_temp)};
    sim::IntegrateOverSamples(
        samples_, sim::WheelState<T>{start, brake_start}, max_step_,
        [&](size_t k, double f, const Terms* near) {
          return Terms{
              tyre::CalcTyreInputTerms(p, tyre_constants, compound, samples_.TyreInputAt<T>(k, f),
                                       near ? &near->first : nullptr),
              brake::CalcBrakeInputTerms(bp, brake_constants,
                                         brake_samples_.BrakeInputAt<T>(k, f))};
        },
        [&](const sim::WheelState<T>& s, const Terms& t) {
          sim::WheelState<T> d;
          brake::BrakeHeatFlows<T> bq;
          d.brake = brake::CalcBrakeDerivatives(bp, s.brake, t.second, &bq, s.tyre.rim_temp);
          d.tyre =
              tyre::CalcTyreDerivatives(p, compound, s.tyre, t.first,
                                        static_cast<tyre::TyreHeatFlows<T>*>(nullptr), bq.ToRim());
          return d;
        },
        [&](size_t k, const sim::WheelState<T>& s) { on_sample(k, s.tyre); }, &brake_samples_);
  }

  const tyre::TyreFile& tyre_;
  sim::CornerSamples samples_, brake_samples_;
  const brake::BrakeThermalParams<double>* brake_;
  brake::BrakeState<double> brake_start_;
  double tread0_, carcass0_;
  double max_step_;
  double lag_;
};

FitParameter TyreParameter(int index, const tyre::TyreThermalParams<double>& car) {
  if (index <= kWp2) {
    const tyre::TyreThermalField& f = *TyreFitFields()[index];
    return FitParameterOf(std::string(f.key), *f.fit, f.Of(car));
  }
  switch (index) {
    case kTread0:
      return InitialTemperatureParameter("initial_tread_temp_C", "T_tread(0)");
    case kCarcass0:
      return InitialTemperatureParameter("initial_carcass_temp_C", "T_carcass(0)");
    default:
      return {.key = "initial_wear_mm",
              .label = "wear(0)",
              .unit = "mm",
              .lower = -10.0,
              .upper = 50.0,
              .scale = 0.01,
              .role = ParameterRole::kNuisance};
  }
}

// Cumulative trapezoid integral of f over time.
std::vector<double> Cumulative(std::span<const double> time, const std::vector<double>& f) {
  std::vector<double> out(f.size(), 0.0);
  for (size_t k = 1; k < f.size(); ++k) {
    out[k] = out[k - 1] + 0.5 * (f[k] + f[k - 1]) * (time[k] - time[k - 1]);
  }
  return out;
}

// The equation-error guess: the heat balances (000:7-8) integrated from the first sample,
// m c (T(t) - T(0)) = integral of the flows, are linear in p1..p5 once the measured (smoothed)
// temperatures stand in for the states.
std::optional<std::array<double, 5>> EquationErrorGuess(const tyre::TyreFile& tyre,
                                                        const TyreCornerData& d) {
  if (!d.tread.usable || !d.carcass.usable) return std::nullopt;
  const std::span<const double> time = d.samples.time;
  const size_t n = time.size();
  const std::vector<double> tt = SmoothedForGuess(d.tread.values);
  const std::vector<double> tc = SmoothedForGuess(d.carcass.values);
  // Each regressor is a heat flow with one parameter at 1 and the others at 0.
  std::array<tyre::TyreThermalParams<double>, 5> unit;
  for (int i = kP1; i <= kP5; ++i) {
    unit[i] = tyre.params;
    for (int j = kP1; j <= kP5; ++j) TyreFitFields()[j]->Of(unit[i]) = i == j ? 1.0 : 0.0;
  }
  std::vector<double> s(n), hx(n), hy(n), hz(n), dd(n), lt(n), lc(n);
  for (size_t k = 0; k < n; ++k) {
    const tyre::TyreInput<double> in = d.samples.TyreInputAt<double>(k, 0.0);
    const tyre::TyreState<double> x{tt[k], tc[k], 0.0};
    const auto q = tyre::CalcTyreHeatFlows(unit[0], x, in);
    s[k] = q.q1;
    lt[k] = q.q3 + q.q4 + q.q6;
    lc[k] = q.q7;
    hx[k] = tyre::CalcTyreHeatFlows(unit[1], x, in).q2;
    hy[k] = tyre::CalcTyreHeatFlows(unit[2], x, in).q2;
    hz[k] = tyre::CalcTyreHeatFlows(unit[3], x, in).q2;
    dd[k] = tyre::CalcTyreHeatFlows(unit[4], x, in).q5;
  }
  const auto is = Cumulative(time, s), ihx = Cumulative(time, hx), ihy = Cumulative(time, hy),
             ihz = Cumulative(time, hz), id = Cumulative(time, dd), ilt = Cumulative(time, lt),
             ilc = Cumulative(time, lc);
  const double ct = tyre.params.tread_mass * tyre.params.tread_heat_capacity;
  const double cc = tyre.params.carcass_mass * tyre.params.carcass_heat_capacity;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(2 * n, 5);
  Eigen::VectorXd b(2 * n);
  for (size_t k = 0; k < n; ++k) {
    a(k, 0) = is[k] / ct;
    a(k, 4) = id[k] / ct;
    b(k) = tt[k] - tt[0] + ilt[k] / ct;
    a(n + k, 1) = ihx[k] / cc;
    a(n + k, 2) = ihy[k] / cc;
    a(n + k, 3) = ihz[k] / cc;
    a(n + k, 4) = -id[k] / cc;
    b(n + k) = tc[k] - tc[0] + ilc[k] / cc;
  }
  Eigen::VectorXd lower(5), upper(5), start(5);
  for (int i = 0; i < 5; ++i) {
    const FitParameter p = TyreParameter(i, tyre.params);
    lower(i) = p.lower;
    upper(i) = p.upper;
    start(i) = p.scale;
  }
  const Eigen::VectorXd x = SolveBoundedLeastSquares(a, b, lower, upper, start);
  std::array<double, 5> out;
  for (int i = 0; i < 5; ++i) out[i] = x(i);
  return out;
}

// Carries the thermal parameters' uncertainty into the wear parameters' covariance.
void AddThermalUncertainty(const TyreLogModel& model, const std::vector<double>& all,
                           const std::vector<int>& free_thermal, const FitResult& thermal,
                           const std::vector<int>& free_wear, const MeasuredChannel& wear_channel,
                           const FitOptions& options, FitResult* wear) {
  Predictions pw, pp;
  JetPredictor<TyreLogModel> jw(model, all, free_wear, {kWear});
  JetPredictor<TyreLogModel> jp(model, all, free_thermal, {kWear});
  std::vector<double> xw, xp;
  for (int i : free_wear) xw.push_back(all[i]);
  for (int i : free_thermal) xp.push_back(all[i]);
  if (!jw.Predict(xw, true, &pw) || !jp.Predict(xp, true, &pp)) return;
  const size_t nw = free_wear.size(), np = free_thermal.size();
  Eigen::MatrixXd jww = Eigen::MatrixXd::Zero(nw, nw), jwp = Eigen::MatrixXd::Zero(nw, np);
  for (size_t k = 0; k < wear_channel.values.size(); ++k) {
    if (!std::isfinite(wear_channel.values[k])) continue;
    const double w = wear_channel.weights.empty() ? 1.0 : wear_channel.weights[k];
    const double* rw = &pw.jacobian[0][k * nw];
    const double* rp = &pp.jacobian[0][k * np];
    for (size_t i = 0; i < nw; ++i) {
      for (size_t j = 0; j < nw; ++j) jww(i, j) += w * rw[i] * rw[j];
      for (size_t j = 0; j < np; ++j) jwp(i, j) += w * rw[i] * rp[j];
    }
  }
  const Eigen::MatrixXd g = -jww.completeOrthogonalDecomposition().pseudoInverse() * jwp;
  Eigen::MatrixXd cp = thermal.covariance;
  for (Eigen::Index i = 0; i < cp.rows(); ++i) {
    for (Eigen::Index j = 0; j < cp.cols(); ++j) {
      if (!std::isfinite(cp(i, j))) cp(i, j) = 0.0;  // undetermined: moves no prediction
    }
  }
  wear->covariance += g * cp * g.transpose();
  SummarizeEstimates(*wear, options);
}

}  // namespace

const std::vector<const tyre::TyreThermalField*>& TyreFitFields() {
  static const std::vector<const tyre::TyreThermalField*> fields = [] {
    std::vector<const tyre::TyreThermalField*> f = tyre::FittedTyreThermalFields("heat_generation");
    const std::vector<const tyre::TyreThermalField*> wear = tyre::FittedTyreThermalFields("wear");
    f.insert(f.end(), wear.begin(), wear.end());
    return f;
  }();
  return fields;
}

const std::vector<const tyre::TyreThermalField*>& GasFitFields() {
  static const std::vector<const tyre::TyreThermalField*> fields = {
      tyre::FindTyreThermalField("gas.carcass_gas_W_per_K"),
      tyre::FindTyreThermalField("gas.gas_rim_W_per_K"),
      tyre::FindTyreThermalField("rim.rim_air_W_per_K")};
  return fields;
}

const std::vector<std::string>& TyreParameterKeys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k;
    for (const tyre::TyreThermalField* f : TyreFitFields()) k.emplace_back(f->key);
    return k;
  }();
  return keys;
}

namespace {

// The thermal stage: p1..p5 (and the starting temperatures when fitted) to the tread and carcass
// temperatures, from the car's values, the equation-error guess and seeded random starts. The
// fitted values go into `all`.
void FitThermalStage(const tyre::TyreFile& tyre, const TyreCornerData& d,
                     const LogFitOptions& options, const TyreLogModel& model,
                     const std::vector<int>& free_thermal, std::vector<double>& all,
                     TyreFitResult& r) {
  const tyre::TyreThermalParams<double>& car = tyre.params;
  const std::span<const double> time = d.samples.time;
  std::vector<FitParameter> params;
  for (int i : free_thermal) params.push_back(TyreParameter(i, car));
  const std::vector<MeasuredChannel> channels = {TemperatureChannel(d.tread, d.weights),
                                                 TemperatureChannel(d.carcass, d.weights)};
  std::vector<std::vector<double>> starts;
  const auto with_states = [&](std::array<double, 5> p) {
    std::vector<double> s(p.begin(), p.end());
    for (size_t i = 5; i < free_thermal.size(); ++i) s.push_back(all[free_thermal[i]]);
    return s;
  };
  starts.push_back(with_states({car.p1, car.p2, car.p3, car.p4, car.p5}));
  if (auto guess = EquationErrorGuess(tyre, d)) starts.push_back(with_states(*guess));
  std::mt19937_64 rng(options.seed);
  for (int i = 0; i < options.random_starts; ++i) {
    const double p1 = 0.05 + 0.75 * static_cast<double>(rng() >> 11) * 0x1.0p-53;
    starts.push_back(with_states({p1, LogUniform(rng, 1e-6, 1e-2), LogUniform(rng, 1e-6, 1e-2),
                                  LogUniform(rng, 1e-6, 1e-2), LogUniform(rng, 20.0, 2000.0)}));
  }
  const JetPredictor<TyreLogModel> predictor(model, all, free_thermal, {kTread, kCarcass});
  r.thermal = FitChannels(predictor, params, channels, starts, time, options.solver);
  for (size_t i = 0; i < free_thermal.size(); ++i) {
    all[free_thermal[i]] = r.thermal->estimates[i].value;
  }
  AddLagWarnings(*r.thermal, options.sensor_lag_s, &r.warnings);
  AddMisfitWarnings(*r.thermal, &r.warnings);
}

// The wear measured over the log: the total, else the channel's last finite value less its
// first.
double MeasuredWear(const MeasuredChannel& ch, bool total) {
  double first = kNaN, last = kNaN;
  for (double v : ch.values) {
    if (!std::isfinite(v)) continue;
    if (!std::isfinite(first)) first = v;
    last = v;
  }
  return total ? last : last - first;
}

// Starts of the wear fit: for several wp2, the wp1 that matches the measured wear over the log
// (the wear is proportional to wp1); with a channel, wp2 and the initial wear too.
std::vector<std::vector<double>> WearStarts(const WearQuadratureModel& wear_model,
                                            const tyre::TyreThermalParams<double>& car,
                                            const std::vector<double>& all, size_t samples,
                                            double measured, bool total) {
  std::vector<std::vector<double>> starts;
  std::vector<double> exponents = {car.wear_exponent};
  if (!total) exponents.insert(exponents.end(), {0.5, 1.0, 1.5, 2.0, 3.0});
  for (double wp2 : exponents) {
    std::vector<double> unit_all = all;
    unit_all[kWp1] = 1.0;
    unit_all[kWp2] = wp2;
    unit_all[kWear0] = 0.0;
    double predicted = 0.0;
    wear_model.Run<double>(unit_all, [&](int c, size_t k, double v) {
      if (c == kWear && k + 1 == samples) predicted = v;
    });
    double wp1 = car.wear_coeff;
    if (predicted > 0.0 && std::isfinite(predicted) && measured > 0.0) wp1 = measured / predicted;
    std::vector<double> s = {wp1};
    if (!total) s.insert(s.end(), {wp2, all[kWear0]});
    starts.push_back(s);
  }
  return starts;
}

// The wear stage, at the fitted thermal parameters: wp1 to a measured total (wp2 held), or wp1,
// wp2 and the initial wear to a wear channel. The fitted values go into `all`.
void FitWearStage(const tyre::TyreFile& tyre, const TyreCornerData& d, const LogFitOptions& options,
                  const TyreLogModel& model, const std::vector<int>& free_thermal,
                  std::vector<double>& all, TyreFitResult& r) {
  const tyre::TyreThermalParams<double>& car = tyre.params;
  const std::span<const double> time = d.samples.time;
  const bool total = d.wear_total_mm.has_value();
  std::vector<int> free_wear = {kWp1};
  MeasuredChannel ch{
      .name = "wear", .unit = "mm", .values = std::vector<double>(time.size(), kNaN)};
  if (total) {
    ch.values.back() = *d.wear_total_mm;
    ch.prior_sigma = d.wear_total_sd_mm;
    ch.fixed_sigma = true;
    r.warnings.push_back(fmt::format(
        "wear measured as one total: only wp1 is fitted; wp2 held at {:.4g} from the car file "
        "(a log with a wear channel determines both)",
        car.wear_exponent));
  } else {
    free_wear = {kWp1, kWp2, kWear0};
    ch.values = d.wear.values;
    ch.weights = d.weights;
    ch.prior_sigma = 1e-3;
    ch.min_sigma = 1e-9;
    all[kWear0] = RobustFirstValue(time, d.wear.values);
  }
  const double measured = MeasuredWear(ch, total);
  const WearQuadratureModel wear_model(tyre, d.samples, all, options.max_step_s);
  const std::vector<std::vector<double>> starts =
      WearStarts(wear_model, car, all, time.size(), measured, total);
  std::vector<FitParameter> params;
  for (int i : free_wear) params.push_back(TyreParameter(i, car));
  const JetPredictor<WearQuadratureModel> predictor(wear_model, all, free_wear, {kWear});
  const std::vector<MeasuredChannel> channels = {ch};
  r.wear = FitChannels(predictor, params, channels, starts, {}, options.solver);
  for (size_t i = 0; i < free_wear.size(); ++i) all[free_wear[i]] = r.wear->estimates[i].value;
  if (r.thermal) {
    AddThermalUncertainty(model, all, free_thermal, *r.thermal, free_wear, ch, options.solver,
                          &*r.wear);
  }
}

// A logged TPMS pressure (gauge, Pa) as a fitted channel, shown in kPa: trapezoid weights, a
// prior noise of 1 kPa and a floor of 1 Pa on the estimated one.
MeasuredChannel PressureChannel(const LoggedChannel& logged, const std::vector<double>& weights) {
  return {.name = logged.quantity,
          .unit = "kPa",
          .display_scale = 1e-3,
          .values = logged.values,
          .weights = weights,
          .prior_sigma = 1e3,
          .min_sigma = 1.0};
}

// Starts of the gas stage: the file's conductances, and each scaled up and down together and
// against one another (the gas temperature sees their ratio, the rim's warming their size).
std::vector<std::vector<double>> GasStarts(const tyre::TyreThermalParams<double>& car,
                                           double rim0) {
  const double g_cg = car.carcass_gas_conductance, g_gr = car.gas_rim_conductance,
               g_ra = car.rim_air_conductance;
  std::vector<std::vector<double>> starts;
  for (const auto& [a, b, c] :
       {std::array{1.0, 1.0, 1.0}, std::array{2.0, 2.0, 2.0}, std::array{0.5, 0.5, 0.5},
        std::array{2.0, 0.5, 1.0}, std::array{0.5, 2.0, 1.0}}) {
    starts.push_back({a * g_cg, b * g_gr, c * g_ra, rim0});
  }
  return starts;
}

// The gas stage: the gas path's conductances and the rim's starting temperature to the TPMS
// channels, on the car's own gas-and-rim model with the file's p1..p5 (docs/fitting.md, "The
// gas path from TPMS"). Fills r.gas, the conductances of r.params and the modelled channels.
void FitGasStage(const tyre::TyreFile& car_tyre, const TyreCornerData& d,
                 const LogFitOptions& options, TyreFitResult& r) {
  const std::span<const double> time = d.samples.time;
  const tyre::TyreThermalParams<double>& car = car_tyre.params;
  const double tread0 =
      StartingTemperature(d.tread, time, options.initial_state, d.fallback_tread_temp);
  const double carcass0 =
      StartingTemperature(d.carcass, time, options.initial_state, d.fallback_carcass_temp);
  const GasLogModel model(car_tyre, d, tread0, carcass0, options.max_step_s, options.tpms_lag_s);
  std::vector<FitParameter> params;
  for (const tyre::TyreThermalField* f : GasFitFields()) {
    params.push_back(FitParameterOf(std::string(f->key), *f->fit, f->Of(car)));
  }
  params.push_back(InitialTemperatureParameter("initial_rim_temp_C", "T_rim(0)"));
  std::vector<MeasuredChannel> channels;
  std::vector<int> fitted_channels;
  if (d.pressure.usable) {
    channels.push_back(PressureChannel(d.pressure, d.weights));
    fitted_channels.push_back(kPressure);
  }
  if (d.gas_temp.usable) {
    channels.push_back(TemperatureChannel(d.gas_temp, d.weights));
    fitted_channels.push_back(kGasTemp);
  }
  std::vector<double> all = {car.carcass_gas_conductance, car.gas_rim_conductance,
                             car.rim_air_conductance, d.fallback_rim_temp};
  const std::vector<int> free = {kCarcassGas, kGasRim, kRimAir, kRim0};
  const JetPredictor<GasLogModel> predictor(model, all, free, fitted_channels);
  r.gas = FitChannels(predictor, params, channels, GasStarts(car, d.fallback_rim_temp), time,
                      options.solver);
  for (size_t i = 0; i < free.size(); ++i) all[free[i]] = r.gas->estimates[i].value;
  for (size_t i = 0; i < GasFitFields().size(); ++i) GasFitFields()[i]->Of(r.params) = all[i];
  AddLagWarnings(*r.gas, options.tpms_lag_s, &r.warnings, "--tpms-lag-s");
  AddMisfitWarnings(*r.gas, &r.warnings);
  r.pressure_model.resize(time.size());
  r.gas_temp_model.resize(time.size());
  model.Run<double>(all, [&](int c, size_t k, double v) {
    (c == kPressure ? r.pressure_model : r.gas_temp_model)[k] = v;
  });
}

// Whether the gas stage runs: a gas-and-rim tyre and a usable TPMS channel. Says why not where
// the log has a TPMS column the fit cannot use (a log without any is fitted as before, silently).
bool WantsGasStage(const tyre::TyreFile& tyre, const TyreCornerData& d, TyreFitResult& r) {
  const bool columns = !d.pressure.column.empty() || !d.gas_temp.column.empty();
  if (!columns) return false;
  if (!tyre.params.HasGasAndRim()) {
    r.warnings.push_back(
        "the tyre file runs the paper's model (no gas node): the TPMS channels are not fitted");
    return false;
  }
  for (const LoggedChannel* ch : {&d.pressure, &d.gas_temp}) {
    if (ch->column.empty()) continue;
    if (const std::string s = DescribeChannelProblems(*ch); !s.empty()) r.warnings.push_back(s);
  }
  if (!d.pressure.usable && !d.gas_temp.usable) {
    r.warnings.push_back(
        "no usable pressure or gas temperature: the gas path's conductances kept from the car "
        "file");
    return false;
  }
  return true;
}

}  // namespace

TyreFitResult FitTyreCorner(const tyre::TyreFile& any_tyre, const TyreCornerData& d,
                            const LogFitOptions& options) {
  // The fit identifies the paper's two masses (docs/fitting.md): a gas-and-rim tyre is fitted as
  // its paper part.
  tyre::TyreFile tyre = any_tyre;
  tyre.params.model = tyre::TyreThermalModel::kPaper;
  const std::span<const double> time = d.samples.time;
  if (time.empty()) throw InputError("the log has no samples");
  TyreFitResult r;
  r.params = tyre.params;
  const TyreLogModel model(tyre, d.samples, options.max_step_s, options.sensor_lag_s);
  const tyre::TyreThermalParams<double>& car = tyre.params;
  std::vector<double> all(kCount);
  for (int i = kP1; i <= kWp2; ++i) all[i] = TyreFitFields()[i]->Of(car);
  all[kTread0] = StartingTemperature(d.tread, time, options.initial_state, d.fallback_tread_temp);
  all[kCarcass0] =
      StartingTemperature(d.carcass, time, options.initial_state, d.fallback_carcass_temp);
  all[kWear0] = 0.0;
  for (const LoggedChannel* ch : {&d.tread, &d.carcass}) {
    if (const std::string s = DescribeChannelProblems(*ch); !s.empty()) r.warnings.push_back(s);
  }

  // Thermal stage.
  std::vector<int> free_thermal = {kP1, kP2, kP3, kP4, kP5};
  if (options.initial_state == InitialStateMode::kFitted) {
    free_thermal.push_back(kTread0);
    free_thermal.push_back(kCarcass0);
  }
  if (d.tread.usable || d.carcass.usable) {
    FitThermalStage(tyre, d, options, model, free_thermal, all, r);
  } else {
    r.warnings.push_back("no usable tread or carcass temperature: p1..p5 kept from the car file");
  }

  // Wear stage, at the fitted thermal parameters.
  if (const std::string s = DescribeChannelProblems(d.wear);
      !s.empty() && !d.wear_total_mm && !d.wear.column.empty()) {
    r.warnings.push_back(s);
  }
  if (d.wear_total_mm.has_value() || d.wear.usable) {
    FitWearStage(tyre, d, options, model, free_thermal, all, r);
  } else if (d.wear.column.empty()) {
    r.warnings.push_back(
        "no wear measurement (no wear column and no --wear-per-lap-mm): wp1 and wp2 kept from "
        "the car file");
  }

  for (int i = kP1; i <= kWp2; ++i) TyreFitFields()[i]->Of(r.params) = all[i];
  r.tread_model.resize(time.size());
  r.carcass_model.resize(time.size());
  r.wear_model.resize(time.size());
  model.Run<double>(all, [&](int c, size_t k, double v) {
    (c == kTread ? r.tread_model : c == kCarcass ? r.carcass_model : r.wear_model)[k] = v;
  });

  // Gas stage, on the car's own gas-and-rim model.
  if (WantsGasStage(any_tyre, d, r)) FitGasStage(any_tyre, d, options, r);
  return r;
}

}  // namespace hotlap::ident
