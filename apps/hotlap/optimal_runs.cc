// The optimal lap's runs for `hotlap optimise` and `hotlap lap --method ocp`
// (docs/optimal-control.md): the checks, the library's solves, the summary and the outputs.

#include "optimal_runs.h"

#include <chrono>
#include <cstdio>
#include <optional>

#include <fmt/format.h>

#include "hotlap/common/data_path.h"
#include "hotlap/common/error.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/ocp/lap_start_file.h"
#include "hotlap/ocp/mesh_check.h"
#include "hotlap/ocp/optimal_run_json.h"
#include "hotlap/ocp/optimal_run_output.h"
#include "hotlap/ocp/optimal_run_text.h"
#include "hotlap/ocp/solver_memory.h"
#include "hotlap/track/track_io.h"
#include "hotlap/vehicle/f1_car.h"

namespace hotlap::app {

namespace {

namespace fs = std::filesystem;

// Progress on the terminal: every tenth iteration, and the library's own lines.
bool PrintProgress(const std::string& label, int it, double obj, double pr, double du) {
  if (it % 10 == 0) {
    fmt::print("  [{}] iteration {:4d}: lap {:.4f} s, infeasibility {:.1e}, optimality {:.1e}\n",
               label, it, obj, pr, du);
    std::fflush(stdout);
  }
  return true;
}

void PrintLine(const std::string& line) {
  fmt::print("{}\n", line);
  std::fflush(stdout);
}

// InputError for an option of the other model (the stock car's or the F1 car's).
void CheckModelOptions(const OptimalArgs& a, bool f1) {
  for (const CLI::Option* o : f1 ? a.stock_car_only : a.f1_only) {
    if (o->count() > 0) {
      const std::string name = o->get_name();
      const bool mesh = name == "--step-m" || name == "--mesh-points" || name == "--mesh-check";
      throw InputError(
          fmt::format("{} does not apply to the car '{}' ({} model){}", name, a.car,
                      f1 ? "the limebeer-2014-f1" : "the stock-car",
                      !mesh ? ""
                      : f1  ? ": its mesh is set by --mesh-points (docs/f1-peer.md)"
                            : ": its mesh is set by --step-m (docs/optimal-control.md)"));
    }
  }
}

}  // namespace

ocp::OptimalRunOptions RunOptions(const OptimalArgs& a) {
  ocp::OptimalRunOptions o = a.run;
  o.convex_element_hessians = a.hessian == "convex-elements";
  o.independent_drive_and_brake = a.controls == "independent";
  o.second_process = !a.single_process;
  for (const std::string& kv : a.ipopt_options) {
    const size_t eq = kv.find('=');  // the option's check guarantees one
    o.ipopt_options.emplace_back(kv.substr(0, eq), kv.substr(eq + 1));
  }
  return o;
}

int RunOptimal(const OptimalArgs& a) {
  // The 3-DOF F1 car of the fastest-lap peer benchmark has its own solver (docs/f1-peer.md).
  const fs::path car_file = ResolveCarFile(a.car);
  const bool f1 = vehicle::IsF1CarFile(car_file);
  CheckModelOptions(a, f1);
  if (f1) return RunF1Optimal(a, car_file);
  const ocp::OptimalRunOptions o = RunOptions(a);
  const auto started = std::chrono::steady_clock::now();
  const vehicle::Car car = vehicle::LoadCar(car_file, vehicle::ParseCarOverrides(a.set));
  vehicle::RequireVehicle(car, "the optimal lap");
  const track::Track track = track::LoadTrack(a.track);
  CheckOutputDirectory(a.out, "--out");
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  if (!a.save_solution.empty()) CheckOutputFolder(a.save_solution, "--save-solution");
  if (o.compare_disc_limit_C && !(a.warm_start.empty() && a.save_solution.empty())) {
    throw InputError("--warm-start and --save-solution are for one solve, not the comparison");
  }
  CheckDiscLimits(o);
  std::optional<ocp::LapStart> warm_start;
  if (!a.warm_start.empty()) warm_start = ocp::ReadLapStart(a.warm_start);
  ocp::KeepSolverMemory();
  fmt::print("hotlap optimal lap: car '{}' on {} ({:.1f} m)\n", car.name, track.name(),
             track.length_m());
  const ocp::OptimalRuns runs = ocp::SolveOptimalRuns(
      car, track, o, warm_start ? &*warm_start : nullptr, PrintProgress, PrintLine);
  const ocp::SolvedLap& first = runs.laps.front();
  if (!a.save_solution.empty() && first.run.solution.solve.ok()) {
    ocp::WriteLapStart(a.save_solution, first.run.solution, track.length_m());
    fmt::print("wrote {}\n", a.save_solution);
  }
  std::optional<double> mesh_delta;
  if (a.mesh_check) {
    const ocp::SolvedLap fine = ocp::SolveOnHalfMesh(car, track, ocp::MakeOptimalLapOptions(o),
                                                     first, PrintProgress, PrintLine);
    mesh_delta = fine.figures.lap_time_s - first.figures.lap_time_s;
  }
  for (const ocp::SolvedLap& s : runs.laps) {
    fmt::print("{}:\n{}{}", s.label, ocp::SolvedLapText(s, o.thermal_start),
               ocp::SensitivitiesText(s));
  }
  if (runs.laps.size() == 2) fmt::print("{}", ocp::DiscLimitCostText(first, runs.laps[1]));
  if (mesh_delta) {
    fmt::print("mesh check: halving the spacing to {:.2f} m changes the lap by {:.1f} ms\n",
               0.5 * o.step_m, 1e3 * *mesh_delta);
  }

  for (const fs::path& p : ocp::WriteOptimalRunFiles(a.out, runs.laps, car, track, o.step_m)) {
    fmt::print("wrote {}\n", p.string());
  }
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  fmt::print("done in {:.1f} s\n", elapsed);

  bool ok = true;
  for (const ocp::SolvedLap& s : runs.laps) ok = ok && s.run.solution.solve.ok();
  if (!a.json.empty()) {
    nlohmann::json j = ocp::OptimalRunsJson(runs, o, track.name(), car, elapsed, mesh_delta);
    j["command"] = a.command;  // the command that ran it, whether one solve or the comparison
    WriteJsonFile(a.json, j);
    fmt::print("wrote {}\n", a.json);
  }
  return ok ? 0 : 3;
}

}  // namespace hotlap::app
