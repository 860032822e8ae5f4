// The optimal lap's runs, summaries and outputs for `hotlap optimise` and `hotlap lap --method
// ocp` (docs/optimal-control.md).

#include "optimal_runs.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "f1_optimal_run.h"
#include "hotlap/common/csv.h"
#include "hotlap/common/data_path.h"
#include "hotlap/common/error.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/common/units.h"
#include "hotlap/ocp/disc_limit_comparison.h"
#include "hotlap/ocp/lap_start_file.h"
#include "hotlap/ocp/mesh_check.h"
#include "hotlap/ocp/optimal_lap.h"
#include "hotlap/ocp/optimal_output.h"
#include "hotlap/ocp/solver_memory.h"
#include "hotlap/report/html_report.h"
#include "hotlap/track/track_io.h"
#include "hotlap/vehicle/f1_car.h"
#include "optimal_summary.h"

namespace hotlap::app {

namespace {

namespace fs = std::filesystem;

// The command's options as the library's.
ocp::OptimalLapOptions LapOptions(const OptimalArgs& a, double step_m) {
  ocp::OptimalLapOptions o;
  o.step_m = step_m;
  o.coarse_step_m = a.coarse_step_m;
  o.steer_smoothing_weight = a.steer_smoothing;
  o.pedal_smoothing_weight = a.pedal_smoothing;
  o.convex_element_hessians = a.hessian == "convex-elements";
  o.thermal_start = ocp::ParseThermalStart(a.thermal_start);
  o.ambient_temp = CelsiusToKelvin(a.ambient_C);
  o.track_temp = CelsiusToKelvin(a.track_C);
  o.ipopt.max_iterations = a.max_iterations;
  for (auto& kv : IpoptOptionPairs(a)) o.ipopt.extra.push_back(std::move(kv));
  o.ipopt.print_level = a.ipopt_output ? 5 : 0;
  o.second_process = !a.single_process;
  return o;
}

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

}  // namespace

int RunOptimal(const OptimalArgs& a) {
  // The 3-DOF F1 car of the fastest-lap peer benchmark has its own solver (docs/f1-peer.md).
  const fs::path car_file = ResolveCarFile(a.car);
  const bool f1 = vehicle::IsF1CarFile(car_file);
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
  if (f1) return RunF1Optimal(a, car_file);
  const auto started = std::chrono::steady_clock::now();
  const vehicle::Car car = vehicle::LoadCar(car_file);
  vehicle::RequireVehicle(car, "the optimal lap");
  const track::Track track = track::LoadTrack(a.track);
  if (fs::exists(a.out) && !fs::is_directory(a.out)) {
    throw InputError(fmt::format("--out {}: exists and is not a folder", a.out));
  }
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  if (!a.save_solution.empty()) CheckOutputFolder(a.save_solution, "--save-solution");
  if (a.compare_disc_limit_C && !(a.warm_start.empty() && a.save_solution.empty())) {
    throw InputError("--warm-start and --save-solution are for one solve, not the comparison");
  }
  if (a.disc_limit_C && a.compare_disc_limit_C) {
    throw InputError("give either --disc-limit-C (one solve) or --compare-disc-limit-C (two)");
  }
  for (const auto& limit : {a.disc_limit_C, a.compare_disc_limit_C}) {
    if (limit && !(*limit > 0.0 && *limit < 1500.0)) {
      throw InputError(fmt::format("the disc limit {:g} degC must be in (0, 1500)", *limit));
    }
  }
  std::optional<ocp::LapStart> warm_start;
  if (!a.warm_start.empty()) warm_start = ocp::ReadLapStart(a.warm_start);
  ocp::KeepSolverMemory();
  fmt::print("hotlap optimal lap: car '{}' on {} ({:.1f} m)\n", car.name, track.name(),
             track.length_m());
  std::vector<ocp::SolvedLap> runs;
  bool limited_in_second_process = false;
  if (a.compare_disc_limit_C) {
    ocp::DiscLimitComparison c =
        ocp::CompareDiscLimit(car, track, LapOptions(a, a.step_m),
                              CelsiusToKelvin(*a.compare_disc_limit_C), PrintProgress, PrintLine);
    limited_in_second_process = c.limited_in_second_process;
    runs.push_back(std::move(c.free));
    runs.push_back(std::move(c.limited));
  } else {
    ocp::OptimalLapOptions o = LapOptions(a, a.step_m);
    if (a.disc_limit_C) o.front_disc_limit = CelsiusToKelvin(*a.disc_limit_C);
    if (warm_start) ocp::UseLapStart(*warm_start, track, o);
    runs.push_back(ocp::SolveLap(
        car, track, o,
        a.disc_limit_C ? fmt::format("discs <= {:g} degC", *a.disc_limit_C) : "optimal lap",
        nullptr, PrintProgress, PrintLine));
  }
  if (!a.save_solution.empty() && runs.front().run.solution.solve.ok()) {
    ocp::WriteLapStart(a.save_solution, runs.front().run.solution, track.length_m());
    fmt::print("wrote {}\n", a.save_solution);
  }
  std::optional<double> mesh_delta;
  if (a.mesh_check) {
    const ocp::SolvedLap fine = ocp::SolveOnHalfMesh(car, track, LapOptions(a, a.step_m),
                                                     runs.front(), PrintProgress, PrintLine);
    mesh_delta = fine.figures.lap_time_s - runs.front().figures.lap_time_s;
  }
  for (const ocp::SolvedLap& s : runs) {
    fmt::print("{}:\n", s.label);
    PrintRun(s, a.thermal_start);
  }
  if (runs.size() == 2) {
    const double delta = runs[1].figures.lap_time_s - runs[0].figures.lap_time_s;
    fmt::print("the {} limit costs {:.3f} s ({:.0f} ms); top speed {:.2f} -> {:.2f} m/s\n",
               runs[1].label, delta, 1e3 * delta, runs[0].figures.top_speed_mps,
               runs[1].figures.top_speed_mps);
    for (size_t t = 0; t < runs[0].approaches.size() && t < runs[1].approaches.size(); ++t) {
      const ocp::TurnApproach& x = runs[0].approaches[t];
      const ocp::TurnApproach& y = runs[1].approaches[t];
      fmt::print("  {}: lift {} -> {} m, brake {} -> {} m\n", x.turn, Opt(x.lift_m, "{:.0f}"),
                 Opt(y.lift_m, "{:.0f}"), Opt(x.brake_m, "{:.0f}"), Opt(y.brake_m, "{:.0f}"));
    }
  }
  if (mesh_delta) {
    fmt::print("mesh check: halving the spacing to {:.2f} m changes the lap by {:.1f} ms\n",
               0.5 * a.step_m, 1e3 * *mesh_delta);
  }

  // Outputs.
  fs::create_directories(a.out);
  std::vector<fs::path> written;
  if (runs.size() == 1) {
    written.push_back(fs::path(a.out) / "optimal.csv");
    WriteRunCsv(written.back(), runs[0], track, car);
  } else {
    written.push_back(fs::path(a.out) / "unconstrained.csv");
    WriteRunCsv(written.back(), runs[0], track, car);
    written.push_back(fs::path(a.out) / "constrained.csv");
    WriteRunCsv(written.back(), runs[1], track, car);
  }
  {
    report::HtmlReport page(fmt::format("hotlap optimal lap: {} on {}", car.name, track.name()));
    page.AddMetadata("car", car.path.string());
    page.AddMetadata("track", fmt::format("{} ({:.1f} m)", track.name(), track.length_m()));
    page.AddMetadata("mesh", fmt::format("{:g} m, trapezoidal collocation, Ipopt", a.step_m));
    page.AddMetadata("version", HOTLAP_VERSION);
    page.AddHeading("Summary");
    std::vector<std::vector<std::string>> rows;
    for (const ocp::SolvedLap& s : runs) {
      rows.push_back({s.label, fmt::format("{:.3f}", s.figures.lap_time_s),
                      fmt::format("{:.2f}", s.figures.top_speed_mps),
                      fmt::format("{:.1f}", s.figures.max_front_disc_temp_C),
                      s.run.solution.solve.message,
                      fmt::format("{} / {:.1f} s", s.run.solution.solve.iterations,
                                  s.run.solution.solve.solve_seconds)});
    }
    page.AddTable({.title = "Runs",
                   .header = {"run", "lap s", "top m/s", "front disc pk \u00b0C", "Ipopt",
                              "iterations / time"},
                   .rows = rows});
    std::vector<const ocp::OptimalLapRun*> ptrs;
    std::vector<std::string> labels;
    for (const ocp::SolvedLap& s : runs) {
      ptrs.push_back(&s.run);
      labels.push_back(s.label);
    }
    ocp::AddOptimalLapCharts(page, ptrs, labels, track);
    written.push_back(fs::path(a.out) / (runs.size() == 2 ? "compare.html" : "optimal.html"));
    page.Write(written.back());
  }
  for (const fs::path& p : written) fmt::print("wrote {}\n", p.string());
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  fmt::print("done in {:.1f} s\n", elapsed);

  bool ok = true;
  for (const ocp::SolvedLap& s : runs) ok = ok && s.run.solution.solve.ok();
  if (!a.json.empty()) {
    nlohmann::json j;
    if (runs.size() == 2) {
      j = {{"command", "lap --method ocp"},
           {"unconstrained", RunJson(runs[0], a.thermal_start)},
           {"constrained", RunJson(runs[1], a.thermal_start)},
           {"delta_s", RoundSignificant(runs[1].figures.lap_time_s - runs[0].figures.lap_time_s)}};
      // The headline keys of the unconstrained run at the top level too.
      for (const char* k : {"lap_time_s", "solve_time_s", "ipopt_iterations", "status",
                            "max_front_disc_temp_C", "top_speed_mps"}) {
        j[k] = j["unconstrained"][k];
      }
      j["limited_in_second_process"] = limited_in_second_process;
    } else {
      j = RunJson(runs[0], a.thermal_start);
      j["command"] = "optimise";
    }
    j["track"] = track.name();
    j["car"] = car.name;
    j["mesh_step_m"] = a.step_m;
    j["wall_time_s"] = RoundSignificant(elapsed);
    if (mesh_delta) j["mesh_check_delta_s"] = RoundSignificant(*mesh_delta);
    WriteJsonFile(a.json, j);
    fmt::print("wrote {}\n", a.json);
  }
  return ok ? 0 : 3;
}

}  // namespace hotlap::app
