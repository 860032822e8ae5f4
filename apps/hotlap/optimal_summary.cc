// What `hotlap optimise` and `hotlap lap --method ocp` print and write of a solved lap.

#include "optimal_summary.h"

#include <fmt/format.h>

#include "hotlap/common/csv.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/units.h"

namespace hotlap::app {

namespace fs = std::filesystem;

nlohmann::json RunJson(const ocp::SolvedLap& s, const std::string& thermal_start) {
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
  nlohmann::json start = {{"mode", thermal_start}, {"qss_laps", s.run.start_laps}};
  if (thermal_start == "racing") {
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
  return {
      {"lap_time_s", RoundSignificant(f.lap_time_s)},
      {"qss_lap_time_s", RoundSignificant(s.run.qss_lap_time)},
      {"qss_on_optimal_line_lap_time_s", RoundSignificant(s.run.qss_on_line_lap_time)},
      {"solve_time_s", RoundSignificant(r.solve_seconds)},
      {"ipopt_iterations", r.iterations},
      {"regularized_iterations", r.regularized_iterations},
      {"coarse_solve",
       s.run.coarse.iterations > 0
           ? nlohmann::json{{"ipopt_iterations", s.run.coarse.iterations},
                            {"regularized_iterations", s.run.coarse.regularized_iterations},
                            {"solve_time_s", RoundSignificant(s.run.coarse.solve_seconds)},
                            {"lap_time_s", RoundSignificant(s.run.coarse_lap_time)},
                            {"status", s.run.coarse.ok() ? "converged" : "failed"}}
           : nlohmann::json()},
      {"status", r.ok() ? "converged" : "failed"},
      {"message", r.message},
      {"front_disc_limit_C",
       s.front_disc_limit ? nlohmann::json(RoundSignificant(KelvinToCelsius(*s.front_disc_limit)))
                          : nlohmann::json()},
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

void PrintRun(const ocp::SolvedLap& s, const std::string& thermal_start) {
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
               thermal_start, s.run.start_laps, carcass, disc);
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

void WriteRunCsv(const fs::path& path, const ocp::SolvedLap& s, const track::Track& track,
                 const vehicle::Car& car) {
  const sim::ColumnSet columns = ocp::OptimalLapColumns(s.run, track);
  WriteCsv(
      path,
      {{"source", fmt::format("hotlap {} optimal lap", HOTLAP_VERSION)},
       {"track", track.name()},
       {"car", car.path.string()},
       {"front_disc_limit_C",
        s.front_disc_limit ? fmt::format("{:g}", KelvinToCelsius(*s.front_disc_limit)) : "none"},
       {"status", s.run.solution.solve.message}},
      columns.names, columns.values);
}

}  // namespace hotlap::app
