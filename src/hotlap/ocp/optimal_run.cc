#include "hotlap/ocp/optimal_run.h"

#include <algorithm>
#include <chrono>
#include <thread>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"

namespace hotlap::ocp {

OptimalLapOptions MakeOptimalLapOptions(const OptimalRunOptions& a) {
  // The command line's ranges, for callers that do not go through it (the Python package).
  if (!(a.step_m >= 0.5 && a.step_m <= 50.0)) {
    throw InputError(fmt::format("step_m: {:g} m is not 0.5 to 50 m", a.step_m));
  }
  if (!(a.coarse_step_m >= 0.0 && a.coarse_step_m <= 100.0)) {
    throw InputError(fmt::format("coarse_step_m: {:g} m is not 0 to 100 m (0: no coarse solve)",
                                 a.coarse_step_m));
  }
  if (!(a.tolerance_s >= 0.0 && a.tolerance_s <= 1.0)) {
    throw InputError(
        fmt::format("tolerance: {:g} s is not 0 to 1 s (0: the fixed mesh)", a.tolerance_s));
  }
  if (a.tolerance_s > 0.0 && a.collocation != "trapezoid") {
    throw InputError("the adaptive mesh (a tolerance) is for the trapezoid collocation only");
  }
  if (a.max_iterations < 1) {
    throw InputError(fmt::format("max_iterations: {} is not 1 or more", a.max_iterations));
  }
  OptimalLapOptions o;
  o.step_m = a.step_m;
  o.tolerance_s = a.tolerance_s;
  o.coarse_step_m = a.coarse_step_m;
  o.collocation = ParseCollocation(a.collocation);
  o.coarse_collocation = ParseCollocation(a.coarse_collocation);
  o.steer_smoothing_weight = a.steer_smoothing;
  o.pedal_smoothing_weight = a.pedal_smoothing;
  o.convex_element_hessians = a.convex_element_hessians;
  o.wear_in_programme = a.wear_in_programme;
  o.paper_models = a.paper_models;
  o.independent_drive_and_brake = a.independent_drive_and_brake;
  o.thermal_start = ParseThermalStart(a.thermal_start);
  o.ambient_temp = CelsiusToKelvin(a.ambient_C);
  o.track_temp = CelsiusToKelvin(a.track_C);
  o.ipopt.max_iterations = a.max_iterations;
  for (const auto& kv : a.ipopt_options) o.ipopt.extra.push_back(kv);
  o.ipopt.print_level = a.ipopt_output ? 5 : 0;
  o.second_process = a.second_process;
  // One per core, at most 8: each evaluation splits about 10-50 ms of work, and every thread adds
  // a buffer of the whole Jacobian or Hessian to be summed.
  o.derivative_threads =
      a.threads > 0 ? a.threads
                    : std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, 8);
  return o;
}

namespace {

// Each converged lap's set-up sensitivities (no solve: the programme evaluated at the solution).
void AddSensitivities(const vehicle::Car& car, const track::Track& track,
                      const OptimalRunOptions& a, const LapLog& log, OptimalRuns& runs) {
  const OptimalLapOptions o = MakeOptimalLapOptions(a);
  for (SolvedLap& lap : runs.laps) {
    if (!lap.run.solution.solve.ok()) {
      if (log)
        log(fmt::format("{}: no set-up sensitivities (the lap did not converge)", lap.label));
      continue;
    }
    if (log) log(fmt::format("{}: set-up sensitivities...", lap.label));
    const auto started = std::chrono::steady_clock::now();
    lap.sensitivities = ComputeLapSensitivities(car, track, o, lap.run);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (log) {
      log(fmt::format("{}: {} set-up sensitivities in {:.1f} s (no solve)", lap.label,
                      lap.sensitivities.size(), seconds));
    }
  }
}

OptimalRuns SolveLaps(const vehicle::Car& car, const track::Track& track,
                      const OptimalRunOptions& a, const std::vector<LapStart>& warm_starts,
                      const LapProgress& progress, const LapLog& log) {
  OptimalRuns runs;
  if (a.compare_disc_limit_C) {
    DiscLimitComparison c =
        CompareDiscLimit(car, track, MakeOptimalLapOptions(a),
                         CelsiusToKelvin(*a.compare_disc_limit_C), progress, log);
    runs.limited_in_second_process = c.limited_in_second_process;
    runs.laps.push_back(std::move(c.free));
    runs.laps.push_back(std::move(c.limited));
    return runs;
  }
  OptimalLapOptions o = MakeOptimalLapOptions(a);
  if (a.disc_limit_C) o.front_disc_limit = CelsiusToKelvin(*a.disc_limit_C);
  const std::string label =
      a.disc_limit_C ? fmt::format("discs <= {:g} degC", *a.disc_limit_C) : "optimal lap";
  // The saved laps in turn, each within start_max_iterations; then the default start (with its
  // own fallback). Every attempt that failed is reported with the solution.
  std::vector<OptimalLapRun::FailedStart> failed;
  for (size_t i = 0; i < warm_starts.size(); ++i) {
    OptimalLapOptions from = o;
    UseLapStart(warm_starts[i], track, from);
    if (a.start_max_iterations > 0) {
      from.ipopt.max_iterations = std::min(from.ipopt.max_iterations, a.start_max_iterations);
    }
    SolvedLap lap = SolveLap(car, track, from, label, nullptr, progress, log);
    const SolveResult& r = lap.run.solution.solve;
    const std::string name =
        warm_starts.size() == 1 ? std::string("the saved lap") : fmt::format("saved lap {}", i + 1);
    if (r.ok() || r.status == SolveStatus::kStopped) {
      lap.run.failed_starts.insert(lap.run.failed_starts.begin(), failed.begin(), failed.end());
      lap.run.started_from = name;
      runs.laps.push_back(std::move(lap));
      return runs;
    }
    failed.push_back({name, r.iterations, r.message});
    if (log)
      log(fmt::format("{}: from {}: {}; the next start", label, failed.back().from, r.message));
  }
  SolvedLap lap = SolveLap(car, track, o, label, nullptr, progress, log);
  lap.run.failed_starts.insert(lap.run.failed_starts.begin(), failed.begin(), failed.end());
  runs.laps.push_back(std::move(lap));
  return runs;
}

}  // namespace

OptimalRuns SolveOptimalRuns(const vehicle::Car& car, const track::Track& track,
                             const OptimalRunOptions& a, const LapStart* warm_start,
                             const LapProgress& progress, const LapLog& log) {
  std::vector<LapStart> starts;
  if (warm_start) starts.push_back(*warm_start);
  return SolveOptimalRuns(car, track, a, starts, progress, log);
}

OptimalRuns SolveOptimalRuns(const vehicle::Car& car, const track::Track& track,
                             const OptimalRunOptions& a, const std::vector<LapStart>& warm_starts,
                             const LapProgress& progress, const LapLog& log) {
  OptimalRuns runs = SolveLaps(car, track, a, warm_starts, progress, log);
  if (a.sensitivities) AddSensitivities(car, track, a, log, runs);
  return runs;
}

}  // namespace hotlap::ocp
