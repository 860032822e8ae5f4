#pragma once
// A small hand-made fit of one corner (two model parameters, one nuisance, one held, one channel
// pair over three samples) for the tests of what is written of a fit run.

#include <cmath>
#include <limits>

#include "hotlap/ident/fit_run.h"

namespace hotlap::ident::testing {

inline FitRun MakeExampleFitRun() {
  FitRun run;
  run.command = "fit tyre";
  run.telemetry = "logs/run1.csv";
  run.car_name = "gen7";
  run.car_path = "data/cars/gen7/car.yaml";
  run.out = "fitted/car.yaml";
  run.time = {0.0, 0.5, 1.0};
  run.log_metadata = {{"track", "darlington"}};
  run.options = {{"loss", "huber"}};
  run.elapsed_s = 1.23456789012;
  run.result.joint_family_size = 2;

  CornerFitOutcome c;
  c.corner = Corner::kRearRight;
  c.fitted = true;
  c.rms = {{"rms_tread_C", 0.512345}};
  c.truth = {{"p1", 0.5}};
  c.warnings = {"short log"};
  ReportedFit r;
  r.title = "thermal";
  r.held = {{"p4", 7.0}};
  r.fit.parameters = {{.key = "p1", .label = "p1", .unit = "", .scale = 1.0},
                      {.key = "t0_K",
                       .label = "T0",
                       .unit = "degC",
                       .role = ParameterRole::kNuisance,
                       .display_offset = -273.15},
                      {.key = "p5", .label = "p5", .unit = "W/(m2 K)", .scale = 100.0}};
  ParameterEstimate e1{.value = 0.49, .std_error = 0.01, .ci_low = 0.47, .ci_high = 0.51};
  e1.joint_low = 0.46;
  e1.joint_high = 0.52;
  e1.well_determined = true;
  e1.start = 0.3;
  ParameterEstimate e2{.value = 300.0, .std_error = 0.5, .ci_low = 299.0, .ci_high = 301.0};
  e2.start = 293.15;
  ParameterEstimate e3{.value = 640.0, .std_error = std::numeric_limits<double>::infinity()};
  e3.ci_low = 0.0;
  e3.ci_high = 1000.0;
  e3.undetermined = true;
  r.fit.estimates = {e1, e2, e3};
  r.fit.correlation = Eigen::MatrixXd::Identity(3, 3);
  r.fit.correlation(0, 2) = r.fit.correlation(2, 0) = std::nan("");
  r.fit.channels = {{.name = "tread_temp", .samples = 3, .rms = 0.5, .sigma = 0.4}};
  r.fit.converged = true;
  r.fit.iterations = 12;
  r.fit.warnings = {"p5 is undetermined"};
  c.fits = {r};
  c.channels = {{.quantity = "tread_temp",
                 .title = "tread temperature",
                 .unit = "\u00b0C",
                 .column_unit = "C",
                 .measured = {50.0, 51.0, 52.0},
                 .model = {50.5, 51.0, 51.5}}};
  run.result.corners = {c};
  return run;
}

}  // namespace hotlap::ident::testing
