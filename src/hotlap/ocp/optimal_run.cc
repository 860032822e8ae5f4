#include "hotlap/ocp/optimal_run.h"

#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <thread>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/folder_fingerprint.h"
#include "hotlap/common/units.h"
#include "hotlap/ocp/lap_sensitivities.h"

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

void CheckDiscLimits(const OptimalRunOptions& a) {
  if (a.disc_limit_C && a.compare_disc_limit_C) {
    throw InputError("give a disc limit (one solve) or a comparison's limit (two), not both");
  }
  for (const auto& limit : {a.disc_limit_C, a.compare_disc_limit_C}) {
    if (limit && !(*limit > 0.0 && *limit < 1500.0)) {
      throw InputError(fmt::format("the disc limit {:g} degC must be in (0, 1500)", *limit));
    }
  }
}

CachedLapKey LapCacheKeyOf(const vehicle::Car& car, const track::Track& track,
                           const OptimalRunOptions& a) {
  if (car.path.empty()) throw InputError("lap cache: the car has no files to key its laps by");
  CachedLapKey key;
  key.family = fmt::format(
      "hotlap {}\ncar{}\ntrack {} {:.3f} m\nmesh {:g} m {}\nthermal start {}\nwear in "
      "programme {}\npaper models {}\ncontrols {}\nsmoothing {:g} {:g}\nhessian {}",
      HOTLAP_VERSION, FolderFingerprint(car.path.parent_path()), track.name(), track.length_m(),
      a.step_m, a.collocation, a.thermal_start, a.wear_in_programme, a.paper_models,
      a.independent_drive_and_brake ? "independent" : "pedal", a.steer_smoothing, a.pedal_smoothing,
      a.convex_element_hessians ? "convex" : "exact");
  // Every crew-chief value (the car's or its override), so that a run with --set and one
  // without are neighbours; other overrides as given.
  for (const SetupParameter& p : CrewChiefParameters()) {
    key.coordinates[p.key] = SetupValue(car, p.key);
  }
  for (const vehicle::CarOverride& o : car.overrides) key.coordinates[o.key] = o.value;
  if (a.disc_limit_C) key.coordinates["disc_limit_C"] = *a.disc_limit_C;
  key.coordinates["ambient_temp_C"] = a.ambient_C;
  key.coordinates["track_temp_C"] = a.track_C;
  return key;
}

namespace {

// The laps of a lap cache a solve tries first: start_max_iterations each unless set.
constexpr int kCachedStartIterations = 150;

// The default scales of the cache's distance: a crew chief's step of each set-up key.
std::map<std::string, double> DefaultLapCacheScales() {
  std::map<std::string, double> scales = {
      {"disc_limit_C", 50.0}, {"ambient_temp_C", 10.0}, {"track_temp_C", 10.0}};
  for (const SetupParameter& p : CrewChiefParameters()) scales[p.key] = p.typical_step;
  return scales;
}

// The name of a run's lap in the cache: the car's and its overrides.
std::string LapCacheName(const vehicle::Car& car) {
  std::string name = car.name;
  for (const vehicle::CarOverride& o : car.overrides) name += " " + vehicle::OverrideText(o);
  return name;
}

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
  CheckDiscLimits(a);
  OptimalRuns runs;
  if (a.compare_disc_limit_C && !a.lap_cache_dir.empty()) {
    throw InputError("a lap cache is for one solve, not the comparison (it has its own starts)");
  }
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
  // The caller's saved laps, then the cache's nearest (a lap that cannot be read is no start).
  std::vector<LapStart> starts = warm_starts;
  std::vector<CachedLap> cached;
  std::optional<CachedLapKey> key;
  int cap = a.start_max_iterations;
  if (!a.lap_cache_dir.empty()) {
    key = LapCacheKeyOf(car, track, a);
    const std::map<std::string, double> scales =
        a.lap_cache_scales.empty() ? DefaultLapCacheScales() : a.lap_cache_scales;
    for (const CachedLap& c : NearestCachedLaps(a.lap_cache_dir, *key, scales, 2)) {
      try {
        starts.push_back(ReadLapStart(c.lap));
        cached.push_back(c);
      } catch (const InputError& e) {
        if (log)
          log(fmt::format("{}: the cached lap '{}' is no start: {}", label, c.name, e.what()));
      }
    }
    if (cap == 0) cap = kCachedStartIterations;
  }
  // The saved laps in turn, each within the cap; then the default start (with its own
  // fallback). Every attempt that failed is reported with the solution.
  std::vector<OptimalLapRun::FailedStart> failed;
  std::optional<SolvedLap> solved;
  for (size_t i = 0; i < starts.size() && !solved; ++i) {
    const std::string name =
        starts.size() == 1 ? std::string("the saved lap") : fmt::format("saved lap {}", i + 1);
    OptimalLapOptions from = o;
    std::optional<SolvedLap> tried;
    try {
      UseLapStart(starts[i], track, from);
      if (cap > 0) from.ipopt.max_iterations = std::min(from.ipopt.max_iterations, cap);
      tried = SolveLap(car, track, from, label, nullptr, progress, log);
    } catch (const InputError& e) {
      // The caller's own lap that does not fit is their error; a cached one (of another build
      // with the same version, say) is just no start.
      if (i < warm_starts.size()) throw;
      failed.push_back({name, 0, e.what()});
      if (log) log(fmt::format("{}: from {}: {}; the next start", label, name, e.what()));
      continue;
    }
    SolvedLap& lap = *tried;
    const SolveResult& r = lap.run.solution.solve;
    if (r.ok() || r.status == SolveStatus::kStopped) {
      lap.run.started_from = name;
      if (i >= warm_starts.size()) {
        lap.warm_start_from = cached[i - warm_starts.size()].name;
        lap.warm_start_distance = cached[i - warm_starts.size()].distance;
      }
      solved = std::move(lap);
    } else {
      failed.push_back({name, r.iterations, r.message});
      if (log) log(fmt::format("{}: from {}: {}; the next start", label, name, r.message));
    }
  }
  if (!solved) solved = SolveLap(car, track, o, label, nullptr, progress, log);
  solved->run.failed_starts.insert(solved->run.failed_starts.begin(), failed.begin(), failed.end());
  if (key && solved->run.solution.solve.ok()) {
    // Written beside the cache's laps, then moved into place with its entry.
    const std::filesystem::path saved =
        std::filesystem::path(a.lap_cache_dir) /
        fmt::format(".{}-{}.lap", CachedLapHash(*key), static_cast<long>(getpid()));
    std::error_code ec;
    std::filesystem::create_directories(a.lap_cache_dir, ec);
    WriteLapStart(saved, solved->run.solution, track.length_m());
    KeepCachedLap(a.lap_cache_dir, *key,
                  a.lap_cache_name.empty() ? LapCacheName(car) : a.lap_cache_name, saved,
                  solved->figures.lap_time_s, solved->run.solution.solve.iterations);
  }
  runs.laps.push_back(std::move(*solved));
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
