#include "hotlap/sim/synth.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "hotlap/common/csv.h"
#include "hotlap/common/error.h"
#include "hotlap/logs/telemetry.h"
#include "hotlap/sim/sampled_inputs.h"
#include "hotlap/sim/synth_sensor.h"

namespace hotlap::sim {

namespace {

// Linear interpolation of y(x) at `at` (x increasing; held beyond the ends).
double Interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  if (at <= x.front()) return y.front();
  if (at >= x.back()) return y.back();
  const size_t j = std::upper_bound(x.begin(), x.end(), at) - x.begin();
  const double f = (at - x[j - 1]) / (x[j] - x[j - 1]);
  return y[j - 1] + f * (y[j] - y[j - 1]);
}

void CheckOptions(const SynthOptions& o) {
  if (o.laps < 1) throw InputError(fmt::format("synth: laps must be >= 1, got {}", o.laps));
  if (!(o.rate_hz > 0.0) || !std::isfinite(o.rate_hz)) {
    throw InputError(fmt::format("synth: rate must be > 0 Hz, got {:g}", o.rate_hz));
  }
  for (const auto& [value, name] :
       {std::pair{o.temp_noise_K, "temperature noise"}, std::pair{o.sensor_lag_s, "sensor lag"},
        std::pair{o.wear_noise_mm, "wear noise"}, std::pair{o.radius_noise_m, "radius noise"}}) {
    if (!(value >= 0.0) || !std::isfinite(value)) {
      throw InputError(fmt::format("synth: {} must be finite and >= 0, got {:g}", name, value));
    }
  }
  for (const auto& [value, name] : {std::pair{o.tpms.pressure_noise_kPa, "TPMS pressure noise"},
                                    std::pair{o.tpms.temp_noise_K, "TPMS temperature noise"},
                                    std::pair{o.tpms.lag_s, "TPMS lag"}}) {
    if (!(value >= 0.0) || !std::isfinite(value)) {
      throw InputError(fmt::format("synth: {} must be finite and >= 0, got {:g}", name, value));
    }
  }
  if (o.process_noise && !o.paper_models) {
    throw InputError(
        "synth: process noise makes a stochastic truth of the paper's models only; not with the "
        "car's own models");
  }
  if (o.process_noise) {
    const SynthProcessNoise& q = *o.process_noise;
    for (const auto& [value, name] :
         {std::pair{q.tread_temp_K2_per_s, "tread_temp_K2_per_s"},
          std::pair{q.carcass_temp_K2_per_s, "carcass_temp_K2_per_s"},
          std::pair{q.wear_mm2_per_s, "wear_mm2_per_s"},
          std::pair{q.disc_temp_K2_per_s, "disc_temp_K2_per_s"},
          std::pair{q.calliper_temp_K2_per_s, "calliper_temp_K2_per_s"}}) {
      if (!(value >= 0.0) || !std::isfinite(value)) {
        throw InputError(
            fmt::format("synth: process noise {} must be finite and >= 0, got {:g}", name, value));
      }
    }
  }
}

void CheckTruthTemperature(double temp, const char* what, Corner c, double time) {
  if (!(temp > 0.0 && temp < 3000.0)) {
    throw NumericalError(fmt::format(
        "synth: the stochastic truth diverged: {} temperature of corner {} is {:g} K at t = {:g} "
        "s; lower the process noise",
        what, CornerName(c), temp, time));
  }
}

// Samples k and k+1 of `in` alone.
CornerSamples Interval(const CornerSamples& in, size_t k) {
  return {in.time.subspan(k, 2),       in.speed.subspan(k, 2),        in.fx.subspan(k, 2),
          in.fy.subspan(k, 2),         in.fz.subspan(k, 2),           in.slip_angle.subspan(k, 2),
          in.slip_ratio.subspan(k, 2), in.ambient_temp.subspan(k, 2), in.track_temp.subspan(k, 2)};
}

}  // namespace

ReplayResult RunStochasticReplay(const vehicle::Car& any_car, const ReplayInputs& in,
                                 const ReplayInitialState& initial, double max_step_s,
                                 const SynthProcessNoise& q, uint64_t seed) {
  // The stochastic truth is the paper's models' (synth.h).
  const vehicle::Car car = vehicle::PaperModelsOf(any_car);
  const size_t n = in.time.size();
  if (n < 2) throw InputError("synth: the stochastic truth needs at least two samples");
  if (!(max_step_s > 0.0)) throw InputError("synth: max step must be > 0 s");
  GaussianNoise noise(seed);
  ReplayResult result;
  result.time = in.time;
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    const CornerChannels& ch = in.corners[i];
    for (const std::vector<double>* v : {&ch.speed, &ch.fx, &ch.fy, &ch.fz, &ch.slip_angle,
                                         &ch.slip_ratio, &in.ambient_temp, &in.track_temp}) {
      if (v->size() != n) {
        throw InputError(fmt::format("synth: a channel of corner {} has {} samples, time has {}",
                                     CornerName(c), v->size(), n));
      }
    }
    const CornerSamples samples = CornerSamplesOf(in, c);
    const CornerSamples brake_samples = BrakeSamplesOf(in, c);
    const tyre::TyreFile& tyre_file = car.tyre(c);
    const brake::BrakeFile& brake_file = car.brake(c);
    const tyre::TyreThermalParams<double>& tp = tyre_file.params;
    const tyre::TyreCompound& compound = *tyre_file.compound;
    const tyre::TyreConstants<double> tc = tyre::CalcTyreConstants(tp);
    const brake::BrakeThermalParams<double>& bp = brake_file.params;
    const brake::BrakeConstants<double> bc = brake::CalcBrakeConstants(bp);

    CornerHistory& h = result.corners[i];
    for (auto* v : {&h.tread_temp, &h.carcass_temp, &h.wear, &h.grip_factor, &h.disc_temp,
                    &h.calliper_temp, &h.brake_power}) {
      v->resize(n);
    }
    tyre::TyreState<double> tyre = initial.tyres[i];
    brake::BrakeState<double> brake = initial.brakes[i];
    for (size_t k = 0;; ++k) {
      CheckTruthTemperature(tyre.tread_temp, "tread", c, in.time[k]);
      CheckTruthTemperature(tyre.carcass_temp, "carcass", c, in.time[k]);
      CheckTruthTemperature(brake.disc_temp, "disc", c, in.time[k]);
      CheckTruthTemperature(brake.calliper_temp, "calliper", c, in.time[k]);
      h.tread_temp[k] = tyre.tread_temp;
      h.carcass_temp[k] = tyre.carcass_temp;
      h.wear[k] = tyre.wear;
      h.grip_factor[k] = compound.GripFactor(tyre.tread_temp, tyre.wear);
      h.disc_temp[k] = brake.disc_temp;
      h.calliper_temp[k] = brake.calliper_temp;
      h.brake_power[k] = brake::CalcBrakePower(ch.speed[k], brake_samples.fx[k]);
      if (k + 1 == n) break;
      // The model over the interval, exactly as replay and the observer's prediction take it.
      const CornerSamples two = Interval(samples, k);
      IntegrateOverSamples(
          two, tyre, max_step_s,
          [&](size_t j, double f, const tyre::TyreInputTerms<double>* near) {
            return tyre::CalcTyreInputTerms(tp, tc, compound, two.TyreInputAt<double>(j, f), near);
          },
          [&](const tyre::TyreState<double>& x, const tyre::TyreInputTerms<double>& terms) {
            return tyre::CalcTyreDerivatives(tp, compound, x, terms);
          },
          [&](size_t j, const tyre::TyreState<double>& x) {
            if (j == 1) tyre = x;
          });
      const CornerSamples two_brake = Interval(brake_samples, k);
      IntegrateOverSamples(
          two_brake, brake, max_step_s,
          [&](size_t j, double f, const brake::BrakeInputTerms<double>*) {
            return brake::CalcBrakeInputTerms(bp, bc, two_brake.BrakeInputAt<double>(j, f));
          },
          [&](const brake::BrakeState<double>& x, const brake::BrakeInputTerms<double>& terms) {
            return brake::CalcBrakeDerivatives(bp, x, terms);
          },
          [&](size_t j, const brake::BrakeState<double>& x) {
            if (j == 1) brake = x;
          });
      // The random walk over the interval.
      const double dt = in.time[k + 1] - in.time[k];
      tyre.tread_temp += std::sqrt(q.tread_temp_K2_per_s * dt) * noise.Next();
      tyre.carcass_temp += std::sqrt(q.carcass_temp_K2_per_s * dt) * noise.Next();
      tyre.wear += std::sqrt(q.wear_mm2_per_s * dt) * noise.Next();
      brake.disc_temp += std::sqrt(q.disc_temp_K2_per_s * dt) * noise.Next();
      brake.calliper_temp += std::sqrt(q.calliper_temp_K2_per_s * dt) * noise.Next();
    }
  }
  return result;
}

namespace {

// The QSS laps back to back (each lap's closing sample is the next one's first): the corners'
// channels with the distance and the speed along the lap.
struct JoinedLaps {
  ReplayInputs inputs;
  std::vector<double> distance, speed;
  double total_time_s = 0.0;
};

JoinedLaps JoinLaps(const QssResult& laps, const SynthOptions& o) {
  JoinedLaps out;
  ReplayInputs& joined = out.inputs;
  double t0 = 0.0, s0 = 0.0;
  for (size_t l = 0; l < laps.laps.size(); ++l) {
    const QssLap& lap = laps.laps[l];
    const size_t count = lap.time.size() - (l + 1 < laps.laps.size() ? 1 : 0);
    for (size_t i = 0; i < count; ++i) {
      joined.time.push_back(t0 + lap.time[i]);
      out.distance.push_back(s0 + lap.distance[i]);
      out.speed.push_back(lap.speed[i]);
      for (int c = 0; c < 4; ++c) {
        const CornerChannels& from = lap.corners[c];
        CornerChannels& to = joined.corners[c];
        to.speed.push_back(from.speed[i]);
        to.fx.push_back(from.fx[i]);
        to.fy.push_back(from.fy[i]);
        to.fz.push_back(from.fz[i]);
        to.slip_angle.push_back(from.slip_angle[i]);
        to.slip_ratio.push_back(from.slip_ratio[i]);
        if (!from.brake_fx.empty()) to.brake_fx.push_back(from.brake_fx[i]);
      }
    }
    t0 += lap.time.back();
    s0 += lap.distance.back();
  }
  joined.ambient_temp.assign(joined.time.size(), o.ambient_temp);
  joined.track_temp.assign(joined.time.size(), o.track_temp);
  out.total_time_s = t0;
  return out;
}

// `truth` at the samples' times as a sensor reads it: a first-order lag of `lag_s`, then Gaussian
// noise of `sd` drawn sample by sample from `noise`.
std::vector<double> Sensed(const std::vector<double>& time, const std::vector<double>& truth,
                           double lag_s, double sd, GaussianNoise& noise) {
  FirstOrderLag<double> sensor(lag_s);
  std::vector<double> out(time.size());
  for (size_t k = 0; k < time.size(); ++k)
    out[k] = sensor.Next(time[k], truth[k]) + sd * noise.Next();
  return out;
}

// A column of SI values, written in its quantity's canonical unit.
void AddColumn(SynthLog& log, std::string_view quantity, std::optional<Corner> corner,
               std::vector<double> si) {
  for (double& v : si) v = ConvertSiToCanonical(quantity, v);
  log.columns.push_back(ChannelColumn(quantity, corner, CanonicalUnit(quantity)));
  log.values.push_back(std::move(si));
}

// The TPMS channels of the tyres with a gas node, from a noise stream of their own.
void AddTpmsChannels(const SynthOptions& o, SynthLog& log) {
  if (!o.tpms.enabled) return;
  const std::vector<double>& time = log.inputs.time;
  GaussianNoise noise(TpmsNoiseSeed(o.seed));
  for (Corner c : kAllCorners) {
    const CornerHistory& h = log.truth.corners[CornerIndex(c)];
    if (h.pressure.size() != time.size() || h.gas_temp.size() != time.size()) continue;
    AddColumn(log, "pressure", c,
              Sensed(time, h.pressure, o.tpms.lag_s, 1e3 * o.tpms.pressure_noise_kPa, noise));
    AddColumn(log, "gas_temp", c,
              Sensed(time, h.gas_temp, o.tpms.lag_s, o.tpms.temp_noise_K, noise));
  }
}

// The log's channels at its rate: the inputs as they are, the truth's temperatures and wear as a
// lagged, noisy sensor reads them, and the rolling radius with its noise (one noise stream from
// the seed, drawn in the columns' order).
void AddSynthChannels(const vehicle::Car& car, const JoinedLaps& joined, const SynthOptions& o,
                      SynthLog& log) {
  const ReplayInputs& in = log.inputs;
  const size_t n = in.time.size();
  const auto add = [&](std::string_view quantity, std::optional<Corner> corner,
                       std::vector<double> si) { AddColumn(log, quantity, corner, std::move(si)); };
  const auto resample = [&](const std::vector<double>& y) {
    std::vector<double> out(n);
    for (size_t k = 0; k < n; ++k) out[k] = Interpolate(joined.inputs.time, y, in.time[k]);
    return out;
  };
  GaussianNoise noise(o.seed);
  const auto sensed = [&](const std::vector<double>& truth, double lag, double sd) {
    return Sensed(in.time, truth, lag, sd, noise);
  };
  add("time", std::nullopt, in.time);
  add("distance", std::nullopt, resample(joined.distance));
  add("speed", std::nullopt, resample(joined.speed));
  add("ambient_temp", std::nullopt, in.ambient_temp);
  add("track_temp", std::nullopt, in.track_temp);
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    const CornerChannels& ch = in.corners[i];
    const CornerHistory& h = log.truth.corners[i];
    add("speed", c, ch.speed);
    add("fx", c, ch.fx);
    add("fy", c, ch.fy);
    add("fz", c, ch.fz);
    add("slip_angle", c, ch.slip_angle);
    add("slip_ratio", c, ch.slip_ratio);
    // The brakes' heat input: where the lap's brakes differ from the tyres' forces (the rear
    // discs share the spool's torque) a replay of the log needs it (sim/replay_io.h).
    add("brake_power", c, h.brake_power);
    add("tread_temp", c, sensed(h.tread_temp, o.sensor_lag_s, o.temp_noise_K));
    add("carcass_temp", c, sensed(h.carcass_temp, o.sensor_lag_s, o.temp_noise_K));
    add("disc_temp", c, sensed(h.disc_temp, o.sensor_lag_s, o.temp_noise_K));
    add("calliper_temp", c, sensed(h.calliper_temp, o.sensor_lag_s, o.temp_noise_K));
    add("wear", c, sensed(h.wear, 0.0, o.wear_noise_mm));
    // Rolling radius from the load: the contact patch is a chord of the unloaded circle.
    const tyre::TyreThermalParams<double>& p = car.tyre(c).params;
    std::vector<double> radius(n);
    for (size_t k = 0; k < n; ++k) {
      const double half = 0.5 * tyre::CalcContactLength(p, ch.fz[k]);
      const double r2 = p.unloaded_radius * p.unloaded_radius - half * half;
      radius[k] = r2 > 0.0 ? std::sqrt(r2) + o.radius_noise_m * noise.Next()
                           : std::numeric_limits<double>::quiet_NaN();
    }
    add("rolling_radius", c, std::move(radius));
  }
  AddTpmsChannels(o, log);
}

std::vector<std::pair<std::string, std::string>> SynthMetadata(const vehicle::Car& car,
                                                               const SynthOptions& o,
                                                               double lap_time_s) {
  std::vector<std::pair<std::string, std::string>> metadata = {
      {"source", fmt::format("hotlap {} synth: simulated, not measured", HOTLAP_VERSION)},
      {"car", car.name},
      {"laps", std::to_string(o.laps)},
      {"lap_time_s", fmt::format("{:.6f}", lap_time_s)},
      {"rate_hz", fmt::format("{:g}", o.rate_hz)},
      {"temp_noise_C", fmt::format("{:g}", o.temp_noise_K)},
      {"sensor_lag_s", fmt::format("{:g}", o.sensor_lag_s)},
      {"wear_noise_mm", fmt::format("{:g}", o.wear_noise_mm)},
      {"rolling_radius_noise_mm", fmt::format("{:g}", 1e3 * o.radius_noise_m)},
      {"seed", std::to_string(o.seed)},
  };
  if (!o.paper_models) metadata.push_back({"truth", "the car's own models"});
  if (o.tpms.enabled && !o.paper_models) {
    metadata.push_back(
        {"tpms", fmt::format("pressure noise {:g} kPa, gas temperature noise {:g} C, lag {:g} s",
                             o.tpms.pressure_noise_kPa, o.tpms.temp_noise_K, o.tpms.lag_s)});
  }
  if (o.process_noise) {
    // Only with the option, so that a log without it is what it always was.
    const SynthProcessNoise& q = *o.process_noise;
    metadata.push_back(
        {"process_noise",
         fmt::format("random walk on the true states, intensities tread {:g} K^2/s, carcass {:g} "
                     "K^2/s, wear {:g} mm^2/s, disc {:g} K^2/s, calliper {:g} K^2/s",
                     q.tread_temp_K2_per_s, q.carcass_temp_K2_per_s, q.wear_mm2_per_s,
                     q.disc_temp_K2_per_s, q.calliper_temp_K2_per_s)});
  }
  if (!car.overrides.empty()) {
    metadata.insert(metadata.begin() + 2, {"overrides", vehicle::OverridesText(car.overrides)});
  }
  return metadata;
}

}  // namespace

SynthLog SynthesizeLog(const vehicle::Car& any_car, std::span<const RoadPoint> road,
                       const SynthOptions& o) {
  CheckOptions(o);
  vehicle::RequireVehicle(any_car, "hotlap synth (the lap simulation)");
  // By default the truth is the paper's models, which the fits identify and the observer tracks
  // (docs/fitting.md): a gas-and-rim tyre or a bulk disc runs as its paper part.
  const vehicle::Car car = o.paper_models ? vehicle::PaperModelsOf(any_car) : any_car;
  ReplayInitialState initial;
  if (o.initial) {
    initial = *o.initial;
  } else {
    initial = CarStartState(car);
  }
  QssOptions qss;
  qss.laps = o.laps;
  qss.ambient_temp = o.ambient_temp;
  qss.track_temp = o.track_temp;
  qss.initial = initial;
  qss.replay.max_step_s = o.max_step_s;
  const QssResult laps = RunQssLap(car, road, qss);
  const JoinedLaps joined = JoinLaps(laps, o);

  SynthLog log;
  log.lap_time_s = joined.total_time_s / static_cast<double>(laps.laps.size());
  log.inputs = ResampleReplayInputs(joined.inputs, o.rate_hz, 1);
  ReplayOptions replay;
  replay.max_step_s = o.max_step_s;
  log.truth = o.process_noise ? RunStochasticReplay(car, log.inputs, initial, o.max_step_s,
                                                    *o.process_noise, ProcessNoiseSeed(o.seed))
                              : RunReplay(car, log.inputs, initial, replay);
  AddSynthChannels(car, joined, o, log);
  log.metadata = SynthMetadata(car, o, log.lap_time_s);
  return log;
}

void WriteSynthLog(const std::filesystem::path& path, const SynthLog& log,
                   const std::vector<std::pair<std::string, std::string>>& extra_metadata) {
  auto metadata = log.metadata;
  metadata.insert(metadata.end(), extra_metadata.begin(), extra_metadata.end());
  WriteCsv(path, metadata, log.columns, log.values);
}

}  // namespace hotlap::sim
