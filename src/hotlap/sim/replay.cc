#include "hotlap/sim/replay.h"

#include <algorithm>
#include <cmath>
#include <string>

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

}  // namespace

ReplayResult RunReplay(const vehicle::Car& car, const ReplayInputs& in,
                       const ReplayInitialState& initial, const ReplayOptions& options) {
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
  if (!(options.max_step_s > 0.0)) throw InputError("replay max step must be > 0 s");

  ReplayResult result;
  result.time = in.time;
  for (Corner c : kAllCorners) {
    const CornerChannels& ch = in.corners[CornerIndex(c)];
    const std::string corner(CornerName(c));
    CheckLength(ch.speed, n, "speed_" + corner);
    CheckLength(ch.fx, n, "fx_" + corner);
    CheckLength(ch.fy, n, "fy_" + corner);
    CheckLength(ch.fz, n, "fz_" + corner);
    CheckLength(ch.slip_angle, n, "slip_angle_" + corner);
    CheckLength(ch.slip_ratio, n, "slip_ratio_" + corner);

    const CornerSamples samples{in.time,       ch.speed,      ch.fx,           ch.fy,        ch.fz,
                                ch.slip_angle, ch.slip_ratio, in.ambient_temp, in.track_temp};
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
    IntegrateBrake<double>(brake_file.params, samples, initial.brakes[CornerIndex(c)],
                           options.max_step_s, [&](size_t k, const brake::BrakeState<double>& x) {
                             CheckTemperature(x.disc_temp, "disc", c, in.time[k]);
                             CheckTemperature(x.calliper_temp, "calliper", c, in.time[k]);
                             h.disc_temp[k] = x.disc_temp;
                             h.calliper_temp[k] = x.calliper_temp;
                             h.brake_power[k] = brake::CalcBrakePower(ch.speed[k], ch.fx[k]);
                           });
  }
  return result;
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

}  // namespace hotlap::sim
