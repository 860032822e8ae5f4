// `hotlap lap`: the car round a track by the quasi-steady-state method, with the tyre and brake
// thermal and wear models along the way, lap after lap.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "commands.h"
#include "hotlap/common/data_path.h"
#include "hotlap/common/error.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/runs/lap_run.h"
#include "hotlap/runs/lap_text.h"
#include "hotlap/sim/lap_json.h"
#include "hotlap/track/track_io.h"
#include "optimal_runs.h"

namespace hotlap::app {

namespace {

namespace fs = std::filesystem;

struct LapArgs {
  std::string method = "qss";
  std::string track = "darlington";
  std::string car = "gen7";
  std::vector<std::string> set;  // --set KEY=VALUE
  runs::LapRunOptions run;       // --method qss
  std::string out;
  std::string json;
  std::optional<double> compare_disc_limit_C;  // --method ocp
  std::optional<double> ocp_step_m;            // --method ocp
  std::optional<double> tolerance_s;           // --method ocp: the adaptive mesh
  bool single_process = false;                 // --method ocp with a comparison
  bool wear_in_programme = false;              // --method ocp
  bool sensitivities = false;                  // --method ocp
  int threads = 0;                             // --method ocp: derivative threads (0: per core)
  // What was given on the command line (of the options that have defaults).
  std::vector<std::string> given;
  bool Given(std::string_view name) const {
    return std::find(given.begin(), given.end(), name) != given.end();
  }
};

// Each method's own options are refused, not ignored, by the other: with why where it helps.
void RefuseOtherMethodsOptions(const LapArgs& a) {
  if (a.method == "ocp") {
    for (const auto& [name, instead] :
         {std::pair{"--laps", "one lap; a stint of optimal laps: hotlap stint"},
          std::pair{"--line", "the optimal lap chooses its line"},
          std::pair{"--line-margin-m", "the optimal lap chooses its line"},
          std::pair{"--step-m", "the optimal lap's mesh: --ocp-step-m"},
          std::pair{"--tread-temp-C", "the optimal lap starts from its warm-up lap"},
          std::pair{"--carcass-temp-C", "the optimal lap starts from its warm-up lap"},
          std::pair{"--disc-temp-C", "the optimal lap starts from its warm-up lap"},
          std::pair{"--calliper-temp-C", "the optimal lap starts from its warm-up lap"},
          std::pair{"--rim-temp-C", "the optimal lap starts from its warm-up lap"},
          std::pair{"--disc-bulk-temp-C", "the optimal lap starts from its warm-up lap"},
          std::pair{"--caution-laps", "a run of QSS laps"},
          std::pair{"--caution-speed-kph", "a run of QSS laps"}}) {
      if (a.Given(name))
        throw InputError(fmt::format("{} is for --method qss ({})", name, instead));
    }
    return;
  }
  for (const auto& [given, name] :
       {std::pair{a.compare_disc_limit_C.has_value(), "--compare-disc-limit-C"},
        std::pair{a.ocp_step_m.has_value(), "--ocp-step-m"},
        std::pair{a.tolerance_s.has_value(), "--tolerance"},
        std::pair{a.single_process, "--single-process"},
        std::pair{a.wear_in_programme, "--wear-in-programme"},
        std::pair{a.sensitivities, "--sensitivities"},
        std::pair{a.Given("--threads"), "--threads"}}) {
    if (given) throw InputError(fmt::format("{} is for --method ocp", name));
  }
}

int RunLap(const LapArgs& a) {
  RefuseOtherMethodsOptions(a);
  if (a.method == "ocp") {
    OptimalArgs o;
    o.command = "lap --method ocp";
    o.track = a.track;
    o.car = a.car;
    o.set = a.set;
    o.out = a.out;
    o.json = a.json;
    o.run.compare_disc_limit_C = a.compare_disc_limit_C;
    o.run.ambient_C = a.run.ambient_C;
    o.run.track_C = a.run.track_C;
    if (a.ocp_step_m) o.run.step_m = *a.ocp_step_m;
    if (a.tolerance_s) o.run.tolerance_s = *a.tolerance_s;
    o.single_process = a.single_process;
    o.run.wear_in_programme = a.wear_in_programme;
    o.run.sensitivities = a.sensitivities;
    o.run.threads = a.threads;
    return RunOptimal(o);
  }
  const auto started = std::chrono::steady_clock::now();
  // Everything that can fail on input is read before the output folder is touched.
  const vehicle::Car car =
      vehicle::LoadCar(ResolveCarFile(a.car), vehicle::ParseCarOverrides(a.set));
  vehicle::RequireVehicle(car, "`hotlap lap`");
  const track::Track track = track::LoadTrack(a.track);
  const runs::LapPlan plan = runs::PlanLap(car, track, a.run, runs::NameStyle::kCommandLine);
  CheckOutputDirectory(a.out, "--out");
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  fmt::print("{}", runs::LapRunHeader(car, track, a.run, plan));
  std::fflush(stdout);
  const runs::LapRun run = runs::RunLap(car, track, plan);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  fmt::print("{}", runs::LapRunText(run, car, a.run.laps));

  const runs::LapFiles files = runs::WriteLapFiles(a.out, run, a.run, car, track);
  fmt::print("wrote {} and {} in {:.2f} s\n", files.csv.string(), files.html.string(), elapsed);
  if (!a.json.empty()) {
    WriteJsonFileAndSay(
        a.json, sim::StintJson(run.stint, track, car, files.csv.string(), files.html.string()));
  }
  return 0;
}

}  // namespace

CommandRunner RegisterLapCommand(CLI::App& app) {
  auto args = std::make_shared<LapArgs>();
  CLI::App* sub = app.add_subcommand("lap",
                                     "Drive the car round a track with the thermal models: "
                                     "quasi-steady state, or the optimal lap (--method ocp)");
  AddShownOption(sub, "--method", args->method,
                 "qss (quasi-steady state) or ocp (optimal control, as `hotlap optimise`)")
      ->check(CLI::IsMember({"qss", "ocp"}));
  sub->add_option("--compare-disc-limit-C", args->compare_disc_limit_C,
                  "ocp: solve without and with this front-disc limit (degC) and compare");
  sub->add_option("--ocp-step-m", args->ocp_step_m, "ocp: mesh spacing, m (default 3)");
  sub->add_option("--tolerance", args->tolerance_s, "ocp: adaptive mesh to this lap-time error, s")
      ->excludes("--ocp-step-m");
  sub->add_flag("--single-process", args->single_process,
                "ocp: solve the limited lap after the free one, not beside it in a second process");
  sub->add_flag("--wear-in-programme", args->wear_in_programme,
                "ocp: keep the tyres' wear as states of the fine solves' programmes (by default "
                "frozen for the forces and integrated after the solve; docs/optimal-control.md)");
  sub->add_flag("--sensitivities", args->sensitivities,
                "ocp: after the solves, each lap's set-up sensitivities (the lap time's derivative "
                "with respect to pressures, cambers, brakes, weight split, aero, mass) from its "
                "multipliers, without solving again (docs/optimal-control.md)");
  AddShownOption(sub, "--threads", args->threads,
                 "ocp: threads evaluating the derivatives (0: one per core, at most 8; the "
                 "comparison's two solves take half each)")
      ->check(CLI::Range(0, 256));
  AddShownOption(sub, "--track", args->track, "Built-in track name or a .yaml/.csv/.xml file");
  AddShownOption(sub, "--car", args->car, "Built-in car name or path to a car.yaml");
  AddSetOption(sub, args->set);
  AddShownOption(sub, "--laps", args->run.laps, "Laps in the stint (thermal state carried over)");
  sub->add_option("--out", args->out, "Output folder: lap.csv and lap.html")->required();
  sub->add_option("--json", args->json, "Write the summary as JSON (docs/json-output.md)");
  AddShownOption(sub, "--line", args->run.line,
                 "The path driven: min-curvature (the minimum-curvature racing line), centre, "
                 "or a CSV file with distance_m and offset_m columns (e.g. hotlap optimise's "
                 "channels)");
  AddShownOption(sub, "--line-margin-m", args->run.line_margin_m,
                 "Space the racing line keeps from each edge, m")
      ->check(kPositive);
  AddShownOption(sub, "--step-m", args->run.step_m, "Distance between road points, m")
      ->check(kPositive);
  AddShownOption(sub, "--ambient-temp-C", args->run.ambient_C, "Air temperature");
  AddShownOption(sub, "--track-temp-C", args->run.track_C, "Track surface temperature");
  sub->add_option("--tread-temp-C", args->run.tread_C,
                  "Starting tread temperature (else the car's)");
  sub->add_option("--carcass-temp-C", args->run.carcass_C, "Starting carcass temperature");
  sub->add_option("--disc-temp-C", args->run.disc_C, "Starting disc temperature");
  sub->add_option("--calliper-temp-C", args->run.calliper_C, "Starting calliper temperature");
  sub->add_option("--rim-temp-C", args->run.rim_C, "Starting rim temperature (gas-and-rim tyres)");
  sub->add_option("--disc-bulk-temp-C", args->run.disc_bulk_C,
                  "Starting disc bulk temperature (surface-and-bulk discs)");
  sub->add_option("--caution-laps", args->run.caution_laps,
                  "Laps run behind the pace car, e.g. 11-15,40 (the tyres and brakes cool)");
  AddShownOption(sub, "--caution-speed-kph", args->run.caution_speed_kph,
                 "The pace car's speed under caution, km/h");
  return [args, sub] {
    for (const char* name :
         {"--laps", "--line", "--line-margin-m", "--step-m", "--tread-temp-C", "--carcass-temp-C",
          "--disc-temp-C", "--calliper-temp-C", "--rim-temp-C", "--disc-bulk-temp-C",
          "--caution-laps", "--caution-speed-kph", "--threads"}) {
      if (sub->get_option(name)->count() > 0) args->given.emplace_back(name);
    }
    return RunLap(*args);
  };
}

}  // namespace hotlap::app
