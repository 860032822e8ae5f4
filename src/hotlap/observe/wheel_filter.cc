#include "hotlap/observe/wheel_filter.h"

#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "hotlap/common/error.h"

namespace hotlap::observe {

namespace {

void CheckTemperature(double temp, const char* what, double time) {
  if (!(temp > 0.0 && temp < 3000.0)) {
    throw NumericalError(fmt::format(
        "observer diverged: predicted {} temperature is {:g} K at t = {:g} s; check the inputs "
        "(forces, speeds) and the parameters",
        what, temp, time));
  }
}

const tyre::TyreThermalParams<double>& RequireGasAndRim(const tyre::TyreThermalParams<double>& p) {
  if (!p.HasGasAndRim()) {
    throw InputError(
        "observer: the car's own models are observed for gas-and-rim tyres (thermal_model "
        "gas_rim); this tyre runs the paper's model");
  }
  return p;
}

}  // namespace

WheelFilter::WheelFilter(const tyre::TyreThermalParams<double>& tyre,
                         std::shared_ptr<const tyre::TyreCompound> compound,
                         const brake::BrakeThermalParams<double>& brake,
                         const ProcessNoise& process, const CarModelsNoise& car_models,
                         double max_step_s, const SensorLag& lag)
    : tyre_(RequireGasAndRim(tyre).Cast<Jet>()),
      compound_(std::move(compound)),
      brake_(brake.Cast<Jet>()),
      bulk_(brake.HasBulk()),
      max_step_s_(max_step_s),
      temperature_lag_s_({lag.tread_temp, lag.disc_temp, lag.calliper_temp}),
      tpms_lag_s_(car_models.tpms_lag_s) {
  q_ << process.tread_temp, process.carcass_temp, process.wear, car_models.rim_temp,
      process.disc_temp, process.calliper_temp, bulk_ ? car_models.disc_bulk_temp : 0.0;
}

void WheelFilter::Tpms(const Eigen::Matrix<double, kStates, 1>& mean, double speed, TpmsValues& h,
                       TpmsRows& rows) const {
  const tyre::TyreGas<Jet> gas =
      tyre::CalcTyreGas(tyre_, Jet(mean(kCarcass), kCarcass), Jet(mean(kRim), kRim), Jet(speed));
  h << gas.pressure.a, gas.gas_temp.a;
  rows.row(kTpmsPressure) = gas.pressure.v.transpose();
  rows.row(kTpmsGasTemp) = gas.gas_temp.v.transpose();
}

void WheelFilter::Reset(const Gaussian<kStates>& start, double speed) {
  Gaussian<kStates> x = start;
  if (!bulk_) {  // a lumped disc has no bulk: the state stays where it starts
    x.cov.row(kBulk).setZero();
    x.cov.col(kBulk).setZero();
  }
  speed_ = speed;
  // Every sensor starts settled: y = h(x), fully correlated with the states through its row.
  Eigen::Matrix<double, kAll, kStates> rows = Eigen::Matrix<double, kAll, kStates>::Zero();
  rows.topRows<kStates>().setIdentity();
  TpmsValues h;
  TpmsRows tpms_rows;
  Tpms(x.mean, speed_, h, tpms_rows);
  z_.mean.head<kStates>() = x.mean;
  for (int j = 0; j < 3; ++j) {
    rows(kTemperatureSensors + j, kSensorState[j]) = 1.0;
    z_.mean(kTemperatureSensors + j) = x.mean(kSensorState[j]);
  }
  rows.bottomRows<2>() = tpms_rows;
  z_.mean.tail<2>() = h;
  z_.cov = rows * x.cov * rows.transpose();
}

Gaussian<WheelFilter::kStates> WheelFilter::estimate() const {
  Gaussian<kStates> x;
  x.mean = z_.mean.head<kStates>();
  x.cov = z_.cov.topLeftCorner<kStates, kStates>();
  return x;
}

void WheelFilter::Predict(const sim::CornerSamples& tyre_in, const sim::CornerSamples& brake_in) {
  using State = sim::WheelState<Jet>;
  using Terms = std::pair<tyre::TyreInputTerms<Jet>, brake::BrakeInputTerms<Jet>>;
  const tyre::TyreConstants<Jet> tyre_constants = tyre::CalcTyreConstants(tyre_);
  const brake::BrakeConstants<Jet> brake_constants = brake::CalcBrakeConstants(brake_);
  const Eigen::Matrix<double, kStates, 1> before = z_.mean.head<kStates>();
  const auto seeded = [&](int i) { return Jet(before(i), i); };
  const State start{{seeded(kTread), seeded(kCarcass), seeded(kWear), seeded(kRim)},
                    {seeded(kDisc), seeded(kCalliper), bulk_ ? seeded(kBulk) : Jet(before(kBulk))}};
  State end = start;
  // The wheel as replay integrates it (sim/replay.cc, CornerReplay::RunTogether).
  sim::IntegrateOverSamples(
      tyre_in, start, max_step_s_,
      [&](size_t k, double f, const Terms* near) {
        return Terms{
            tyre::CalcTyreInputTerms(tyre_, tyre_constants, *compound_,
                                     tyre_in.TyreInputAt<Jet>(k, f), near ? &near->first : nullptr),
            brake::CalcBrakeInputTerms(brake_, brake_constants, brake_in.BrakeInputAt<Jet>(k, f))};
      },
      [&](const State& s, const Terms& t) {
        State d;
        brake::BrakeHeatFlows<Jet> bq;
        d.brake = brake::CalcBrakeDerivatives(brake_, s.brake, t.second, &bq, s.tyre.rim_temp);
        d.tyre =
            tyre::CalcTyreDerivatives(tyre_, *compound_, s.tyre, t.first,
                                      static_cast<tyre::TyreHeatFlows<Jet>*>(nullptr), bq.ToRim());
        return d;
      },
      [&](size_t k, const State& x) {
        if (k == 1) end = x;
      },
      &brake_in);
  const Jet* rows[kStates] = {
      &end.tyre.tread_temp, &end.tyre.carcass_temp,   &end.tyre.wear,      &end.tyre.rim_temp,
      &end.brake.disc_temp, &end.brake.calliper_temp, &end.brake.bulk_temp};
  Eigen::Matrix<double, kStates, 1> after;
  for (int i = 0; i < kStates; ++i) {
    after(i) = rows[i]->a;
    f_.row(i) = rows[i]->v.transpose();
  }
  if (!bulk_) f_.row(kBulk) = Eigen::Matrix<double, 1, kStates>::Unit(kBulk);
  const double dt = tyre_in.time[1] - tyre_in.time[0];
  CheckTemperature(after(kTread), "tread", tyre_in.time[1]);
  CheckTemperature(after(kCarcass), "carcass", tyre_in.time[1]);
  CheckTemperature(after(kRim), "rim", tyre_in.time[1]);
  CheckTemperature(after(kDisc), "disc", tyre_in.time[1]);
  CheckTemperature(after(kCalliper), "calliper", tyre_in.time[1]);

  // The joint transition of states and sensors (sensor_lag.h's exact lag over the interval, the
  // inputs linear between its ends): x1 = F x0 + w, y1 = a y0 + c h(x0) + b h(x1).
  Eigen::Matrix<double, kAll, kAll> a = Eigen::Matrix<double, kAll, kAll>::Zero();
  Eigen::Matrix<double, kAll, kStates> noise = Eigen::Matrix<double, kAll, kStates>::Zero();
  a.topLeftCorner<kStates, kStates>() = f_;
  noise.topRows<kStates>().setIdentity();
  const auto lag = [&](double tau, double& decay, double& start_weight, double& end_weight) {
    decay = tau > 0.0 ? std::exp(-dt / tau) : 0.0;  // tau 0: y1 = x1
    end_weight = tau > 0.0 ? 1.0 - tau * (1.0 - decay) / dt : 1.0;
    start_weight = 1.0 - decay - end_weight;
  };
  Eigen::Matrix<double, kAll, 1> mean;
  mean.head<kStates>() = after;
  for (int j = 0; j < 3; ++j) {
    double d, c, b;
    lag(temperature_lag_s_[j], d, c, b);
    const int y = kTemperatureSensors + j, i = kSensorState[j];
    a(y, y) = d;
    a.block<1, kStates>(y, 0) = b * f_.row(i);
    a(y, i) += c;
    noise(y, i) = b;
    mean(y) = d * z_.mean(y) + c * before(i) + b * after(i);
  }
  TpmsValues h0, h1;
  TpmsRows rows0, rows1;
  Tpms(before, tyre_in.speed[0], h0, rows0);
  Tpms(after, tyre_in.speed[1], h1, rows1);
  double d, c, b;
  lag(tpms_lag_s_, d, c, b);
  for (int j = 0; j < 2; ++j) {
    const int y = kTpms + j;
    a(y, y) = d;
    a.block<1, kStates>(y, 0) = c * rows0.row(j) + b * rows1.row(j) * f_;
    noise.row(y) = b * rows1.row(j);
    mean(y) = d * z_.mean(y) + c * h0(j) + b * h1(j);
  }
  const Eigen::Matrix<double, kStates, 1> q_dt = q_ * dt;
  z_.mean = mean;
  z_.cov = a * z_.cov * a.transpose() + noise * q_dt.asDiagonal() * noise.transpose();
  z_.cov = (0.5 * (z_.cov + z_.cov.transpose())).eval();
  speed_ = tyre_in.speed[1];
}

UpdateOutcome WheelFilter::UpdateTemperature(int sensor, double reading, double sd,
                                             double gate_nis) {
  const int index =
      temperature_lag_s_[sensor] > 0.0 ? kTemperatureSensors + sensor : kSensorState[sensor];
  return UpdateScalar(z_, index, reading, sd * sd, gate_nis);
}

GasEstimate WheelFilter::Gas() const {
  TpmsValues h;
  TpmsRows rows;
  Tpms(z_.mean.head<kStates>(), speed_, h, rows);
  const Eigen::Matrix<double, 2, 2> cov =
      rows * z_.cov.topLeftCorner<kStates, kStates>() * rows.transpose();
  const auto sd = [](double var) { return std::sqrt(std::max(var, 0.0)); };
  return {h(kTpmsGasTemp), sd(cov(kTpmsGasTemp, kTpmsGasTemp)), h(kTpmsPressure),
          sd(cov(kTpmsPressure, kTpmsPressure))};
}

}  // namespace hotlap::observe
