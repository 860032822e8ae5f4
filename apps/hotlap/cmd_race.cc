// `hotlap race`: the race plan from the car's own fall-off (docs/race.md).

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.h"
#include "hotlap/common/data_path.h"
#include "hotlap/common/error.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/common/units.h"
#include "hotlap/ocp/min_curvature_line.h"
#include "hotlap/race/fall_off_cache.h"
#include "hotlap/race/race_json.h"
#include "hotlap/race/race_plan.h"
#include "hotlap/race/race_report.h"
#include "hotlap/race/race_run.h"
#include "hotlap/runs/race_spot_checks.h"
#include "hotlap/sim/road.h"
#include "hotlap/track/track_io.h"

namespace hotlap::app {

namespace {

struct RaceArgs {
  std::string track = "darlington";
  std::string car = "gen7";
  std::vector<std::string> set;
  race::RaceRunOptions run;
  std::string stages = "115,230";
  std::string cautions = "record";
  double step_m = 2.0;
  std::string spot_checks;
  double spot_check_step_m = 6.0;
  std::string cache_dir = race::DefaultCacheDir().string();
  bool no_cache = false;
  std::string json;
  std::string report;
};

int RunRace(RaceArgs a) {
  a.run.rules.stage_ends = race::ParseStageEnds(a.stages, a.run.rules.laps, "--stages");
  a.run.cautions = race::ParseCautions(a.cautions, "--cautions");
  race::CheckRaceRules(a.run.rules);
  if (!(a.step_m >= 0.5 && a.step_m <= 10.0)) {
    throw InputError(fmt::format("--step-m {:g} must be in [0.5, 10] m", a.step_m));
  }
  const std::vector<int> spot_ages =
      runs::ParseSpotCheckAges(a.spot_checks, a.run.fall_off_laps, "--spot-checks");
  if (!(a.spot_check_step_m >= 1.0 && a.spot_check_step_m <= 20.0)) {
    throw InputError(
        fmt::format("--spot-check-step-m {:g} must be in [1, 20] m", a.spot_check_step_m));
  }
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  if (!a.report.empty()) CheckOutputFolder(a.report, "--report");
  const vehicle::Car car =
      vehicle::LoadCar(ResolveCarFile(a.car), vehicle::ParseCarOverrides(a.set));
  vehicle::RequireVehicle(car, "`hotlap race`");
  const track::Track track = track::LoadTrack(a.track);
  const std::vector<sim::RoadPoint> road = sim::SampleRoadAlongLine(
      track, ocp::MinimumCurvatureLine(track, {.step_m = std::max(a.step_m, 2.0), .margin_m = 1.5}),
      a.step_m);
  fmt::print("hotlap race: car '{}' on {}: the fall-off from {} QSS laps on a new set\n", car.name,
             track.name(), a.run.fall_off_laps);
  std::fflush(stdout);
  if (!a.no_cache) a.run.cache_dir = a.cache_dir;  // empty: no cache
  a.run.progress = [](const std::string& line) {
    fmt::print("  {}...\n", line);
    std::fflush(stdout);
  };
  const race::RaceRun run = race::RunRace(car, track.length_m(), road, a.run);
  fmt::print("{}", race::RaceText(run));
  runs::RaceSpotChecks spots;
  if (!spot_ages.empty()) {
    spots = runs::RunRaceSpotChecks(car, track, road,
                                    race::FallOffQssOptions(car, track.length_m(), a.run),
                                    run.fall_off, spot_ages, a.spot_check_step_m, a.run.progress);
    fmt::print("{}", runs::RaceSpotChecksText(spots));
  }
  fmt::print("the fall-off {} in {:.1f} s, the plans in {:.2f} s\n",
             run.fall_off_from_cache      ? "read from the cache"
             : run.fall_off_cache.empty() ? "driven"
                                          : "driven (and cached)",
             run.fall_off_seconds, run.plan_seconds);
  if (!run.cache_warning.empty()) fmt::print(stderr, "warning: {}\n", run.cache_warning);
  if (!a.json.empty()) {
    nlohmann::json j = race::RaceJson(run, a.run.cautions);
    j["spot_checks"] =
        spot_ages.empty() ? nlohmann::json(nullptr) : runs::RaceSpotChecksJson(spots);
    WriteJsonFile(a.json, j);
    fmt::print("wrote {}\n", a.json);
  }
  if (!a.report.empty()) {
    race::WriteRaceReport(a.report, run, car.name, track.name());
    fmt::print("wrote {}\n", a.report);
  }
  return 0;
}

}  // namespace

CommandRunner RegisterRaceCommand(CLI::App& app) {
  auto args = std::make_shared<RaceArgs>();
  CLI::App* sub = app.add_subcommand(
      "race",
      "Plan a race's pit stops (four tyres, right-side tyres where allowed, or fuel only) from "
      "the car's own "
      "fall-off: the least race time under the rules, against fixed plans, and the policy under "
      "cautions");
  sub->add_option("--track", args->track, "Track name or file")->capture_default_str();
  sub->add_option("--car", args->car, "Car name or car.yaml")->capture_default_str();
  sub->add_option("--set", args->set, "Override a car parameter, KEY=VALUE (docs/overrides.md)");
  sub->add_option("--laps", args->run.rules.laps, "Race length, laps")->capture_default_str();
  sub->add_option("--stages", args->stages, "Laps that end a stage, e.g. 115,230 (cheap stops)")
      ->capture_default_str();
  sub->add_option("--fuel-capacity-kg", args->run.rules.fuel_capacity_kg, "The fuel cell, kg")
      ->capture_default_str();
  sub->add_option("--fuel-per-lap-kg", args->run.rules.fuel_per_lap_kg,
                  "Fuel burnt per green lap, kg")
      ->capture_default_str();
  sub->add_option("--tyre-sets", args->run.rules.tyre_sets, "Tyre sets, the starting set included")
      ->capture_default_str();
  sub->add_option("--pit-loss-s", args->run.rules.pit_loss_s,
                  "Time a green stop loses, service aside")
      ->capture_default_str();
  sub->add_option("--caution-pit-loss-s", args->run.rules.caution_pit_loss_s,
                  "Time a stop at a stage end loses, service aside")
      ->capture_default_str();
  sub->add_flag(
      "--right-side-stops", args->run.rules.right_side_stops,
      "Allow stops for the two right-side tyres (and fuel) beside four-tyre and fuel-only "
      "stops");
  sub->add_option("--right-tyre-service-s", args->run.rules.right_tyre_service_s,
                  "Time the two right-side tyres take to change, s")
      ->capture_default_str();
  sub->add_option("--fall-off-laps", args->run.fall_off_laps, "QSS laps on a set for the fall-off")
      ->capture_default_str();
  sub->add_option("--reference-fuel-kg", args->run.reference_fuel_kg,
                  "Fuel the car's mass includes, kg")
      ->capture_default_str();
  sub->add_option("--cautions", args->cautions,
                  "Caution rate per green lap for the Monte Carlo races, 'record' (the Southern "
                  "500's) or 'off'")
      ->capture_default_str();
  sub->add_option("--races", args->run.races, "Monte Carlo races of each plan (0: none)")
      ->capture_default_str();
  sub->add_flag("--policy,!--no-policy", args->run.policy,
                "Also solve the policy: pit or stay out at every lap of every caution (a "
                "stochastic programme), raced in the same Monte Carlo races")
      ->capture_default_str();
  sub->add_option("--fuel-units-per-lap", args->run.policy_options.fuel_units_per_lap,
                  "The policy's fuel count: units of a green lap's burn, 1 to 10 (a caution lap's "
                  "burn rounded up)")
      ->capture_default_str();
  sub->add_option("--step-m", args->step_m, "Road spacing of the QSS laps, m")
      ->capture_default_str();
  sub->add_option("--spot-checks", args->spot_checks,
                  "Ages of the set (laps on it, e.g. 2,30,59) at which to solve the optimal lap "
                  "from the fall-off's state, against its QSS lap");
  sub->add_option("--spot-check-step-m", args->spot_check_step_m,
                  "Mesh of the spot checks' optimal laps, m")
      ->capture_default_str();
  sub->add_option("--cache-dir", args->cache_dir,
                  "Keep the fall-off here, keyed by the car's files, the track and the settings "
                  "(default: $HOTLAP_CACHE_DIR, else $XDG_CACHE_HOME/hotlap or ~/.cache/hotlap)");
  sub->add_flag("--no-cache", args->no_cache,
                "Drive the fall-off's laps, neither reading nor "
                "writing the cache");
  sub->add_option("--json", args->json, "Write the summary as JSON (docs/json-output.md)");
  sub->add_option("--report", args->report,
                  "Write an HTML report: the plans, the fall-off, the race traces, the cautions");
  return [args] { return RunRace(*args); };
}

}  // namespace hotlap::app
