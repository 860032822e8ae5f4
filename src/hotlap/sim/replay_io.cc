#include "hotlap/sim/replay_io.h"

#include <fmt/format.h>

#include "hotlap/brake/brake_thermal.h"
#include "hotlap/common/error.h"
#include "hotlap/common/units.h"

namespace hotlap::sim {

namespace {

std::vector<double> AmbientLike(const Telemetry& log, std::string_view quantity,
                                const std::optional<double>& fallback, std::string_view option) {
  // A column with no value on any row (a dead sensor) is as good as none: the option stands in.
  if (log.Has(quantity) && log.FirstValue(quantity)) return log.FilledChannel(quantity);
  if (fallback) return std::vector<double>(log.size(), *fallback);
  if (log.Has(quantity)) {
    throw InputError(
        fmt::format("{}: column '{}_C' (or '_K') has no value on any row, and none "
                    "given instead ({})",
                    log.path().string(), quantity, option));
  }
  throw InputError(fmt::format("{}: no '{}_C' (or '{}_K') column, and none given instead ({})",
                               log.path().string(), quantity, quantity, option));
}

double StartValue(const Telemetry& log, std::string_view quantity, Corner c,
                  const std::optional<double>& override_value, double car_default) {
  if (auto measured = log.FirstValue(quantity, c)) return *measured;
  if (override_value) return *override_value;
  return car_default;
}

}  // namespace

ReplayInputs ReplayInputsFromTelemetry(const Telemetry& log,
                                       const InitialTemperatureOverrides& overrides) {
  ReplayInputs in;
  in.time = log.Channel("time");
  for (Corner c : kAllCorners) {
    CornerChannels& ch = in.corners[CornerIndex(c)];
    ch.speed = log.CornerSpeed(c);
    ch.fx = log.FilledChannel("fx", c);
    ch.fy = log.FilledChannel("fy", c);
    ch.fz = log.FilledChannel("fz", c);
    ch.slip_angle = log.FilledChannel("slip_angle", c);
    ch.slip_ratio = log.FilledChannel("slip_ratio", c);
    // A logged braking power is the brake model's heat input (brake/brake_thermal.h).
    if (log.Has("brake_power", c)) {
      const std::vector<double> power = log.FilledChannel("brake_power", c);
      ch.brake_fx.resize(power.size());
      for (size_t k = 0; k < power.size(); ++k) {
        ch.brake_fx[k] = brake::BrakeFxFromPower(ch.speed[k], power[k], ch.fx[k]);
      }
    }
  }
  in.ambient_temp = AmbientLike(log, "ambient_temp", overrides.ambient_temp,
                                "hotlap: --ambient-temp-C; Python: ambient_temp_C=");
  in.track_temp = AmbientLike(log, "track_temp", overrides.track_temp,
                              "hotlap: --track-temp-C; Python: track_temp_C=");
  return in;
}

ReplayInitialState CarStartState(const vehicle::Car& car, const InitialTemperatureOverrides& o) {
  ReplayInitialState s = CarStartState(car);
  for (int i = 0; i < 4; ++i) {
    tyre::TyreState<double>& t = s.tyres[i];
    brake::BrakeState<double>& b = s.brakes[i];
    t.tread_temp = o.tread_temp.value_or(t.tread_temp);
    t.carcass_temp = o.carcass_temp.value_or(t.carcass_temp);
    t.rim_temp = o.rim_temp.value_or(t.rim_temp);
    b.disc_temp = o.disc_temp.value_or(b.disc_temp);
    b.calliper_temp = o.calliper_temp.value_or(b.calliper_temp);
    b.bulk_temp = o.disc_bulk_temp.value_or(b.bulk_temp);
  }
  return s;
}

ReplayInitialState InitialStateFor(const Telemetry& log, const vehicle::Car& car,
                                   const InitialTemperatureOverrides& o) {
  ReplayInitialState s;
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    s.tyres[i].tread_temp = StartValue(log, "tread_temp", c, o.tread_temp, car.initial.tread_temp);
    s.tyres[i].carcass_temp =
        StartValue(log, "carcass_temp", c, o.carcass_temp, car.initial.carcass_temp);
    s.tyres[i].wear = 0.0;
    s.brakes[i].disc_temp = StartValue(log, "disc_temp", c, o.disc_temp, car.initial.disc_temp);
    s.brakes[i].calliper_temp =
        StartValue(log, "calliper_temp", c, o.calliper_temp, car.initial.calliper_temp);
    // No logger reads a rim or a disc's bulk: the overrides, else the car's starting values.
    s.tyres[i].rim_temp = o.rim_temp.value_or(car.initial.rim_temp);
    s.brakes[i].bulk_temp = o.disc_bulk_temp.value_or(car.initial.disc_bulk_temp);
  }
  return s;
}

ColumnSet ReplayResultColumns(const ReplayResult& result, bool with_heat_flows) {
  ColumnSet out;
  const auto add = [&](std::string name, std::vector<double> values) {
    out.names.push_back(std::move(name));
    out.values.push_back(std::move(values));
  };
  const auto celsius = [](std::vector<double> kelvin) {
    for (double& x : kelvin) x = KelvinToCelsius(x);
    return kelvin;
  };
  add("time_s", result.time);
  for (Corner c : kAllCorners) {
    const CornerHistory& h = result.corners[CornerIndex(c)];
    const std::string_view n = CornerName(c);
    add(fmt::format("tread_temp_{}_C", n), celsius(h.tread_temp));
    add(fmt::format("carcass_temp_{}_C", n), celsius(h.carcass_temp));
    add(fmt::format("wear_{}_mm", n), h.wear);
    add(fmt::format("grip_factor_{}", n), h.grip_factor);
    add(fmt::format("disc_temp_{}_C", n), celsius(h.disc_temp));
    add(fmt::format("calliper_temp_{}_C", n), celsius(h.calliper_temp));
    add(fmt::format("brake_power_{}_W", n), h.brake_power);
    for (const auto& [name, member] : ModelChannels()) {
      if ((h.*member).empty()) continue;
      std::vector<double> values = h.*member;
      for (double& v : values) v = ModelChannelValue(member, v);
      add(fmt::format(fmt::runtime(name), n), std::move(values));
    }
    if (with_heat_flows) {
      for (int q = 0; q < 7; ++q) add(fmt::format("q{}_{}_W", q + 1, n), h.heat_flows[q]);
    }
  }
  return out;
}

}  // namespace hotlap::sim
