#include "hotlap/observe/car_observer.h"

#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"

namespace hotlap::observe {

CarObserver::CarObserver(const vehicle::Car& car, ObserverConfig config, const ObserverStart& start,
                         ObservedModels models)
    : config_(std::move(config)), models_(models), car_initial_(car.initial), start_(start) {
  if (models_ == ObservedModels::kCar && !config_.car_models) {
    throw InputError(fmt::format(
        "{}: no car_models section (the rim's and disc bulk's noise, the TPMS's noise and lag), "
        "which observing the car's own models needs (data/observer/default.yaml has one)",
        config_.source));
  }
  if (models_ == ObservedModels::kCar && config_.p5_scale.estimate) {
    throw InputError(
        "observer: the p5 factor state is estimated on the paper's models only, not with the "
        "car's own");
  }
  tyres_.reserve(4);
  brakes_.reserve(4);
  for (Corner c : kAllCorners) {
    if (models_ == ObservedModels::kCar && car.tyre(c).params.HasGasAndRim()) {
      wheels_[CornerIndex(c)].emplace(car.tyre(c).params, car.tyre(c).compound, car.brake(c).params,
                                      config_.process, *config_.car_models, config_.max_step_s,
                                      config_.sensor_lag);
    }
    tyres_.emplace_back(car.tyre(c).params, car.tyre(c).compound, config_.process, config_.p5_scale,
                        config_.max_step_s, config_.sensor_lag.tread_temp);
    brakes_.emplace_back(car.brake(c).params, config_.process, config_.max_step_s,
                         config_.sensor_lag.disc_temp, config_.sensor_lag.calliper_temp);
  }
  // The starting state before any sample: the car's, so Estimate() is defined.
  ObserverSample none;
  for (auto& r : none.readings) r = CornerReadings{};
  Start(none);
  samples_ = 0;
  for (auto& corner : monitors_) corner = {};
}

void CarObserver::Start(const ObserverSample& first) {
  const InitialSd& sd = config_.initial_sd;
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    const CornerReadings& r = first.readings[i];
    const SensorNoise& noise = config_.sensors[i];
    // A reading starts the state at itself, with the sensor's variance.
    const auto pick = [](double reading, double reading_sd, const std::optional<double>& given,
                         double car_value, double prior_sd) -> std::pair<double, double> {
      if (std::isfinite(reading)) return {reading, reading_sd};
      return {given.value_or(car_value), prior_sd};
    };
    const auto [tread, tread_sd] = pick(r.tread_temp, noise.tread_temp, start_.tread_temp,
                                        car_initial_.tread_temp, sd.tread_temp);
    const auto [disc, disc_sd] =
        pick(r.disc_temp, noise.disc_temp, start_.disc_temp, car_initial_.disc_temp, sd.disc_temp);
    const auto [calliper, calliper_sd] =
        pick(r.calliper_temp, noise.calliper_temp, start_.calliper_temp, car_initial_.calliper_temp,
             sd.calliper_temp);
    Gaussian<TyreFilter::kStates> t;
    t.mean << tread, start_.carcass_temp.value_or(car_initial_.carcass_temp), 0.0, 1.0;
    t.cov.diagonal() << tread_sd * tread_sd, sd.carcass_temp * sd.carcass_temp, sd.wear * sd.wear,
        config_.p5_scale.estimate ? config_.p5_scale.initial_sd * config_.p5_scale.initial_sd : 0.0;
    tyres_[i].Reset(t);
    Gaussian<BrakeFilter::kStates> b;
    b.mean << disc, calliper;
    b.cov.diagonal() << disc_sd * disc_sd, calliper_sd * calliper_sd;
    brakes_[i].Reset(b);
    if (wheels_[i]) {
      const CarModelsNoise& n = *config_.car_models;
      Gaussian<WheelFilter::kStates> w;
      w.mean << t.mean(TyreFilter::kTread), t.mean(TyreFilter::kCarcass), 0.0,
          car_initial_.rim_temp, disc, calliper, car_initial_.disc_bulk_temp;
      w.cov.diagonal() << t.cov(0, 0), t.cov(1, 1), t.cov(2, 2), n.rim_temp_sd * n.rim_temp_sd,
          disc_sd * disc_sd, calliper_sd * calliper_sd, n.disc_bulk_temp_sd * n.disc_bulk_temp_sd;
      wheels_[i]->Reset(w, first.inputs[i].speed);
    }
    // The readings that started the state count as readings, not as innovations.
    const double values[3] = {r.tread_temp, r.disc_temp, r.calliper_temp};
    for (int s = 0; s < 3; ++s) {
      if (std::isfinite(values[s])) ++monitors_[i][s].readings;
    }
  }
}

std::vector<DisagreementWarning> CarObserver::Step(const ObserverSample& sample) {
  if (!std::isfinite(sample.time)) throw InputError("observer: sample time is not finite");
  const auto finite = [&](double v, const char* what, Corner c) {
    if (!std::isfinite(v)) {
      throw InputError(fmt::format("observer: input {}_{} is not finite at t = {:g} s", what,
                                   CornerName(c), sample.time));
    }
  };
  for (Corner c : kAllCorners) {
    const CornerInputs& in = sample.inputs[CornerIndex(c)];
    finite(in.speed, "speed", c);
    finite(in.fx, "fx", c);
    finite(in.fy, "fy", c);
    finite(in.fz, "fz", c);
    finite(in.slip_angle, "slip_angle", c);
    finite(in.slip_ratio, "slip_ratio", c);
  }
  if (!std::isfinite(sample.ambient_temp) || !std::isfinite(sample.track_temp)) {
    throw InputError(fmt::format(
        "observer: ambient or track temperature is not finite at t = {:g} s", sample.time));
  }
  std::vector<DisagreementWarning> warnings;
  if (!previous_) {
    for (auto& corner : monitors_) corner = {};
    Start(sample);
    previous_ = sample;
    ++samples_;
    return warnings;
  }
  const ObserverSample& a = *previous_;
  if (!(sample.time > a.time)) {
    throw InputError(fmt::format("observer: time {:g} s does not follow the previous {:g} s",
                                 sample.time, a.time));
  }
  const std::array<double, 2> time = {a.time, sample.time};
  const std::array<double, 2> ambient = {a.ambient_temp, sample.ambient_temp};
  const std::array<double, 2> track = {a.track_temp, sample.track_temp};
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    const CornerInputs& x = a.inputs[i];
    const CornerInputs& y = sample.inputs[i];
    const std::array<double, 2> speed = {x.speed, y.speed}, fx = {x.fx, y.fx}, fy = {x.fy, y.fy},
                                fz = {x.fz, y.fz}, slip_angle = {x.slip_angle, y.slip_angle},
                                slip_ratio = {x.slip_ratio, y.slip_ratio};
    const sim::CornerSamples in{time, speed, fx, fy, fz, slip_angle, slip_ratio, ambient, track};
    // The brake sees its own force where the log has one.
    const std::array<double, 2> brake_fx = {std::isfinite(x.brake_fx) ? x.brake_fx : x.fx,
                                            std::isfinite(y.brake_fx) ? y.brake_fx : y.fx};
    sim::CornerSamples brake_in = in;
    brake_in.fx = brake_fx;
    if (wheels_[i]) {
      wheels_[i]->Predict(in, brake_in);
    } else {
      tyres_[i].Predict(in);
      brakes_[i].Predict(brake_in);
    }
  }
  Correct(sample, warnings);
  previous_ = sample;
  ++samples_;
  return warnings;
}

void CarObserver::Correct(const ObserverSample& sample,
                          std::vector<DisagreementWarning>& warnings) {
  const double gate_nis = config_.gate_sigma * config_.gate_sigma;
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    const CornerReadings& r = sample.readings[i];
    const double readings[] = {r.tread_temp, r.disc_temp, r.calliper_temp, r.pressure, r.gas_temp};
    for (Sensor s : kAllSensors) {
      const bool tpms = s == Sensor::kPressure || s == Sensor::kGasTemp;
      if (tpms && !wheels_[i]) continue;  // the paper's tyre has no gas to read
      SensorMonitor& m = monitors_[i][static_cast<int>(s)];
      const double reading = readings[static_cast<int>(s)];
      if (!std::isfinite(reading)) {
        ++m.missing;
        continue;
      }
      ++m.readings;
      const UpdateOutcome u = Update(i, s, reading, gate_nis);
      const std::optional<double> since = m.Record(sample.time, u.nis, u.used, config_.window_s,
                                                   config_.disagree_nis, config_.disagree_after_s);
      if (since) {
        DisagreementWarning w;
        w.corner = c;
        w.sensor = s;
        w.since_s = *since;
        w.time_s = sample.time;
        w.nis_average = m.nis_average();
        w.message = fmt::format(
            "{} {}: model and car disagree since t = {:.2f} s ({:.1f} s; running mean normalised "
            "innovation {:.1f}, expected about 1; a sensor fault or a changed car)",
            CornerName(c), SensorQuantity(s), w.since_s, w.time_s - w.since_s, w.nis_average);
        warnings.push_back(std::move(w));
      }
    }
  }
}

UpdateOutcome CarObserver::Update(int i, Sensor s, double reading, double gate_nis) {
  const SensorNoise& noise = config_.sensors[i];
  if (wheels_[i]) {
    WheelFilter& w = *wheels_[i];
    const CarModelsNoise& n = *config_.car_models;
    switch (s) {
      case Sensor::kTread:
        return w.UpdateTread(reading, noise.tread_temp, gate_nis);
      case Sensor::kDisc:
        return w.UpdateDisc(reading, noise.disc_temp, gate_nis);
      case Sensor::kCalliper:
        return w.UpdateCalliper(reading, noise.calliper_temp, gate_nis);
      case Sensor::kPressure:
        return w.UpdatePressure(reading, n.pressure_sd, gate_nis);
      case Sensor::kGasTemp:
        return w.UpdateGasTemp(reading, n.gas_temp_sd, gate_nis);
    }
  }
  return s == Sensor::kTread  ? tyres_[i].UpdateTread(reading, noise.tread_temp, gate_nis)
         : s == Sensor::kDisc ? brakes_[i].UpdateDisc(reading, noise.disc_temp, gate_nis)
                              : brakes_[i].UpdateCalliper(reading, noise.calliper_temp, gate_nis);
}

CornerEstimate CarObserver::Estimate(Corner c) const {
  const int i = CornerIndex(c);
  const auto sd = [](double var) { return std::sqrt(std::max(var, 0.0)); };
  CornerEstimate e;
  // The mean and sd of state k of Gaussian g into `mean` and `mean_sd`.
  const auto take = [&](const auto& g, int k, double& mean, double& mean_sd) {
    mean = g.mean(k);
    mean_sd = sd(g.cov(k, k));
  };
  if (wheels_[i]) {
    using W = WheelFilter;
    const Gaussian<W::kStates> w = wheels_[i]->estimate();
    take(w, W::kTread, e.tread_temp, e.tread_temp_sd);
    take(w, W::kCarcass, e.carcass_temp, e.carcass_temp_sd);
    take(w, W::kWear, e.wear, e.wear_sd);
    take(w, W::kDisc, e.disc_temp, e.disc_temp_sd);
    take(w, W::kCalliper, e.calliper_temp, e.calliper_temp_sd);
    take(w, W::kRim, e.rim_temp, e.rim_temp_sd);
    take(w, W::kBulk, e.disc_bulk_temp, e.disc_bulk_temp_sd);
    const GasEstimate gas = wheels_[i]->Gas();
    e.has_gas = true;
    e.gas_temp = gas.gas_temp;
    e.gas_temp_sd = gas.gas_temp_sd;
    e.pressure = gas.pressure;
    e.pressure_sd = gas.pressure_sd;
    return e;
  }
  const Gaussian<TyreFilter::kStates>& t = tyres_[i].estimate();
  const Gaussian<BrakeFilter::kStates>& b = brakes_[i].estimate();
  take(t, TyreFilter::kTread, e.tread_temp, e.tread_temp_sd);
  take(t, TyreFilter::kCarcass, e.carcass_temp, e.carcass_temp_sd);
  take(t, TyreFilter::kWear, e.wear, e.wear_sd);
  take(t, TyreFilter::kP5Scale, e.p5_scale, e.p5_scale_sd);
  take(b, BrakeFilter::kDisc, e.disc_temp, e.disc_temp_sd);
  take(b, BrakeFilter::kCalliper, e.calliper_temp, e.calliper_temp_sd);
  return e;
}

std::vector<std::string> EstimateColumns(const CarObserver& observer) {
  std::vector<std::string> names = {"time_s"};
  const auto with_sd = [&](const std::string& q, const std::string& c, const char* unit) {
    names.push_back(fmt::format("{}_{}_{}", q, c, unit));
    names.push_back(fmt::format("{}_{}_sd_{}", q, c, unit));
  };
  for (Corner c : kAllCorners) {
    const std::string n(CornerName(c));
    with_sd("tread_temp", n, "C");
    with_sd("carcass_temp", n, "C");
    with_sd("wear", n, "mm");
    with_sd("disc_temp", n, "C");
    with_sd("calliper_temp", n, "C");
    if (observer.config().p5_scale.estimate) {
      names.push_back(fmt::format("p5_scale_{}", n));
      names.push_back(fmt::format("p5_scale_{}_sd", n));
    }
    if (observer.observes_gas(c)) {
      with_sd("rim_temp", n, "C");
      with_sd("disc_bulk_temp", n, "C");
      with_sd("gas_temp", n, "C");
      with_sd("pressure", n, "kPa");
    }
  }
  return names;
}

std::vector<double> EstimateRow(const CarObserver& observer) {
  std::vector<double> row = {observer.time()};
  for (Corner c : kAllCorners) {
    const CornerEstimate e = observer.Estimate(c);
    row.insert(row.end(),
               {KelvinToCelsius(e.tread_temp), e.tread_temp_sd, KelvinToCelsius(e.carcass_temp),
                e.carcass_temp_sd, e.wear, e.wear_sd, KelvinToCelsius(e.disc_temp), e.disc_temp_sd,
                KelvinToCelsius(e.calliper_temp), e.calliper_temp_sd});
    if (observer.config().p5_scale.estimate) row.insert(row.end(), {e.p5_scale, e.p5_scale_sd});
    if (e.has_gas) {
      row.insert(row.end(),
                 {KelvinToCelsius(e.rim_temp), e.rim_temp_sd, KelvinToCelsius(e.disc_bulk_temp),
                  e.disc_bulk_temp_sd, KelvinToCelsius(e.gas_temp), e.gas_temp_sd,
                  1e-3 * e.pressure, 1e-3 * e.pressure_sd});
    }
  }
  return row;
}

}  // namespace hotlap::observe
