#include "hotlap/sim/replay.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/sim/sampled_inputs.h"

namespace hotlap::sim {

namespace {

void CheckLength(const std::vector<double>& v, size_t n, const std::string& name) {
  if (v.size() != n) {
    throw InputError(
        fmt::format("replay input '{}' has {} samples, expected {}", name, v.size(), n));
  }
  for (size_t i = 0; i < n; ++i) {
    if (!std::isfinite(v[i])) {
      throw InputError(fmt::format("replay input '{}' is not finite at sample {}", name, i));
    }
  }
}

void CheckTemperature(double temp, const char* what, Corner c, double time) {
  if (!(temp > 0.0 && temp < 3000.0)) {
    throw NumericalError(fmt::format(
        "replay diverged: {} temperature of corner {} is {:g} K at t = {:g} s; check the inputs "
        "(forces, speeds) and the parameters",
        what, CornerName(c), temp, time));
  }
}

// The sample count, after checking it (at least two), the times (finite, strictly increasing) and
// the two temperature channels.
size_t CheckTimesAndTemperatures(const ReplayInputs& in) {
  const size_t n = in.time.size();
  if (n < 2) throw InputError("replay needs at least two samples");
  CheckLength(in.time, n, "time_s");
  for (size_t i = 1; i < n; ++i) {
    if (!(in.time[i] > in.time[i - 1])) {
      throw InputError(fmt::format("replay time is not strictly increasing at sample {}", i));
    }
  }
  CheckLength(in.ambient_temp, n, "ambient_temp");
  CheckLength(in.track_temp, n, "track_temp");
  return n;
}

void CheckCornerChannels(const CornerChannels& ch, size_t n, Corner c) {
  const std::string corner(CornerName(c));
  CheckLength(ch.speed, n, "speed_" + corner);
  CheckLength(ch.fx, n, "fx_" + corner);
  CheckLength(ch.fy, n, "fy_" + corner);
  CheckLength(ch.fz, n, "fz_" + corner);
  CheckLength(ch.slip_angle, n, "slip_angle_" + corner);
  CheckLength(ch.slip_ratio, n, "slip_ratio_" + corner);
}

}  // namespace

CornerSamples CornerSamplesOf(const ReplayInputs& in, Corner corner) {
  const CornerChannels& ch = in.corners[CornerIndex(corner)];
  return {in.time,       ch.speed,      ch.fx,           ch.fy,        ch.fz,
          ch.slip_angle, ch.slip_ratio, in.ambient_temp, in.track_temp};
}

CornerSamples BrakeSamplesOf(const ReplayInputs& in, Corner corner) {
  CornerSamples s = CornerSamplesOf(in, corner);
  const CornerChannels& ch = in.corners[CornerIndex(corner)];
  if (ch.brake_fx.empty()) return s;
  if (ch.brake_fx.size() != in.time.size()) {
    throw InputError(fmt::format("the brake force of corner {} has {} samples, time has {}",
                                 CornerName(corner), ch.brake_fx.size(), in.time.size()));
  }
  s.fx = ch.brake_fx;
  return s;
}

ReplayResult RunReplay(const vehicle::Car& car, const ReplayInputs& in,
                       const ReplayInitialState& initial, const ReplayOptions& options) {
  const size_t n = CheckTimesAndTemperatures(in);
  if (!(options.max_step_s > 0.0)) throw InputError("replay max step must be > 0 s");

  ReplayResult result;
  result.time = in.time;
  for (Corner c : kAllCorners) {
    const CornerChannels& ch = in.corners[CornerIndex(c)];
    CheckCornerChannels(ch, n, c);

    const CornerSamples samples = CornerSamplesOf(in, c);
    const tyre::TyreFile& tyre_file = car.tyre(c);
    const brake::BrakeFile& brake_file = car.brake(c);
    CornerHistory& h = result.corners[CornerIndex(c)];
    for (auto* v : {&h.tread_temp, &h.carcass_temp, &h.wear, &h.grip_factor, &h.disc_temp,
                    &h.calliper_temp, &h.brake_power}) {
      v->resize(n);
    }
    if (options.record_heat_flows) {
      for (auto& q : h.heat_flows) q.resize(n);
    }

    IntegrateTyre<double>(
        tyre_file.params, *tyre_file.compound, samples, initial.tyres[CornerIndex(c)],
        options.max_step_s, [&](size_t k, const tyre::TyreState<double>& x) {
          CheckTemperature(x.tread_temp, "tread", c, in.time[k]);
          CheckTemperature(x.carcass_temp, "carcass", c, in.time[k]);
          h.tread_temp[k] = x.tread_temp;
          h.carcass_temp[k] = x.carcass_temp;
          h.wear[k] = x.wear;
          h.grip_factor[k] = tyre_file.compound->GripFactor(x.tread_temp, x.wear);
          if (options.record_heat_flows) {
            const auto q =
                tyre::CalcTyreHeatFlows(tyre_file.params, x, samples.TyreInputAt<double>(k, 0.0));
            const std::array<double, 7> flows = {q.q1, q.q2, q.q3, q.q4, q.q5, q.q6, q.q7};
            for (int i = 0; i < 7; ++i) h.heat_flows[i][k] = flows[i];
          }
        });
    if (!ch.brake_fx.empty()) CheckLength(ch.brake_fx, n, "brake_fx_" + std::string(CornerName(c)));
    const CornerSamples brake_samples = BrakeSamplesOf(in, c);
    IntegrateBrake<double>(brake_file.params, brake_samples, initial.brakes[CornerIndex(c)],
                           options.max_step_s, [&](size_t k, const brake::BrakeState<double>& x) {
                             CheckTemperature(x.disc_temp, "disc", c, in.time[k]);
                             CheckTemperature(x.calliper_temp, "calliper", c, in.time[k]);
                             h.disc_temp[k] = x.disc_temp;
                             h.calliper_temp[k] = x.calliper_temp;
                             h.brake_power[k] =
                                 brake::CalcBrakePower(ch.speed[k], brake_samples.fx[k]);
                           });
  }
  return result;
}

ReplayInputs ResampleReplayInputs(const ReplayInputs& in, double rate_hz, int laps) {
  if (!(rate_hz > 0.0 && std::isfinite(rate_hz))) {
    throw InputError(fmt::format("resampling rate must be finite and > 0 Hz, got {:g}", rate_hz));
  }
  if (laps < 1) throw InputError(fmt::format("resampling needs at least one lap, got {}", laps));
  const size_t n = CheckTimesAndTemperatures(in);
  for (Corner c : kAllCorners) CheckCornerChannels(in.corners[CornerIndex(c)], n, c);

  const double t0 = in.time.front(), t1 = in.time.back();
  const double period = t1 - t0 + (in.time[1] - in.time[0]);
  // One lap alone covers [t0, t1]; repeated laps fill the whole period each.
  const double per_lap_count =
      laps == 1 ? std::floor((t1 - t0) * rate_hz) + 1.0 : std::floor(period * rate_hz);
  const double total_count = per_lap_count * laps;
  if (total_count < 2.0) {
    throw InputError(fmt::format(
        "resampling at {:g} Hz leaves fewer than two samples of a {:g} s log", rate_hz, t1 - t0));
  }
  if (total_count > static_cast<double>(std::numeric_limits<int>::max())) {
    throw InputError(
        fmt::format("resampling at {:g} Hz over {} laps gives too many samples", rate_hz, laps));
  }
  const size_t per_lap = static_cast<size_t>(per_lap_count);

  // Interval and weight of every grid time within a lap, found by one forward scan: interval j
  // holds time[j] <= t < time[j + 1] (the last interval also takes any t past the end, weight 1).
  std::vector<size_t> interval(per_lap);
  std::vector<double> weight(per_lap);
  size_t j = 0;
  for (size_t k = 0; k < per_lap; ++k) {
    const double t = t0 + k / rate_hz;
    while (j + 2 < n && in.time[j + 1] <= t) ++j;
    interval[k] = j;
    weight[k] = std::clamp((t - in.time[j]) / (in.time[j + 1] - in.time[j]), 0.0, 1.0);
  }
  const auto resample = [&](const std::vector<double>& v) {
    std::vector<double> r(per_lap * laps);
    for (size_t k = 0; k < per_lap; ++k) {
      const size_t i = interval[k];
      r[k] = v[i] + weight[k] * (v[i + 1] - v[i]);
    }
    for (int l = 1; l < laps; ++l) std::copy_n(r.begin(), per_lap, r.begin() + l * per_lap);
    return r;
  };

  ReplayInputs out;
  out.time.reserve(per_lap * laps);
  for (int l = 0; l < laps; ++l) {
    const double start = t0 + l * period;
    for (size_t k = 0; k < per_lap; ++k) out.time.push_back(start + k / rate_hz);
  }
  for (int c = 0; c < 4; ++c) {
    const CornerChannels& a = in.corners[c];
    CornerChannels& b = out.corners[c];
    b.speed = resample(a.speed);
    b.fx = resample(a.fx);
    b.fy = resample(a.fy);
    b.fz = resample(a.fz);
    b.slip_angle = resample(a.slip_angle);
    b.slip_ratio = resample(a.slip_ratio);
    if (!a.brake_fx.empty()) {
      CheckLength(a.brake_fx, n, "brake_fx_" + std::string(CornerName(static_cast<Corner>(c))));
      b.brake_fx = resample(a.brake_fx);
    }
  }
  out.ambient_temp = resample(in.ambient_temp);
  out.track_temp = resample(in.track_temp);
  return out;
}

HistoryStats CalcHistoryStats(const std::vector<double>& time, const std::vector<double>& values) {
  HistoryStats s;
  if (values.empty()) return s;
  s.peak = *std::max_element(values.begin(), values.end());
  s.final = values.back();
  const double span = time.back() - time.front();
  if (values.size() < 2 || span <= 0.0) {
    s.mean = values.front();
    return s;
  }
  double integral = 0.0;
  for (size_t i = 1; i < values.size(); ++i) {
    integral += 0.5 * (values[i] + values[i - 1]) * (time[i] - time[i - 1]);
  }
  s.mean = integral / span;
  return s;
}

std::array<CornerReplaySummary, 4> SummarizeReplay(const ReplayResult& result) {
  std::array<CornerReplaySummary, 4> out;
  const std::vector<double>& t = result.time;
  for (int c = 0; c < 4; ++c) {
    const CornerHistory& h = result.corners[c];
    CornerReplaySummary& s = out[c];
    s.tread = CalcHistoryStats(t, h.tread_temp);
    s.carcass = CalcHistoryStats(t, h.carcass_temp);
    s.disc = CalcHistoryStats(t, h.disc_temp);
    s.calliper = CalcHistoryStats(t, h.calliper_temp);
    s.final_wear_mm = h.wear.empty() ? 0.0 : h.wear.back();
    s.min_grip_factor =
        h.grip_factor.empty() ? 0.0 : *std::min_element(h.grip_factor.begin(), h.grip_factor.end());
    for (size_t i = 1; i < t.size() && i < h.brake_power.size(); ++i) {
      s.brake_energy_J += 0.5 * (h.brake_power[i] + h.brake_power[i - 1]) * (t[i] - t[i - 1]);
    }
  }
  return out;
}

}  // namespace hotlap::sim
