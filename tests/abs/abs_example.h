#pragma once
// A hand-made ABS braking event of three samples and its figures, for the tests of what is
// written of a run (no simulation).

#include "hotlap/abs/abs_config.h"
#include "hotlap/abs/abs_metrics.h"
#include "hotlap/abs/abs_run.h"
#include "hotlap/common/units.h"

namespace hotlap::sim::testing {

inline AbsConfig MakeExampleAbsConfig() {
  AbsConfig config;
  config.name = "example";
  config.path = "abs/example.yaml";
  config.plant.wheel.radius = 0.5;
  config.scenarios.stop_series_surface = "dry";
  config.scenarios.stop_series_interval_s = 30.0;
  return config;
}

inline AbsEvent MakeExampleAbsEvent() {
  AbsEvent event;
  event.initial_speed_mps = 20.0;
  event.duration_s = 2.0;
  event.surface = "dry";
  return event;
}

inline AbsRunResult MakeExampleAbsRun() {
  AbsRunResult run;
  AbsHistory& h = run.history;
  h.time = {0.0, 0.1, 0.2};
  h.distance = {0.0, 2.0, 3.9};
  h.speed = {20.0, 19.0, 18.0};
  h.wheel_speed = {40.0, 30.0, 34.0};
  h.lambda = {0.0, 0.21, 0.06};
  h.transient_slip = {0.0, -0.2, -0.05};
  h.driver_pressure = {0.0, 5e6, 5e6};
  h.pressure_target = {0.0, 4e6, 3e6};
  h.pressure = {0.0, 3e6, 2.5e6};
  h.brake_torque = {0.0, 900.0, 700.0};
  h.fx = {0.0, -4000.0, -3500.0};
  h.friction = {0.9, 0.9, 0.9};
  h.disc_temp = {CelsiusToKelvin(100.0), CelsiusToKelvin(101.5), CelsiusToKelvin(103.0)};
  h.calliper_temp = {CelsiusToKelvin(60.0), CelsiusToKelvin(60.0), CelsiusToKelvin(60.5)};
  h.state = {0, 4, 2};
  h.locked = {0, 0, 1};
  return run;
}

inline AbsMetrics MakeExampleAbsMetrics() {
  AbsMetrics m;
  m.stopped = true;
  m.stop_time_s = 1.5;
  m.stopping_distance_m = 15.123456789012;
  m.distance_m = 15.2;
  m.end_time_s = 1.6;
  m.final_speed_mps = 0.0;
  m.cycles = 3;
  m.cycles_per_s = 2.5;
  m.first_cycle_start_s = 0.1;
  m.max_lambda = 0.21;
  m.peak_disc_temp_K = CelsiusToKelvin(103.0);
  m.peak_calliper_temp_K = CelsiusToKelvin(60.5);
  m.final_disc_temp_K = CelsiusToKelvin(102.0);
  m.energy.kinetic_lost_J = 1000.0;
  m.energy.brake_J = 900.0;
  m.energy.tyre_slip_J = 90.0;
  m.energy.rolling_resistance_J = 10.0;
  m.energy.closure_error = 1.23456e-5;
  return m;
}

}  // namespace hotlap::sim::testing
