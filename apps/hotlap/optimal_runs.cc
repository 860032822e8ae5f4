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
#include "hotlap/common/units.h"
#include "hotlap/ocp/optimal_lap.h"
#include "hotlap/ocp/optimal_output.h"
#include "hotlap/ocp/solver_memory.h"
#include "hotlap/report/html_report.h"
#include "hotlap/track/track_io.h"
#include "hotlap/vehicle/f1_car.h"
#include "output.h"

namespace hotlap::app {

namespace {

namespace fs = std::filesystem;

ocp::ThermalStart ParseStart(const std::string& s) {
  if (s == "car") return ocp::ThermalStart::kCar;
  if (s == "periodic") return ocp::ThermalStart::kPeriodic;
  if (s == "warm") return ocp::ThermalStart::kWarm;
  return ocp::ThermalStart::kRacing;
}

struct Solved {
  std::string label;
  std::string thermal_start;
  std::optional<double> limit_C;
  ocp::OptimalLapRun run;
  ocp::OptimalLapFigures figures;
  std::vector<ocp::TurnApproach> approaches;
};

Solved Solve(const OptimalArgs& a, const vehicle::Car& car, const track::Track& track,
             std::optional<double> limit_C, double step_m, const std::string& label,
             const ocp::SolveResult* from = nullptr) {
  ocp::OptimalLapOptions o;
  if (from != nullptr) {
    // Warm start: the other solution's point and multipliers (same variables and rows).
    o.start_point = from->x;
    o.ipopt.warm_z_lower = from->z_lower;
    o.ipopt.warm_z_upper = from->z_upper;
    o.ipopt.warm_lambda = from->lambda;
  }
  o.step_m = step_m;
  if (limit_C) o.front_disc_limit = CelsiusToKelvin(*limit_C);
  o.thermal_start = ParseStart(a.thermal_start);
  o.ambient_temp = CelsiusToKelvin(a.ambient_C);
  o.track_temp = CelsiusToKelvin(a.track_C);
  o.ipopt.max_iterations = a.max_iterations;
  o.ipopt.extra = IpoptOptionPairs(a);
  o.ipopt.print_level = a.ipopt_output ? 5 : 0;
  o.ipopt.on_iteration = [&](int it, double obj, double pr, double du) {
    if (it % 10 == 0) {
      fmt::print("  [{}] iteration {:4d}: lap {:.4f} s, infeasibility {:.1e}, optimality {:.1e}\n",
                 label, it, obj, pr, du);
      std::fflush(stdout);
    }
    return true;
  };
  fmt::print("{}: solving ({:.1f} m mesh{}{})...\n", label, step_m,
             limit_C ? fmt::format(", front discs <= {:g} degC", *limit_C) : "",
             from == nullptr ? "" : ", from the other solution");
  std::fflush(stdout);
  Solved s;
  s.label = label;
  s.thermal_start = a.thermal_start;
  s.limit_C = limit_C;
  s.run = ocp::RunOptimalLap(car, track, o);
  s.figures = ocp::CalcOptimalLapFigures(s.run, car.vehicle->powertrain.WheelPower());
  s.approaches =
      ocp::FindTurnApproaches(s.run.solution, track, car.vehicle->powertrain.WheelPower());
  const ocp::SolveResult& r = s.run.solution.solve;
  fmt::print(
      "{}: {} after {} iterations in {:.1f} s: lap {:.3f} s (QSS {:.3f} s on the minimum-curvature "
      "line, {:.3f} s on this lap's line)\n",
      label, r.message, r.iterations, r.solve_seconds, s.figures.lap_time_s, s.run.qss_lap_time,
      s.run.qss_on_line_lap_time);
  return s;
}

nlohmann::json RunJson(const Solved& s) {
  const ocp::SolveResult& r = s.run.solution.solve;
  const ocp::OptimalLapFigures& f = s.figures;
  nlohmann::json corners;
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    corners[std::string(CornerName(c))] = {
        {"peak_disc_temp_C", RoundSignificant(f.peak_disc_temp_C[i])},
        {"peak_tread_temp_C", RoundSignificant(f.peak_tread_temp_C[i])},
        {"wear_mm", RoundSignificant(f.wear_mm[i])}};
  }
  nlohmann::json start = {{"mode", s.thermal_start}, {"qss_laps", s.run.start_laps}};
  if (s.thermal_start == "racing") {
    start["carcass_rise_K"] = RoundSignificant(s.run.start_carcass_rise_K);
  }
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    // The state at the start line (periodic: the solution's own first node).
    const ocp::CornerTrace& t = s.run.solution.corners[i];
    const bool own = !t.tread_temp.empty();
    start["corners"][std::string(CornerName(c))] = {
        {"tread_temp_C", RoundSignificant(KelvinToCelsius(own ? t.tread_temp.front()
                                                              : s.run.start.tyres[i].tread_temp))},
        {"carcass_temp_C", RoundSignificant(KelvinToCelsius(
                               own ? t.carcass_temp.front() : s.run.start.tyres[i].carcass_temp))},
        {"disc_temp_C", RoundSignificant(KelvinToCelsius(own ? t.disc_temp.front()
                                                             : s.run.start.brakes[i].disc_temp))},
        {"calliper_temp_C",
         RoundSignificant(KelvinToCelsius(own ? t.calliper_temp.front()
                                              : s.run.start.brakes[i].calliper_temp))}};
  }
  nlohmann::json turns = nlohmann::json::array();
  for (const ocp::TurnApproach& t : s.approaches) {
    nlohmann::json j = {{"turn", t.turn},
                        {"entry_m", RoundSignificant(t.entry_m)},
                        {"min_speed_mps", RoundSignificant(t.min_speed_mps)},
                        {"min_speed_at_m", RoundSignificant(t.min_speed_at_m)}};
    j["lift_m"] = t.lift_m ? nlohmann::json(RoundSignificant(*t.lift_m)) : nlohmann::json();
    j["brake_m"] = t.brake_m ? nlohmann::json(RoundSignificant(*t.brake_m)) : nlohmann::json();
    turns.push_back(j);
  }
  return {{"lap_time_s", RoundSignificant(f.lap_time_s)},
          {"qss_lap_time_s", RoundSignificant(s.run.qss_lap_time)},
          {"qss_on_optimal_line_lap_time_s", RoundSignificant(s.run.qss_on_line_lap_time)},
          {"solve_time_s", RoundSignificant(r.solve_seconds)},
          {"ipopt_iterations", r.iterations},
          {"status", r.ok() ? "converged" : "failed"},
          {"message", r.message},
          {"front_disc_limit_C", s.limit_C ? nlohmann::json(*s.limit_C) : nlohmann::json()},
          {"max_front_disc_temp_C", RoundSignificant(f.max_front_disc_temp_C)},
          {"top_speed_mps", RoundSignificant(f.top_speed_mps)},
          {"min_speed_mps", RoundSignificant(f.min_speed_mps)},
          {"corners", corners},
          {"turns", turns},
          {"thermal_start", start},
          {"brake_energy_J", RoundSignificant(f.brake_energy_J)},
          {"brake_energy_under_drive_J", RoundSignificant(f.brake_energy_under_drive_J)},
          {"max_pedal_rate_per_s", RoundSignificant(f.max_pedal_rate_per_s)},
          {"max_steer_rate_radps", RoundSignificant(f.max_steer_rate_radps)},
          {"smoothing_effect_tread_K", RoundSignificant(s.run.max_tread_difference_K)},
          {"smoothing_effect_disc_K", RoundSignificant(s.run.max_disc_difference_K)},
          {"variables", s.run.solution.variables},
          {"constraints", s.run.solution.constraints}};
}

std::string Opt(const std::optional<double>& v, const char* fmtstr) {
  return v ? fmt::format(fmt::runtime(fmtstr), *v) : std::string("-");
}

void PrintRun(const Solved& s) {
  const ocp::OptimalLapFigures& f = s.figures;
  fmt::print(
      "  lap {:.3f} s, top speed {:.2f} m/s, slowest {:.2f} m/s, front discs peak {:.1f} "
      "degC\n",
      f.lap_time_s, f.top_speed_mps, f.min_speed_mps, f.max_front_disc_temp_C);
  {
    const ocp::LapSolution& sol = s.run.solution;
    std::string carcass, disc;
    for (int i = 0; i < 4 && !sol.corners[i].carcass_temp.empty(); ++i) {
      carcass +=
          fmt::format("{}{:.0f}", i ? "/" : "", KelvinToCelsius(sol.corners[i].carcass_temp[0]));
      disc += fmt::format("{}{:.0f}", i ? "/" : "", KelvinToCelsius(sol.corners[i].disc_temp[0]));
    }
    fmt::print("  thermal start {} ({} QSS laps): carcass fl/fr/rl/rr {} degC, discs {} degC\n",
               s.thermal_start, s.run.start_laps, carcass, disc);
  }
  fmt::print("  brake work {:.0f} kJ, of it against the engine (drive above 2%) {:.2f} kJ\n",
             1e-3 * f.brake_energy_J, 1e-3 * f.brake_energy_under_drive_J);
  for (const ocp::TurnApproach& t : s.approaches) {
    fmt::print("  {}: lift at {} m, brake at {} m, slowest {:.2f} m/s at {:.0f} m\n", t.turn,
               Opt(t.lift_m, "{:.0f}"), Opt(t.brake_m, "{:.0f}"), t.min_speed_mps,
               t.min_speed_at_m);
  }
  fmt::print("  {:<6} {:>12} {:>12} {:>10}\n", "corner", "disc pk C", "tread pk C", "wear mm");
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    fmt::print("  {:<6} {:>12.1f} {:>12.1f} {:>10.5f}\n", CornerName(c), f.peak_disc_temp_C[i],
               f.peak_tread_temp_C[i], f.wear_mm[i]);
  }
  fmt::print(
      "  smooth-model effect on the temperatures (exact replay): tread {:.2f} K, disc {:.2f} "
      "K\n",
      s.run.max_tread_difference_K, s.run.max_disc_difference_K);
}

void WriteRunCsv(const fs::path& path, const Solved& s, const track::Track& track,
                 const vehicle::Car& car) {
  const sim::ColumnSet columns = ocp::OptimalLapColumns(s.run, track);
  WriteCsv(path,
           {{"source", fmt::format("hotlap {} optimal lap", HOTLAP_VERSION)},
            {"track", track.name()},
            {"car", car.path.string()},
            {"front_disc_limit_C", s.limit_C ? fmt::format("{:g}", *s.limit_C) : "none"},
            {"status", s.run.solution.solve.message}},
           columns.names, columns.values);
}

}  // namespace

void AddOptimalOptions(CLI::App* sub, OptimalArgs& a) {
  sub->add_option("--track", a.track, "Built-in track name or a .yaml/.csv/.xml file")
      ->capture_default_str();
  sub->add_option("--car", a.car, "Built-in car name or path to a car.yaml")->capture_default_str();
  sub->add_option("--out", a.out, "Output folder")->required();
  sub->add_option("--json", a.json, "Write the summary as JSON (docs/json-output.md)");
  a.stock_car_only.push_back(
      sub->add_option("--step-m", a.step_m, "Mesh spacing along the centre line, m")
          ->capture_default_str()
          ->check(CLI::Range(0.5, 50.0)));
  a.stock_car_only.push_back(
      sub->add_option("--thermal-start", a.thermal_start,
                      "Thermal states at the start: racing (QSS laps until no carcass rises over "
                      "15 degC a lap), "
                      "warm (after one QSS out-lap), car (the car file's initial_state) or "
                      "periodic (temperatures end where they start)")
          ->capture_default_str()
          ->check(CLI::IsMember({"racing", "warm", "car", "periodic"})));
  a.stock_car_only.push_back(
      sub->add_option("--ambient-temp-C", a.ambient_C, "Air temperature")->capture_default_str());
  a.stock_car_only.push_back(
      sub->add_option("--track-temp-C", a.track_C, "Track surface temperature")
          ->capture_default_str());
  sub->add_option("--max-iterations", a.max_iterations, "Ipopt's iteration limit")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  a.stock_car_only.push_back(
      sub->add_flag("--mesh-check", a.mesh_check,
                    "Solve again on a mesh of half the spacing and report the lap time's change"));
  sub->add_flag("--ipopt-output", a.ipopt_output, "Print Ipopt's own iteration log");
  sub->add_option("--ipopt-option", a.ipopt_options,
                  "An Ipopt option as NAME=VALUE (repeatable), e.g. mumps_pivot_order=5")
      ->check([](const std::string& s) {
        const size_t eq = s.find('=');
        return eq == std::string::npos || eq == 0 || eq + 1 == s.size()
                   ? std::string("expected NAME=VALUE, got '" + s + "'")
                   : std::string();
      });
}

std::vector<std::pair<std::string, std::string>> IpoptOptionPairs(const OptimalArgs& a) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const std::string& kv : a.ipopt_options) {
    const size_t eq = kv.find('=');  // the option's check guarantees one
    out.emplace_back(kv.substr(0, eq), kv.substr(eq + 1));
  }
  return out;
}

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
  if (a.disc_limit_C && a.compare_disc_limit_C) {
    throw InputError("give either --disc-limit-C (one solve) or --compare-disc-limit-C (two)");
  }
  for (const auto& limit : {a.disc_limit_C, a.compare_disc_limit_C}) {
    if (limit && !(*limit > 0.0 && *limit < 1500.0)) {
      throw InputError(fmt::format("the disc limit {:g} degC must be in (0, 1500)", *limit));
    }
  }
  ocp::KeepSolverMemory();
  fmt::print("hotlap optimal lap: car '{}' on {} ({:.1f} m)\n", car.name, track.name(),
             track.length_m());
  std::vector<Solved> runs;
  if (a.compare_disc_limit_C) {
    runs.push_back(Solve(a, car, track, std::nullopt, a.step_m, "no limit"));
    // The limited lap from the free one (continuation): the same neighbourhood, fewer iterations.
    const ocp::SolveResult& free = runs[0].run.solution.solve;
    runs.push_back(Solve(a, car, track, a.compare_disc_limit_C, a.step_m,
                         fmt::format("discs <= {:g} degC", *a.compare_disc_limit_C),
                         free.ok() ? &free : nullptr));
    // The problem is not convex, so each solve finds a local optimum. The limited lap is a
    // feasible point of the free problem: if it is faster, the free solve stopped at a worse
    // local optimum, and is solved again from the limited lap (then the better of the two kept).
    const Solved& first = runs[0];
    const Solved& limited = runs[1];
    if (limited.run.solution.solve.ok() && limited.figures.lap_time_s < first.figures.lap_time_s) {
      fmt::print(
          "no limit: the limited lap is {:.1f} ms faster, so the free solve stopped at a "
          "local optimum; solving it again from the limited lap\n",
          1e3 * (first.figures.lap_time_s - limited.figures.lap_time_s));
      Solved again =
          Solve(a, car, track, std::nullopt, a.step_m, "no limit", &limited.run.solution.solve);
      if (again.run.solution.solve.ok() &&
          (!first.run.solution.solve.ok() || again.figures.lap_time_s < first.figures.lap_time_s)) {
        again.run.solution.solve.iterations += first.run.solution.solve.iterations;
        again.run.solution.solve.solve_seconds += first.run.solution.solve.solve_seconds;
        runs[0] = std::move(again);
      }
    }
  } else {
    runs.push_back(
        Solve(a, car, track, a.disc_limit_C, a.step_m,
              a.disc_limit_C ? fmt::format("discs <= {:g} degC", *a.disc_limit_C) : "optimal lap"));
  }
  std::optional<double> mesh_delta;
  if (a.mesh_check) {
    const Solved fine = Solve(a, car, track, runs.front().limit_C, 0.5 * a.step_m, "half mesh");
    mesh_delta = fine.figures.lap_time_s - runs.front().figures.lap_time_s;
  }
  for (const Solved& s : runs) {
    fmt::print("{}:\n", s.label);
    PrintRun(s);
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
    for (const Solved& s : runs) {
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
    for (const Solved& s : runs) {
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
  for (const Solved& s : runs) ok = ok && s.run.solution.solve.ok();
  if (!a.json.empty()) {
    nlohmann::json j;
    if (runs.size() == 2) {
      j = {{"command", "lap --method ocp"},
           {"unconstrained", RunJson(runs[0])},
           {"constrained", RunJson(runs[1])},
           {"delta_s", RoundSignificant(runs[1].figures.lap_time_s - runs[0].figures.lap_time_s)}};
      // The headline keys of the unconstrained run at the top level too.
      for (const char* k : {"lap_time_s", "solve_time_s", "ipopt_iterations", "status",
                            "max_front_disc_temp_C", "top_speed_mps"}) {
        j[k] = j["unconstrained"][k];
      }
    } else {
      j = RunJson(runs[0]);
      j["command"] = "optimise";
    }
    j["track"] = track.name();
    j["car"] = car.name;
    j["mesh_step_m"] = a.step_m;
    if (mesh_delta) j["mesh_check_delta_s"] = RoundSignificant(*mesh_delta);
    WriteJsonFile(a.json, j);
    fmt::print("wrote {}\n", a.json);
  }
  return ok ? 0 : 3;
}

}  // namespace hotlap::app
