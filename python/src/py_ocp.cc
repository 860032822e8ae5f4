// hotlap.optimal_lap: the minimum-time lap (one solve, or the disc-limit comparison) as
// `hotlap optimise` / `hotlap lap --method ocp` run it, with the GIL released during the solve,
// a progress callback and cancelling from Python (the callback returning False, or Ctrl-C).

#include <chrono>
#include <exception>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "hotlap/common/error.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/ocp/optimal_output.h"
#include "hotlap/ocp/optimal_run.h"
#include "hotlap/ocp/optimal_run_json.h"
#include "hotlap/ocp/stint_output.h"
#include "hotlap/runs/stint_run.h"
#include "hotlap/track/track.h"
#include "hotlap/vehicle/car.h"
#include "py_convert.h"

namespace hotlap::python {

namespace {

py::dict OptimalLap(
    const vehicle::Car& car, const track::Track& track, std::optional<double> disc_limit_C,
    std::optional<double> compare_disc_limit_C, double step_m, double tolerance_s,
    double coarse_step_m, const std::string& collocation, const std::string& thermal_start,
    double ambient_C, double track_C, int max_iterations,
    const std::vector<std::pair<std::string, std::string>>& ipopt_options, int threads,
    bool wear_in_programme, bool paper_models, bool sensitivities, const py::object& warm_start,
    int start_max_iterations, const std::optional<std::filesystem::path>& lap_cache,
    const std::string& lap_cache_name, const std::map<std::string, double>& lap_cache_scales,
    const std::optional<std::filesystem::path>& save_solution, const py::object& progress) {
  runs::CheckThreads(threads, runs::NameStyle::kPython);
  ocp::OptimalRunOptions o;
  o.threads = threads;
  o.step_m = step_m;
  o.tolerance_s = tolerance_s;
  o.coarse_step_m = coarse_step_m;
  ocp::ParseCollocation(collocation);  // an InputError (ValueError) before any work
  o.collocation = collocation;
  o.disc_limit_C = disc_limit_C;
  o.compare_disc_limit_C = compare_disc_limit_C;
  o.thermal_start = thermal_start;
  o.ambient_C = ambient_C;
  o.track_C = track_C;
  o.max_iterations = max_iterations;
  o.ipopt_options = ipopt_options;
  o.wear_in_programme = wear_in_programme;
  o.sensitivities = sensitivities;
  o.paper_models = paper_models;
  // One process: a fork beside Python's own threads is not safe (docs/python.md).
  o.second_process = false;
  ocp::CheckDiscLimits(o);
  // warm_start: one saved lap's path, or a list of them tried in turn.
  std::vector<std::filesystem::path> start_paths;
  if (py::isinstance<py::list>(warm_start) || py::isinstance<py::tuple>(warm_start)) {
    start_paths = warm_start.cast<std::vector<std::filesystem::path>>();
  } else if (!warm_start.is_none()) {
    start_paths.push_back(warm_start.cast<std::filesystem::path>());
  }
  if (compare_disc_limit_C && (!start_paths.empty() || save_solution)) {
    throw InputError("warm_start and save_solution are for one solve, not the comparison");
  }
  if (start_max_iterations < 0) {
    throw InputError(
        fmt::format("start_max_iterations: {} is not 0 or more", start_max_iterations));
  }
  o.start_max_iterations = start_max_iterations;
  if (lap_cache) o.lap_cache_dir = lap_cache->string();
  o.lap_cache_name = lap_cache_name;
  o.lap_cache_scales = lap_cache_scales;
  std::vector<ocp::LapStart> starts;
  for (const std::filesystem::path& p : start_paths) starts.push_back(ocp::ReadLapStart(p));
  if (save_solution) CheckOutputFolder(*save_solution, "save_solution");

  // Called on the solving thread without the GIL: take it, call Python, and stop the solve when
  // the callback returns False, raises, or Ctrl-C arrives (the error is raised after the solve).
  std::exception_ptr callback_error;
  bool cancelled = false;
  const ocp::LapProgress on_iteration = [&](const std::string& label, int iteration,
                                            double objective, double infeasibility,
                                            double optimality) {
    py::gil_scoped_acquire acquire;
    if (callback_error || cancelled) return false;
    if (PyErr_CheckSignals() != 0) {
      callback_error = std::make_exception_ptr(py::error_already_set());
      return false;
    }
    if (progress.is_none()) return true;
    try {
      const py::object go = progress(label, iteration, objective, infeasibility, optimality);
      if (!go.is_none() && !go.cast<bool>()) {
        cancelled = true;
        return false;
      }
      return true;
    } catch (...) {
      callback_error = std::current_exception();
      return false;
    }
  };
  const auto started = std::chrono::steady_clock::now();
  ocp::OptimalRuns runs;
  {
    py::gil_scoped_release release;
    runs = ocp::SolveOptimalRuns(car, track, o, starts, on_iteration);
  }
  if (callback_error) std::rethrow_exception(callback_error);
  const ocp::SolvedLap& first = runs.laps.front();
  if (save_solution && first.run.solution.solve.ok()) {
    ocp::WriteLapStart(*save_solution, first.run.solution, track.length_m());
  }
  const double wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  py::dict out;
  out["summary"] = ToPython(ocp::OptimalRunsJson(runs, o, track.name(), car, wall_time_s));
  py::dict laps;
  for (const ocp::SolvedLap& lap : runs.laps) {
    const sim::ColumnSet columns = ocp::OptimalLapColumns(lap.run, track);
    laps[py::str(lap.label)] = ColumnsToDict(columns.names, columns.values);
  }
  out["channels"] = laps;
  out["cancelled"] = cancelled;
  return out;
}

py::dict Stint(const vehicle::Car& car, const track::Track& track, int laps, double wear_scale,
               double fuel_kg, std::optional<double> disc_limit_C, double step_m,
               double coarse_step_m, const std::string& thermal_start, double ambient_C,
               double track_C, int max_iterations, int threads,
               std::optional<std::filesystem::path> checkpoint_dir, int checkpoint_every) {
  runs::StintRunOptions stint;
  stint.laps = laps;
  stint.wear_scale = wear_scale;
  stint.fuel_kg = fuel_kg;
  stint.disc_limit_C = disc_limit_C;
  ocp::OptimalRunOptions& run = stint.run;
  run.threads = threads;
  run.step_m = step_m;
  run.coarse_step_m = coarse_step_m;
  run.thermal_start = thermal_start;
  run.ambient_C = ambient_C;
  run.track_C = track_C;
  run.max_iterations = max_iterations;
  run.second_process = false;
  // Checkpoints: the car's parameters count in their fingerprint through the warm-up (the car
  // here may have been changed in Python, so there is no file to add).
  if (checkpoint_dir) stint.checkpoint_dir = *checkpoint_dir;
  stint.checkpoint_every = checkpoint_every;
  const ocp::StintOptions o = runs::MakeStintOptions(stint, runs::NameStyle::kPython);
  const auto started = std::chrono::steady_clock::now();
  ocp::StintResult r;
  {
    py::gil_scoped_release release;
    r = ocp::SolveStint(car, track, o);
  }
  const double wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  py::dict out;
  out["summary"] = ToPython(ocp::StintJson(r, o, track.name(), car, wall_time_s));
  const sim::ColumnSet columns = ocp::StintColumns(r, track);
  out["channels"] = ColumnsToDict(columns.names, columns.values);
  return out;
}

}  // namespace

void BindOcp(py::module_& m) {
  const ocp::OptimalRunOptions defaults;  // the library's defaults are the module's
  m.def("optimal_lap", &OptimalLap, py::arg("car"), py::arg("track"), py::kw_only(),
        py::arg("disc_limit_C") = py::none(), py::arg("compare_disc_limit_C") = py::none(),
        py::arg("step_m") = defaults.step_m, py::arg("tolerance_s") = defaults.tolerance_s,
        py::arg("coarse_step_m") = defaults.coarse_step_m,
        py::arg("collocation") = defaults.collocation,
        py::arg("thermal_start") = defaults.thermal_start,
        py::arg("ambient_temp_C") = defaults.ambient_C, py::arg("track_temp_C") = defaults.track_C,
        py::arg("max_iterations") = defaults.max_iterations,
        py::arg("ipopt_options") = std::vector<std::pair<std::string, std::string>>{},
        py::arg("threads") = defaults.threads,
        py::arg("wear_in_programme") = defaults.wear_in_programme,
        py::arg("paper_models") = defaults.paper_models,
        py::arg("sensitivities") = defaults.sensitivities, py::arg("warm_start") = py::none(),
        py::arg("start_max_iterations") = defaults.start_max_iterations,
        py::arg("lap_cache") = py::none(), py::arg("lap_cache_name") = "",
        py::arg("lap_cache_scales") = std::map<std::string, double>{},
        py::arg("save_solution") = py::none(), py::arg("progress") = py::none(),
        "The minimum-time lap with tyre and brake temperatures and wear as states: one solve "
        "(optionally with a front-disc limit, degC), or with compare_disc_limit_C the free and "
        "the limited lap. Returns {'summary': dict (the keys of `hotlap optimise --json`), "
        "'channels': {label: {column: array}}, 'cancelled': bool}. progress(label, iteration, "
        "objective_s, infeasibility, optimality) is called at every Ipopt iteration; returning "
        "False stops the solve. collocation: 'trapezoid' or 'hermite-simpson' (step_m is then an "
        "interval with a node at its midpoint; the coarse solve stays trapezoid). "
        "tolerance_s: > 0 for the adaptive mesh, refined until the estimated lap-time error is "
        "within it, s (step_m is then not used; trapezoid only; docs/optimal-control.md). "
        "threads: threads evaluating the derivatives (1, the default, "
        "suits sweeps of one case per worker; 0: one per core, as the command line). "
        "wear_in_programme: keep the tyres' wear as states of a solve from a solution (by "
        "default frozen for the forces at its start's and integrated after the solve; "
        "docs/optimal-control.md). paper_models: the lap on the paper's models (two-mass tyres, "
        "lumped discs) in place of the car's own. sensitivities: after the solves, each converged "
        "lap's set-up "
        "sensitivities (the lap time's derivative for each parameter a crew chief sets, from the "
        "solved lap's multipliers) in summary['sensitivities'] (per lap in the comparison, with "
        "summary['limit_cost_sensitivities']). warm_start: a lap saved with save_solution (or "
        "`hotlap optimise --save-solution`) to start from, its point and multipliers (the coarse "
        "solve skipped), or a list of them tried in turn, each within start_max_iterations "
        "(0: max_iterations); should every one fail, the default start (summary['started_from'], "
        "summary['failed_starts']); lap_cache: a folder of solved laps: the solve starts from "
        "the two nearest (the same car files, track and programme; the distance over the "
        "overrides, disc limit and temperatures, each divided by lap_cache_scales[key] or a "
        "crew chief's step) and keeps its lap there as lap_cache_name "
        "(summary['warm_start_from'], summary['warm_start_distance']); "
        "save_solution: where to write the converged lap (one solve, not the comparison).");
  const ocp::StintOptions stint;
  m.def("stint", &Stint, py::arg("car"), py::arg("track"), py::kw_only(),
        py::arg("laps") = stint.laps, py::arg("wear_scale") = stint.wear_scale,
        py::arg("fuel_kg") = stint.fuel_kg, py::arg("disc_limit_C") = py::none(),
        py::arg("step_m") = stint.lap.step_m, py::arg("coarse_step_m") = defaults.coarse_step_m,
        py::arg("thermal_start") = defaults.thermal_start,
        py::arg("ambient_temp_C") = defaults.ambient_C, py::arg("track_temp_C") = defaults.track_C,
        py::arg("max_iterations") = defaults.max_iterations, py::arg("threads") = defaults.threads,
        py::arg("checkpoint_dir") = py::none(),
        py::arg("checkpoint_every") = stint.checkpoint_every,
        "A stint of `laps` laps as one optimal-control problem (wear, carcass heat and fuel "
        "carried lap to lap) and the greedy driver's single laps, as `hotlap stint` runs them. "
        "With checkpoint_dir, each greedy lap and every checkpoint_every iterations of the "
        "stint's solve are saved there, and a call again with the same folder and stint resumes "
        "from them (summary keys greedy_laps_resumed, resumed_from_iteration). "
        "Returns {'summary': dict (the keys of `hotlap stint --json`), 'channels': {column: "
        "array} over the whole stint, with its lap column}.");
}

}  // namespace hotlap::python
