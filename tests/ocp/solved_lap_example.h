#pragma once
// Hand-made solved laps of three nodes (no solve), for the tests of what is written and printed
// of an optimal-lap run.

#include <optional>
#include <string>

#include "hotlap/common/units.h"
#include "hotlap/ocp/disc_limit_comparison.h"

namespace hotlap::ocp::testing {

/// A lap labelled `label` of `lap_time_s` with, if given, a front-disc limit (degC).
inline SolvedLap MakeExampleSolvedLap(const std::string& label, double lap_time_s,
                                      std::optional<double> limit_C = std::nullopt) {
  SolvedLap s;
  s.label = label;
  if (limit_C) s.front_disc_limit = CelsiusToKelvin(*limit_C);
  LapSolution& sol = s.run.solution;
  sol.distance = {0.0, 100.0, 200.0};
  sol.time = {0.0, 1.5, 3.0};
  sol.u = {70.0, 60.0, 70.0};
  sol.v = sol.r = sol.n = sol.xi = sol.steer = {0.0, 0.01, 0.0};
  sol.pedal = {1.0, -0.5, 1.0};
  sol.drive_power = {5e5, 0.0, 5e5};
  sol.brake_force = {0.0, 8e3, 0.0};
  for (CornerTrace& t : sol.corners) {
    t.fz = t.fx = t.fy = t.slip_angle = t.slip_ratio = t.speed = t.wear =
        t.brake_power = {1.0, 2.0, 3.0};
    t.tread_temp = {CelsiusToKelvin(90.0), CelsiusToKelvin(95.0), CelsiusToKelvin(92.0)};
    t.carcass_temp = {CelsiusToKelvin(70.0), CelsiusToKelvin(71.0), CelsiusToKelvin(71.0)};
    t.disc_temp = {CelsiusToKelvin(400.0), CelsiusToKelvin(480.0), CelsiusToKelvin(450.0)};
    t.calliper_temp = {CelsiusToKelvin(150.0), CelsiusToKelvin(150.0), CelsiusToKelvin(151.0)};
  }
  sol.solve.status = SolveStatus::kConverged;
  sol.solve.message = "Optimal Solution Found";
  sol.solve.iterations = 42;
  sol.solve.regularized_iterations = 3;
  sol.solve.solve_seconds = 1.234567891234;
  sol.variables = 300;
  sol.constraints = 280;
  s.run.qss_lap_time = lap_time_s + 0.5;
  s.run.start_laps = 4;
  s.run.start_carcass_rise_K = 12.5;
  s.figures.lap_time_s = lap_time_s;
  s.figures.top_speed_mps = 70.0;
  s.figures.min_speed_mps = 60.0;
  s.figures.max_front_disc_temp_C = 480.0;
  s.figures.peak_disc_temp_C = {480.0, 481.0, 300.0, 301.0};
  s.figures.peak_tread_temp_C = {95.0, 95.5, 93.0, 93.5};
  s.figures.wear_mm = {0.01, 0.011, 0.012, 0.013};
  s.figures.brake_energy_J = 2.5e6;
  s.approaches = {{.turn = "turn 1",
                   .entry_m = 150.0,
                   .lift_m = 120.0,
                   .brake_m = std::nullopt,
                   .min_speed_mps = 60.0,
                   .min_speed_at_m = 100.0}};
  return s;
}

}  // namespace hotlap::ocp::testing
