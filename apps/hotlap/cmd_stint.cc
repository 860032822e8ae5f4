// `hotlap stint`: N laps as one optimal-control problem, with wear, carcass heat and fuel carried
// from lap to lap, against the greedy driver's N single optimal laps (docs/optimal-control.md,
// "Stints").

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.h"
#include "hotlap/common/data_path.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/ocp/optimal_run.h"
#include "hotlap/ocp/solver_memory.h"
#include "hotlap/ocp/stint_output.h"
#include "hotlap/runs/stint_run.h"
#include "hotlap/track/track_io.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::app {
namespace {

namespace fs = std::filesystem;

struct StintArgs {
  std::string track = "darlington";
  std::string car = "gen7";
  std::vector<std::string> set;
  runs::StintRunOptions stint = [] {
    runs::StintRunOptions o;
    o.bsfc_g_per_kWh = 300.0;
    o.run.threads = 0;  // --threads: one per core
    return o;
  }();
  std::string out, json;
  std::string checkpoint;
};

int RunStint(const StintArgs& a) {
  const auto started = std::chrono::steady_clock::now();
  CheckOutputDirectory(a.out, "--out");
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  const vehicle::Car car =
      vehicle::LoadCar(ResolveCarFile(a.car), vehicle::ParseCarOverrides(a.set));
  vehicle::RequireVehicle(car, "a stint");
  const track::Track track = track::LoadTrack(a.track);
  runs::StintRunOptions stint = a.stint;
  if (!a.checkpoint.empty()) {
    stint.checkpoint_dir = a.checkpoint;
    stint.checkpoint_key =
        runs::StintCheckpointKey(ResolveCarFile(a.car), ResolveTrackFile(a.track), a.set);
  }
  ocp::StintOptions o = runs::MakeStintOptions(stint, runs::NameStyle::kCommandLine);
  // Progress of every solve (the greedy laps' and the stint's), every tenth iteration.
  o.lap.ipopt.on_iteration = [](int it, double objective, double infeasibility, double optimality) {
    if (it % 10 == 0) {
      fmt::print("    iteration {:4d}: objective {:.4f}, infeasibility {:.1e}, optimality {:.1e}\n",
                 it, objective, infeasibility, optimality);
      std::fflush(stdout);
    }
    return true;
  };
  ocp::KeepSolverMemory();
  fmt::print("hotlap stint: {} laps of {} ({:.1f} m) with car '{}', wear x {:g}, {:g} kg of fuel\n",
             o.laps, track.name(), track.length_m(), car.name, o.wear_scale, o.fuel_kg);
  std::fflush(stdout);
  const ocp::StintResult r = ocp::SolveStint(car, track, o, [](const std::string& line) {
    fmt::print("  {}\n", line);
    std::fflush(stdout);
  });
  fmt::print("{}", ocp::StintText(r));
  CreateOutputDirectory(a.out, "--out");
  for (const fs::path& p : ocp::WriteStintFiles(a.out, r, o, car, track)) {
    fmt::print("wrote {}\n", p.string());
  }
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  fmt::print("done in {:.1f} s\n", elapsed);
  if (!a.json.empty()) {
    WriteJsonFileAndSay(a.json, ocp::StintJson(r, o, track.name(), car, elapsed));
  }
  return r.ok() ? 0 : 3;
}

}  // namespace

CommandRunner RegisterStintCommand(CLI::App& app) {
  auto a = std::make_shared<StintArgs>();
  CLI::App* sub = app.add_subcommand(
      "stint",
      "N laps as one optimal-control problem (wear, carcass heat and fuel carried lap to lap) "
      "against the greedy driver's lap-by-lap optimal laps");
  AddShownOption(sub, "--track", a->track, "Built-in track name or a track file");
  AddShownOption(sub, "--car", a->car, "Built-in car name or path to a car.yaml");
  AddSetOption(sub, a->set);
  AddShownOption(sub, "--laps", a->stint.laps, "Laps in the stint")->check(CLI::Range(1, 100));
  AddShownOption(sub, "--wear-scale", a->stint.wear_scale,
                 "Wear rate times this: N laps stand for about N times this many laps of wear "
                 "(0: no wear)")
      ->check(kNonNegative);
  AddShownOption(sub, "--fuel-kg", a->stint.fuel_kg,
                 "Fuel aboard at the start (in the car's mass), burnt with the engine's work; 0: "
                 "mass constant")
      ->check(kNonNegative);
  sub->add_option("--bsfc-g-per-kWh", *a->stint.bsfc_g_per_kWh,
                  "Brake-specific fuel consumption (assumed 300 g/kWh)")
      ->capture_default_str()
      ->check(kPositive);
  sub->add_option("--disc-limit-C", a->stint.disc_limit_C,
                  "Front disc temperatures at most this on every lap, degC");
  AddShownOption(sub, "--step-m", a->stint.run.step_m, "Mesh spacing along the centre line, m")
      ->check(CLI::Range(0.5, 50.0));
  AddShownOption(sub, "--coarse-step-m", a->stint.run.coarse_step_m,
                 "The greedy laps coarse to fine from this spacing, m (0: off)")
      ->check(CLI::Range(0.0, 100.0));
  AddShownOption(sub, "--thermal-start", a->stint.run.thermal_start,
                 "Thermal states at the start: racing, warm or car (docs/optimal-control.md)")
      ->check(CLI::IsMember({"racing", "warm", "car"}));
  AddShownOption(sub, "--ambient-temp-C", a->stint.run.ambient_C, "Air temperature");
  AddShownOption(sub, "--track-temp-C", a->stint.run.track_C, "Track surface temperature");
  AddShownOption(sub, "--threads", a->stint.run.threads,
                 "Threads evaluating the derivatives (0: one per core, at most 8)")
      ->check(CLI::Range(0, 256));
  AddShownOption(sub, "--max-iterations", a->stint.run.max_iterations,
                 "Ipopt's iteration limit per solve")
      ->check(kPositive);
  sub->add_option("--checkpoint", a->checkpoint,
                  "Checkpoint folder: each greedy lap's solves and the stint's iterate saved as "
                  "the run goes; run the same command again to resume from them "
                  "(docs/reliability.md)");
  AddShownOption(sub, "--checkpoint-every", a->stint.checkpoint_every,
                 "Save the stint solve's iterate every this many Ipopt iterations")
      ->check(CLI::Range(1, 100000));
  sub->add_option("--out", a->out, "Output folder: stint.csv and stint.html")->required();
  sub->add_option("--json", a->json, "Write the summary as JSON (docs/json-output.md)");
  return [a] { return RunStint(*a); };
}

}  // namespace hotlap::app
