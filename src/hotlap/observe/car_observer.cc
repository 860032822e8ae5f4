#include "hotlap/observe/car_observer.h"

#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"

namespace hotlap::observe {

CarObserver::CarObserver(const vehicle::Car& car, ObserverConfig config, const ObserverStart& start)
    : config_(std::move(config)), car_initial_(car.initial), start_(start) {
  tyres_.reserve(4);
  brakes_.reserve(4);
  for (Corner c : kAllCorners) {
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
    tyres_[i].Predict(in);
    if (std::isfinite(x.brake_fx) || std::isfinite(y.brake_fx)) {  // the brake's own force
      const std::array<double, 2> brake_fx = {std::isfinite(x.brake_fx) ? x.brake_fx : x.fx,
                                              std::isfinite(y.brake_fx) ? y.brake_fx : y.fx};
      sim::CornerSamples brake_in = in;
      brake_in.fx = brake_fx;
      brakes_[i].Predict(brake_in);
    } else {
      brakes_[i].Predict(in);
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
    const SensorNoise& noise = config_.sensors[i];
    for (Sensor s : kAllSensors) {
      SensorMonitor& m = monitors_[i][static_cast<int>(s)];
      const double reading = s == Sensor::kTread  ? r.tread_temp
                             : s == Sensor::kDisc ? r.disc_temp
                                                  : r.calliper_temp;
      if (!std::isfinite(reading)) {
        ++m.missing;
        continue;
      }
      ++m.readings;
      const UpdateOutcome u =
          s == Sensor::kTread  ? tyres_[i].UpdateTread(reading, noise.tread_temp, gate_nis)
          : s == Sensor::kDisc ? brakes_[i].UpdateDisc(reading, noise.disc_temp, gate_nis)
                               : brakes_[i].UpdateCalliper(reading, noise.calliper_temp, gate_nis);
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

CornerEstimate CarObserver::Estimate(Corner c) const {
  const Gaussian<TyreFilter::kStates>& t = tyres_[CornerIndex(c)].estimate();
  const Gaussian<BrakeFilter::kStates>& b = brakes_[CornerIndex(c)].estimate();
  const auto sd = [](double var) { return std::sqrt(std::max(var, 0.0)); };
  CornerEstimate e;
  e.tread_temp = t.mean(TyreFilter::kTread);
  e.tread_temp_sd = sd(t.cov(TyreFilter::kTread, TyreFilter::kTread));
  e.carcass_temp = t.mean(TyreFilter::kCarcass);
  e.carcass_temp_sd = sd(t.cov(TyreFilter::kCarcass, TyreFilter::kCarcass));
  e.wear = t.mean(TyreFilter::kWear);
  e.wear_sd = sd(t.cov(TyreFilter::kWear, TyreFilter::kWear));
  e.p5_scale = t.mean(TyreFilter::kP5Scale);
  e.p5_scale_sd = sd(t.cov(TyreFilter::kP5Scale, TyreFilter::kP5Scale));
  e.disc_temp = b.mean(BrakeFilter::kDisc);
  e.disc_temp_sd = sd(b.cov(BrakeFilter::kDisc, BrakeFilter::kDisc));
  e.calliper_temp = b.mean(BrakeFilter::kCalliper);
  e.calliper_temp_sd = sd(b.cov(BrakeFilter::kCalliper, BrakeFilter::kCalliper));
  return e;
}

std::vector<std::string> EstimateColumns(bool with_p5_scale) {
  std::vector<std::string> names = {"time_s"};
  for (Corner c : kAllCorners) {
    const std::string n(CornerName(c));
    for (const char* q : {"tread_temp", "carcass_temp"}) {
      names.push_back(fmt::format("{}_{}_C", q, n));
      names.push_back(fmt::format("{}_{}_sd_C", q, n));
    }
    names.push_back(fmt::format("wear_{}_mm", n));
    names.push_back(fmt::format("wear_{}_sd_mm", n));
    for (const char* q : {"disc_temp", "calliper_temp"}) {
      names.push_back(fmt::format("{}_{}_C", q, n));
      names.push_back(fmt::format("{}_{}_sd_C", q, n));
    }
    if (with_p5_scale) {
      names.push_back(fmt::format("p5_scale_{}", n));
      names.push_back(fmt::format("p5_scale_{}_sd", n));
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
  }
  return row;
}

}  // namespace hotlap::observe
