// The optimal-lap commands' options (`hotlap optimise`, `hotlap lap --method ocp`), as
// optimal_runs.h declares them.

#include <string>

#include "commands.h"
#include "optimal_runs.h"

namespace hotlap::app {

void AddOptimalOptions(CLI::App* sub, OptimalArgs& a) {
  sub->add_option("--track", a.track, "Built-in track name or a .yaml/.csv/.xml file")
      ->capture_default_str();
  sub->add_option("--car", a.car, "Built-in car name or path to a car.yaml")->capture_default_str();
  AddSetOption(sub, a.set);
  sub->add_option("--out", a.out, "Output folder")->required();
  sub->add_option("--json", a.json, "Write the summary as JSON (docs/json-output.md)");
  CLI::Option* step_m =
      sub->add_option("--step-m", a.run.step_m, "Mesh spacing along the centre line, m")
          ->capture_default_str()
          ->check(CLI::Range(0.5, 50.0));
  CLI::Option* tolerance = sub->add_option("--tolerance", a.run.tolerance_s,
                                           "Adaptive mesh: the estimated lap-time error asked "
                                           "for, 0 to 1 s (e.g. 2e-4; docs/optimal-control.md)")
                               ->excludes(step_m);
  a.stock_car_only.insert(a.stock_car_only.end(), {step_m, tolerance});
  a.stock_car_only.push_back(
      sub->add_option("--coarse-step-m", a.run.coarse_step_m,
                      "Coarse to fine: solve first on a mesh of this spacing, m, and start the "
                      "--step-m solve from it (0: off; docs/optimal-control.md)")
          ->capture_default_str()
          ->check(CLI::Range(0.0, 100.0)));
  a.stock_car_only.push_back(
      sub->add_option("--collocation", a.run.collocation,
                      "trapezoid, or hermite-simpson (--step-m is then an interval with a node "
                      "at its midpoint; docs/optimal-control.md)")
          ->capture_default_str()
          ->check(CLI::IsMember({"trapezoid", "hermite-simpson"})));
  a.stock_car_only.push_back(sub->add_option("--coarse-collocation", a.run.coarse_collocation,
                                             "The coarse solve's (as --collocation)")
                                 ->capture_default_str()
                                 ->check(CLI::IsMember({"trapezoid", "hermite-simpson"})));
  a.stock_car_only.push_back(
      sub->add_option("--steer-smoothing", a.run.steer_smoothing,
                      "Weight of the steer's smoothness penalty, s per squared scaled change "
                      "between nodes (default: the library's; docs/optimal-control.md)"));
  a.stock_car_only.push_back(
      sub->add_option("--pedal-smoothing", a.run.pedal_smoothing,
                      "Weight of the pedal's smoothness penalty (as --steer-smoothing)"));
  a.stock_car_only.push_back(
      sub->add_option("--hessian", a.hessian,
                      "exact (Ipopt corrects its inertia where needed) or convex-elements (each "
                      "element's negative curvature clipped; docs/optimal-control.md)")
          ->capture_default_str()
          ->check(CLI::IsMember({"exact", "convex-elements"})));
  a.stock_car_only.push_back(sub->add_flag(
      "--wear-in-programme", a.run.wear_in_programme,
      "Keep the tyres' wear as states of the programme (by default the lap freezes "
      "it for the forces and integrates it after the solve; docs/optimal-control.md)"));
  a.stock_car_only.push_back(sub->add_flag(
      "--paper-models", a.run.paper_models,
      "Run the lap on the paper's models (two-mass tyres, lumped discs) instead of the car's own "
      "gas-and-rim tyres and surface-and-bulk discs (docs/optimal-control.md)"));
  a.stock_car_only.push_back(
      sub->add_option("--controls", a.controls,
                      "pedal (one signed pedal: drive or brake, never both) or independent (the "
                      "old drive power and brake force, which the optimiser may apply together; "
                      "for comparison, docs/optimal-control.md)")
          ->capture_default_str()
          ->check(CLI::IsMember({"pedal", "independent"})));
  a.stock_car_only.push_back(
      sub->add_option("--thermal-start", a.run.thermal_start,
                      "Thermal states at the start: racing (QSS laps until no carcass rises over "
                      "5 degC a lap), "
                      "warm (after one QSS out-lap), car (the car file's initial_state) or "
                      "periodic (temperatures end where they start)")
          ->capture_default_str()
          ->check(CLI::IsMember({"racing", "warm", "car", "periodic"})));
  a.stock_car_only.push_back(sub->add_option("--ambient-temp-C", a.run.ambient_C, "Air temperature")
                                 ->capture_default_str());
  a.stock_car_only.push_back(
      sub->add_option("--track-temp-C", a.run.track_C, "Track surface temperature")
          ->capture_default_str());
  sub->add_option("--max-iterations", a.run.max_iterations, "Ipopt's iteration limit")
      ->capture_default_str()
      ->check(kPositive);
  a.stock_car_only.push_back(sub->add_flag(
      "--sensitivities", a.run.sensitivities,
      "After the solve, the lap time's derivative with respect to each set-up parameter (cold "
      "pressures, cambers, brake balance and ducts, weight split, aero, mass) from the solved "
      "lap's multipliers, without solving again (docs/optimal-control.md)"));
  a.stock_car_only.push_back(
      sub->add_flag("--mesh-check", a.mesh_check,
                    "Solve again on a mesh of half the spacing and report the lap time's change")
          ->excludes(tolerance));
  sub->add_flag("--ipopt-output", a.run.ipopt_output, "Print Ipopt's own iteration log");
  a.stock_car_only.push_back(
      sub->add_option(
             "--threads", a.run.threads,
             "Threads evaluating the derivatives of each solve (0: one per core, at most 8; the "
             "comparison's two solves side by side take half each)")
          ->capture_default_str()
          ->check(CLI::Range(0, 256)));
  a.stock_car_only.push_back(sub->add_option(
      "--warm-start", a.warm_start,
      "Start from a lap saved with --save-solution (any mesh; the coarse solve is skipped)"));
  a.stock_car_only.push_back(sub->add_option(
      "--save-solution", a.save_solution,
      "Save the solved lap (point and multipliers) for --warm-start (binary, this machine)"));
  a.stock_car_only.push_back(sub->add_option(
      "--lap-cache", a.run.lap_cache_dir,
      "Start from the nearest laps solved in this folder, and keep the lap there (one solve)"));
  a.stock_car_only.push_back(sub->add_flag(
      "--single-process", a.single_process,
      "With a comparison: the limited lap after the free one, not beside it in a second process"));
  sub->add_option("--ipopt-option", a.ipopt_options,
                  "An Ipopt option as NAME=VALUE (repeatable), e.g. mumps_pivot_order=5")
      ->check([](const std::string& s) {
        const size_t eq = s.find('=');
        return eq == std::string::npos || eq == 0 || eq + 1 == s.size()
                   ? std::string("expected NAME=VALUE, got '" + s + "'")
                   : std::string();
      });
}

}  // namespace hotlap::app
