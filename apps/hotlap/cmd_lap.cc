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
#include "hotlap/common/csv.h"
#include "hotlap/common/data_path.h"
#include "hotlap/common/error.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/common/units.h"
#include "hotlap/ocp/min_curvature_line.h"
#include "hotlap/sim/lap_json.h"
#include "hotlap/sim/lap_output.h"
#include "hotlap/sim/lap_report.h"
#include "hotlap/sim/lap_summary.h"
#include "hotlap/sim/qss_lap.h"
#include "hotlap/sim/replay_io.h"
#include "hotlap/sim/road.h"
#include "hotlap/track/racing_line.h"
#include "hotlap/track/track_io.h"
#include "optimal_runs.h"

namespace hotlap::app {

namespace {

double Celsius(double kelvin) { return KelvinToCelsius(kelvin); }

// The last lap's means and energy audit per corner (docs/lap-simulation.md, "Heat over a run").
void PrintLastLapHeat(const sim::LapFigures& f, const vehicle::Car& car) {
  fmt::print("last lap means and energy audit:\n");
  fmt::print("{:<6} {:>7} {:>9} {:>6} {:>6} {:>8} {:>9} {:>8} {:>8} {:>7} {:>9} {:>9}\n", "corner",
             "tread C", "carcass C", "gas C", "rim C", "hot kPa", "build psi", "bulk C", "work kW",
             "heat kW", "heat/work", "closure");
  for (Corner c : kAllCorners) {
    const int k = CornerIndex(c);
    const sim::CornerLapMeans& m = f.means[k];
    const sim::CornerEnergyAudit& a = f.audit[k];
    const double span = a.duration_s > 0.0 ? a.duration_s : 1.0;
    const auto opt = [](bool has, double v, const char* fmt_spec) {
      return has ? fmt::format(fmt::runtime(fmt_spec), v) : std::string("-");
    };
    const bool gas = m.gas > 0.0;
    fmt::print(
        "{:<6} {:>7.1f} {:>9.1f} {:>6} {:>6} {:>8} {:>9} {:>8} {:>8.2f} {:>7.2f} {:>9.3f} "
        "{:>9.1e}\n",
        CornerName(c), Celsius(m.tread), Celsius(m.carcass), opt(gas, Celsius(m.gas), "{:.1f}"),
        opt(gas, Celsius(m.rim), "{:.1f}"), opt(gas, 1e-3 * m.pressure, "{:.0f}"),
        opt(gas, (m.pressure - car.tyre(c).params.cold_pressure) / kPsi, "{:+.1f}"),
        opt(m.disc_bulk > 0.0, Celsius(m.disc_bulk), "{:.0f}"), 1e-3 * a.MechanicalWork() / span,
        1e-3 * a.GeneratedHeat() / span, a.HeatOverWork(),
        std::max(
            {std::abs(a.TyreClosure()), std::abs(a.RimClosure()), std::abs(a.BrakeClosure())}));
  }
}

namespace fs = std::filesystem;

struct LapArgs {
  std::string method = "qss";
  std::string line = "min-curvature";
  double line_margin_m = 1.5;
  std::string track = "darlington";
  std::string car = "gen7";
  std::vector<std::string> set;  // --set KEY=VALUE
  int laps = 1;
  std::string out;
  std::string json;
  double step_m = 1.0;
  double ambient_C = 25.0;
  double track_C = 40.0;
  std::optional<double> tread_C, carcass_C, disc_C, calliper_C, rim_C, disc_bulk_C;
  std::string caution_laps;          // --method qss: laps behind the pace car, e.g. "11-15,40"
  double caution_speed_kph = 110.0;  // --method qss: the pace car's speed
  std::optional<double> compare_disc_limit_C;  // --method ocp
  std::optional<double> ocp_step_m;            // --method ocp
  bool single_process = false;                 // --method ocp with a comparison
  bool wear_in_programme = false;              // --method ocp
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
        std::pair{a.single_process, "--single-process"},
        std::pair{a.wear_in_programme, "--wear-in-programme"},
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
    o.run.ambient_C = a.ambient_C;
    o.run.track_C = a.track_C;
    if (a.ocp_step_m) o.run.step_m = *a.ocp_step_m;
    o.single_process = a.single_process;
    o.run.wear_in_programme = a.wear_in_programme;
    o.run.threads = a.threads;
    return RunOptimal(o);
  }
  if (a.laps < 1 || a.laps > 1000) {
    throw InputError(fmt::format("--laps {} must be in [1, 1000]", a.laps));
  }
  const auto started = std::chrono::steady_clock::now();
  // Everything that can fail on input is read before the output folder is touched.
  const vehicle::Car car =
      vehicle::LoadCar(ResolveCarFile(a.car), vehicle::ParseCarOverrides(a.set));
  vehicle::RequireVehicle(car, "`hotlap lap`");
  const track::Track track = track::LoadTrack(a.track);
  std::vector<sim::RoadPoint> road;
  if (a.line == "centre") {
    road = sim::SampleRoad(track, a.step_m);
  } else if (a.line == "min-curvature") {
    road = sim::SampleRoadAlongLine(
        track,
        ocp::MinimumCurvatureLine(track,
                                  {.step_m = std::max(a.step_m, 2.0), .margin_m = a.line_margin_m}),
        a.step_m);
  } else {
    // A line from a file, e.g. the channels of `hotlap optimise` (its distance_m and offset_m).
    road = sim::SampleRoadAlongLine(
        track, track::ReadRacingLine(a.line, track, std::max(a.step_m, 2.0)), a.step_m);
  }
  if (fs::exists(a.out) && !fs::is_directory(a.out)) {
    throw InputError(fmt::format("--out {}: exists and is not a folder", a.out));
  }
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");

  sim::QssOptions options;
  options.laps = a.laps;
  options.track_length = track.length_m();
  options.ambient_temp = CelsiusToKelvin(a.ambient_C);
  options.track_temp = CelsiusToKelvin(a.track_C);
  options.caution_laps = sim::ParseLapList(a.caution_laps, a.laps, "--caution-laps");
  options.caution_speed = sim::CheckCautionSpeed(a.caution_speed_kph, "--caution-speed-kph");
  const auto kelvin = [](const std::optional<double>& c) {
    return c ? std::optional<double>(CelsiusToKelvin(*c)) : std::nullopt;
  };
  options.initial = sim::CarStartState(car, {.tread_temp = kelvin(a.tread_C),
                                             .carcass_temp = kelvin(a.carcass_C),
                                             .disc_temp = kelvin(a.disc_C),
                                             .calliper_temp = kelvin(a.calliper_C),
                                             .rim_temp = kelvin(a.rim_C),
                                             .disc_bulk_temp = kelvin(a.disc_bulk_C)});
  fmt::print(
      "hotlap lap: car '{}' on {} ({:.1f} m; {} line, {:.1f} m, {} points), {} lap{}, "
      "quasi-steady-state\n",
      car.name, track.name(), track.length_m(), a.line,
      road.size() * (road[1].distance - road[0].distance), road.size(), a.laps,
      a.laps > 1 ? "s" : "");
  std::fflush(stdout);
  const sim::QssResult result = sim::RunQssLap(car, road, options);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  // Terminal summary.
  const sim::StintSummary stint = sim::SummarizeStint(result);
  fmt::print("{:>4} {:>9} {:>9} {:>9}\n", "lap", "time s", "top m/s", "min m/s");
  for (size_t l = 0; l < stint.laps.size(); ++l) {
    const sim::LapFigures& f = stint.laps[l];
    fmt::print("{:>4} {:>9.3f} {:>9.2f} {:>9.2f}\n", l + 1, f.lap_time_s, f.top_speed, f.min_speed);
  }
  fmt::print("braking zones{}:\n", a.laps > 1 ? " (last lap)" : "");
  for (const sim::BrakingZone& z : stint.braking_zones) {
    if (z.lap != a.laps) continue;
    fmt::print("  {:6.0f} m to {:6.0f} m: {:.1f} -> {:.1f} m/s, peak {:.2f} m/s^2, {:.2f} s\n",
               z.start_m, z.end_m, z.entry_speed, z.exit_speed, z.peak_decel, z.duration_s);
  }
  fmt::print("{:<6} {:>10} {:>11} {:>9} {:>12} {:>12}\n", "corner", "tread pk C", "carcass pk C",
             "disc pk C", "calliper pk C", "wear mm/lap");
  for (Corner c : kAllCorners) {
    const sim::StintCorner& s = stint.corners[CornerIndex(c)];
    fmt::print("{:<6} {:>10.1f} {:>11.1f} {:>9.1f} {:>12.1f} {:>12.5f}\n", CornerName(c),
               Celsius(s.peak_tread_temp), Celsius(s.peak_carcass_temp), Celsius(s.peak_disc_temp),
               Celsius(s.peak_calliper_temp), s.wear_per_lap_mm);
  }
  PrintLastLapHeat(stint.laps.back(), car);
  if (stint.slip_points_not_reached > 0) {
    fmt::print(
        "note: at {} samples a tyre could not make the force the speed profile gave it (largest "
        "shortfall {:.0f} N): the combined-slip envelope is inside the friction ellipse there\n",
        stint.slip_points_not_reached, stint.max_force_deficit);
  }

  // Outputs: the folder, then each file atomically.
  fs::create_directories(a.out);
  const fs::path csv = fs::path(a.out) / "lap.csv", html = fs::path(a.out) / "lap.html";
  const sim::ColumnSet columns =
      sim::LapResultColumns(result, track, options.ambient_temp, options.track_temp);
  std::vector<std::pair<std::string, std::string>> metadata = {
      {"source", fmt::format("hotlap {} lap --method qss", HOTLAP_VERSION)},
      {"track", track.name()},
      {"car", car.path.string()},
      {"laps", std::to_string(a.laps)}};
  if (!a.set.empty()) metadata.emplace_back("overrides", vehicle::OverridesText(car.overrides));
  WriteCsv(csv, metadata, columns.names, columns.values);
  sim::WriteLapReport(html, {a.line, a.laps, a.ambient_C, a.track_C}, car, track, columns, stint);
  fmt::print("wrote {} and {} in {:.2f} s\n", csv.string(), html.string(), elapsed);

  if (!a.json.empty()) {
    WriteJsonFile(a.json, sim::StintJson(stint, track, car, csv.string(), html.string()));
    fmt::print("wrote {}\n", a.json);
  }
  return 0;
}

}  // namespace

CommandRunner RegisterLapCommand(CLI::App& app) {
  auto args = std::make_shared<LapArgs>();
  CLI::App* sub = app.add_subcommand("lap",
                                     "Drive the car round a track with the thermal models: "
                                     "quasi-steady state, or the optimal lap (--method ocp)");
  sub->add_option("--method", args->method,
                  "qss (quasi-steady state) or ocp (optimal control, as `hotlap optimise`)")
      ->capture_default_str()
      ->check(CLI::IsMember({"qss", "ocp"}));
  sub->add_option("--compare-disc-limit-C", args->compare_disc_limit_C,
                  "ocp: solve without and with this front-disc limit (degC) and compare");
  sub->add_option("--ocp-step-m", args->ocp_step_m, "ocp: mesh spacing, m (default 3)");
  sub->add_flag("--single-process", args->single_process,
                "ocp: solve the limited lap after the free one, not beside it in a second process");
  sub->add_flag("--wear-in-programme", args->wear_in_programme,
                "ocp: keep the tyres' wear as states of the fine solves' programmes (by default "
                "frozen for the forces and integrated after the solve; docs/optimal-control.md)");
  sub->add_option("--threads", args->threads,
                  "ocp: threads evaluating the derivatives (0: one per core, at most 8; the "
                  "comparison's two solves take half each)")
      ->capture_default_str()
      ->check(CLI::Range(0, 256));
  sub->add_option("--track", args->track, "Built-in track name or a .yaml/.csv/.xml file")
      ->capture_default_str();
  sub->add_option("--car", args->car, "Built-in car name or path to a car.yaml")
      ->capture_default_str();
  AddSetOption(sub, args->set);
  sub->add_option("--laps", args->laps, "Laps in the stint (thermal state carried over)")
      ->capture_default_str();
  sub->add_option("--out", args->out, "Output folder: lap.csv and lap.html")->required();
  sub->add_option("--json", args->json, "Write the summary as JSON (docs/json-output.md)");
  sub->add_option("--line", args->line,
                  "The path driven: min-curvature (the minimum-curvature racing line), centre, "
                  "or a CSV file with distance_m and offset_m columns (e.g. hotlap optimise's "
                  "channels)")
      ->capture_default_str();
  sub->add_option("--line-margin-m", args->line_margin_m,
                  "Space the racing line keeps from each edge, m")
      ->capture_default_str()
      ->check(kPositive);
  sub->add_option("--step-m", args->step_m, "Distance between road points, m")
      ->capture_default_str()
      ->check(kPositive);
  sub->add_option("--ambient-temp-C", args->ambient_C, "Air temperature")->capture_default_str();
  sub->add_option("--track-temp-C", args->track_C, "Track surface temperature")
      ->capture_default_str();
  sub->add_option("--tread-temp-C", args->tread_C, "Starting tread temperature (else the car's)");
  sub->add_option("--carcass-temp-C", args->carcass_C, "Starting carcass temperature");
  sub->add_option("--disc-temp-C", args->disc_C, "Starting disc temperature");
  sub->add_option("--calliper-temp-C", args->calliper_C, "Starting calliper temperature");
  sub->add_option("--rim-temp-C", args->rim_C, "Starting rim temperature (gas-and-rim tyres)");
  sub->add_option("--disc-bulk-temp-C", args->disc_bulk_C,
                  "Starting disc bulk temperature (surface-and-bulk discs)");
  sub->add_option("--caution-laps", args->caution_laps,
                  "Laps run behind the pace car, e.g. 11-15,40 (the tyres and brakes cool)");
  sub->add_option("--caution-speed-kph", args->caution_speed_kph,
                  "The pace car's speed under caution, km/h")
      ->capture_default_str();
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
