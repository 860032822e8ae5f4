#include "hotlap/runs/race_spot_checks.h"

#include <algorithm>
#include <chrono>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/json_output.h"
#include "hotlap/ocp/optimal_lap.h"
#include "hotlap/sim/replay.h"

namespace hotlap::runs {

namespace {

// The four corners' time-mean of a history member over a replay.
double CornerMean(const sim::ReplayResult& r, std::vector<double> sim::CornerHistory::*member) {
  double sum = 0.0;
  for (const sim::CornerHistory& h : r.corners)
    sum += sim::CalcHistoryStats(r.time, h.*member).mean;
  return sum / 4.0;
}

}  // namespace

std::vector<int> ParseSpotCheckAges(const std::string& text, int fall_off_laps,
                                    std::string_view option) {
  std::vector<int> ages;
  if (text.empty()) return ages;
  size_t at = 0;
  while (at <= text.size()) {
    const size_t comma = std::min(text.find(',', at), text.size());
    const std::string item = text.substr(at, comma - at);
    int age = -1;
    try {
      size_t used = 0;
      age = std::stoi(item, &used);
      if (used != item.size()) age = -1;
    } catch (const std::exception&) {
    }
    if (age < 0 || age >= fall_off_laps || (!ages.empty() && age <= ages.back())) {
      throw InputError(fmt::format(
          "{} '{}': ages (laps on the set) increasing, each in [0, {}] (the fall-off's laps)",
          option, text, fall_off_laps - 1));
    }
    ages.push_back(age);
    at = comma + 1;
  }
  return ages;
}

RaceSpotChecks RunRaceSpotChecks(const vehicle::Car& car, const track::Track& track,
                                 std::span<const sim::RoadPoint> road, const sim::QssOptions& qss,
                                 const race::FallOff& fall_off, const std::vector<int>& ages,
                                 double step_m,
                                 const std::function<void(const std::string&)>& progress) {
  const auto started = std::chrono::steady_clock::now();
  RaceSpotChecks out;
  out.step_m = step_m;
  if (ages.empty()) return out;
  if (ages.back() >= static_cast<int>(fall_off.lap_time_s.size())) {
    throw InputError(fmt::format("spot check at age {}: the fall-off has {} laps", ages.back(),
                                 fall_off.lap_time_s.size()));
  }
  // The states the fall-off's laps reach: the same QSS laps again, as far as the oldest age.
  sim::QssOptions laps = qss;
  laps.laps = ages.back() + 1;  // through the oldest age's own lap
  const sim::QssResult run = sim::RunQssLap(car, road, laps);
  ocp::OptimalLapOptions o;
  o.step_m = step_m;
  o.ambient_temp = qss.ambient_temp;
  o.track_temp = qss.track_temp;
  o.thermal_start = ocp::ThermalStart::kCar;  // the guess's lap; its start replaced below
  // The wear as states (its start is each age's), and each lap after the first started from the
  // last one's solution: the laps differ only in the state they start from.
  o.wear_in_programme = true;
  o.start_point_fallback = true;
  // A neighbouring age's lap is a close start: one that is not done in 150 iterations (the lap
  // cache's limit) is given up for the default start rather than run to 1000.
  o.start_point_max_iterations = 150;
  ocp::LapWarmUp warm = ocp::RunLapWarmUp(car, track, o);
  for (int age : ages) {
    if (progress) progress(fmt::format("the optimal lap at age {} (a {:g} m mesh)", age, step_m));
    warm.start = age == 0 ? qss.initial : sim::EndState(run.laps[age - 1].thermal);
    // From the last age's solution; should that fail, again from the guess
    // (OptimalLapOptions::start_point_fallback).
    const ocp::OptimalLapRun lap = ocp::RunOptimalLap(car, track, o, &warm);
    int failed_iterations = 0;
    for (const ocp::OptimalLapRun::FailedStart& f : lap.failed_starts)
      failed_iterations += f.iterations;
    if (lap.solution.solve.ok()) o.start_point = lap.solution.solve.x;
    const sim::ReplayResult& qss_lap = run.laps[std::min<size_t>(age, run.laps.size() - 1)].thermal;
    out.checks.push_back(
        {.age = age,
         .qss_lap_time_s = fall_off.lap_time_s[age],
         .optimal_lap_time_s = lap.solution.lap_time,
         .qss_tread_temp = CornerMean(qss_lap, &sim::CornerHistory::tread_temp),
         .optimal_tread_temp = CornerMean(lap.exact, &sim::CornerHistory::tread_temp),
         .qss_grip = CornerMean(qss_lap, &sim::CornerHistory::grip_factor),
         .optimal_grip = CornerMean(lap.exact, &sim::CornerHistory::grip_factor),
         .converged = lap.solution.solve.ok(),
         .iterations = failed_iterations + lap.coarse.iterations + lap.solution.solve.iterations});
  }
  out.qss_fall_off_s = out.checks.back().qss_lap_time_s - out.checks.front().qss_lap_time_s;
  out.optimal_fall_off_s =
      out.checks.back().optimal_lap_time_s - out.checks.front().optimal_lap_time_s;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return out;
}

nlohmann::json RaceSpotChecksJson(const RaceSpotChecks& c) {
  nlohmann::json checks = nlohmann::json::array();
  for (const RaceSpotCheck& s : c.checks) {
    checks.push_back(
        {{"age_laps", s.age},
         {"qss_lap_time_s", RoundSignificant(s.qss_lap_time_s)},
         {"optimal_lap_time_s", RoundSignificant(s.optimal_lap_time_s)},
         {"difference_s", RoundSignificant(s.qss_lap_time_s - s.optimal_lap_time_s)},
         {"qss_mean_tread_temp_C", RoundSignificant(s.qss_tread_temp - 273.15, 6)},
         {"optimal_mean_tread_temp_C", RoundSignificant(s.optimal_tread_temp - 273.15, 6)},
         {"qss_mean_grip_factor", RoundSignificant(s.qss_grip, 6)},
         {"optimal_mean_grip_factor", RoundSignificant(s.optimal_grip, 6)},
         {"converged", s.converged},
         {"iterations", s.iterations}});
  }
  return {{"step_m", c.step_m},
          {"checks", checks},
          {"qss_fall_off_s", RoundSignificant(c.qss_fall_off_s)},
          {"optimal_fall_off_s", RoundSignificant(c.optimal_fall_off_s)}};
}

std::string RaceSpotChecksText(const RaceSpotChecks& c) {
  if (c.checks.empty()) return "";
  std::string out = fmt::format(
      "optimal-lap spot checks (the minimum-time lap from the QSS laps' state at each age, {:g} m "
      "mesh; the four tyres' mean tread temperature and grip factor over each lap):\n"
      "    age       QSS   optimal  QSS - optimal   tread C QSS/opt    grip QSS/opt\n",
      c.step_m);
  for (const RaceSpotCheck& s : c.checks) {
    out += fmt::format(
        "  {:>5} {:>9.3f} {:>9.3f} {:>+14.3f}   {:>7.1f}/{:<7.1f}  {:.3f}/{:.3f}{}\n", s.age,
        s.qss_lap_time_s, s.optimal_lap_time_s, s.qss_lap_time_s - s.optimal_lap_time_s,
        s.qss_tread_temp - 273.15, s.optimal_tread_temp - 273.15, s.qss_grip, s.optimal_grip,
        s.converged ? "" : "  (not converged)");
  }
  if (c.checks.size() > 1) {
    out += fmt::format(
        "  from age {} to {}: the QSS laps fall off {:+.3f} s, the optimal laps {:+.3f} s\n",
        c.checks.front().age, c.checks.back().age, c.qss_fall_off_s, c.optimal_fall_off_s);
  }
  return out;
}

}  // namespace hotlap::runs
