// `hotlap race`: the race plan from the car's own fall-off (docs/race.md).

#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.h"
#include "hotlap/common/data_path.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/race/fall_off_cache.h"
#include "hotlap/race/race_report.h"
#include "hotlap/runs/race_command_run.h"
#include "hotlap/track/track_io.h"

namespace hotlap::app {

namespace {

struct RaceArgs {
  std::string track = "darlington";
  std::string car = "gen7";
  std::vector<std::string> set;
  runs::RaceCommandOptions race;
  std::string cache_dir = race::DefaultCacheDir().string();
  bool no_cache = false;
  std::string json;
  std::string report;
};

int RunRace(RaceArgs a) {
  if (!a.no_cache) a.race.run.cache_dir = a.cache_dir;  // empty: no cache
  const runs::RaceCommandPlan plan = runs::PlanRaceCommand(a.race, runs::NameStyle::kCommandLine);
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  if (!a.report.empty()) CheckOutputFolder(a.report, "--report");
  const vehicle::Car car =
      vehicle::LoadCar(ResolveCarFile(a.car), vehicle::ParseCarOverrides(a.set));
  vehicle::RequireVehicle(car, "`hotlap race`");
  const track::Track track = track::LoadTrack(a.track);
  fmt::print("hotlap race: car '{}' on {}: the fall-off from {} QSS laps on a new set\n", car.name,
             track.name(), plan.run.fall_off_laps);
  std::fflush(stdout);
  const runs::RaceCommandRun run =
      runs::RunRaceCommand(car, track, plan, [](const std::string& line) {
        fmt::print("  {}...\n", line);
        std::fflush(stdout);
      });
  fmt::print("{}", runs::RaceCommandText(run));
  if (!run.race.cache_warning.empty()) fmt::print(stderr, "warning: {}\n", run.race.cache_warning);
  if (!a.json.empty()) WriteJsonFileAndSay(a.json, runs::RaceCommandJson(run));
  if (!a.report.empty()) {
    race::WriteRaceReport(a.report, run.race, car.name, track.name());
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
      "the car's own fall-off: the least race time under the rules, against fixed plans, and the "
      "policy under cautions");
  AddShownOption(sub, "--track", args->track, "Track name or file");
  AddShownOption(sub, "--car", args->car, "Car name or car.yaml");
  sub->add_option("--set", args->set, "Override a car parameter, KEY=VALUE (docs/overrides.md)");
  AddShownOption(sub, "--laps", args->race.run.rules.laps, "Race length, laps");
  AddShownOption(sub, "--stages", args->race.stages,
                 "Laps that end a stage, e.g. 115,230 (cheap stops)");
  AddShownOption(sub, "--fuel-capacity-kg", args->race.run.rules.fuel_capacity_kg,
                 "The fuel cell, kg");
  AddShownOption(sub, "--fuel-per-lap-kg", args->race.run.rules.fuel_per_lap_kg,
                 "Fuel burnt per green lap, kg");
  AddShownOption(sub, "--tyre-sets", args->race.run.rules.tyre_sets,
                 "Tyre sets, the starting set included");
  AddShownOption(sub, "--pit-loss-s", args->race.run.rules.pit_loss_s,
                 "Time a green stop loses, service aside");
  AddShownOption(sub, "--caution-pit-loss-s", args->race.run.rules.caution_pit_loss_s,
                 "Time a stop at a stage end loses, service aside");
  sub->add_flag("--right-side-stops", args->race.run.rules.right_side_stops,
                "Allow stops for the two right-side tyres (and fuel) beside four-tyre and "
                "fuel-only stops");
  AddShownOption(sub, "--right-tyre-service-s", args->race.run.rules.right_tyre_service_s,
                 "Time the two right-side tyres take to change, s");
  AddShownOption(sub, "--fall-off-laps", args->race.run.fall_off_laps,
                 "QSS laps on a set for the fall-off");
  AddShownOption(sub, "--reference-fuel-kg", args->race.run.reference_fuel_kg,
                 "Fuel the car's mass includes, kg");
  AddShownOption(
      sub, "--cautions", args->race.cautions,
      "Caution rate per green lap for the Monte Carlo races, 'record' (the Southern 500's) or "
      "'off'");
  AddShownOption(sub, "--races", args->race.run.races, "Monte Carlo races of each plan (0: none)");
  sub->add_flag("--policy,!--no-policy", args->race.run.policy,
                "Also solve the policy: pit or stay out at every lap of every caution (a "
                "stochastic programme), raced in the same Monte Carlo races")
      ->capture_default_str();
  AddShownOption(
      sub, "--fuel-units-per-lap", args->race.run.policy_options.fuel_units_per_lap,
      "The policy's fuel count: units of a green lap's burn, 1 to 10 (a caution lap's burn "
      "rounded up)");
  AddShownOption(sub, "--step-m", args->race.step_m, "Road spacing of the QSS laps, m");
  sub->add_option("--spot-checks", args->race.spot_checks,
                  "Ages of the set (laps on it, e.g. 2,30,59) at which to solve the optimal lap "
                  "from the fall-off's state, against its QSS lap");
  AddShownOption(sub, "--spot-check-step-m", args->race.spot_check_step_m,
                 "Mesh of the spot checks' optimal laps, m");
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
