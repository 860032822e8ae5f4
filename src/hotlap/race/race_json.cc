#include "hotlap/race/race_json.h"

#include <algorithm>
#include <limits>

#include <fmt/format.h>

#include "hotlap/common/json_output.h"
#include "hotlap/race/plan_runs.h"

namespace hotlap::race {

namespace {

nlohmann::json Rounded(const std::vector<double>& v) {
  nlohmann::json out = nlohmann::json::array();
  for (double x : v) out.push_back(RoundSignificant(x));
  return out;
}

nlohmann::json RightStopsJson(const FallOff& f) {
  nlohmann::json out = nlohmann::json::array();
  for (size_t i = 0; i < f.right_stop_after_laps.size(); ++i) {
    out.push_back({{"after_laps", f.right_stop_after_laps[i]},
                   {"lap_time_s", Rounded(f.right_stop_lap_time_s[i])}});
  }
  return out;
}

nlohmann::json SideCheckJson(const std::optional<SideStopCheck>& c) {
  if (!c) return nullptr;
  return {{"laps_before", c->before},
          {"laps_after", c->after},
          {"driven_lap_time_s", Rounded(c->driven_s)},
          {"fall_off_lap_time_s", Rounded(c->fall_off_s)},
          {"max_abs_difference_s", RoundSignificant(c->max_abs_difference_s)},
          {"mean_difference_s", RoundSignificant(c->mean_difference_s)}};
}

double BestFixed(const std::vector<RacePlan>& fixed) {
  double best = std::numeric_limits<double>::infinity();
  for (const RacePlan& p : fixed) best = std::min(best, p.race_time_s);
  return best;
}

std::string PolicyText(const PolicyRun& pr) {
  std::string out = fmt::format(
      "policy (a stochastic programme with the caution in its state): expected {:.3f} s\n",
      pr.policy.expected_time_s);
  if (pr.monte_carlo.races > 0) {
    out += fmt::format(
        "  in the same races: {:.3f} s +- {:.3f}, {:.1f} stops a race (at most {} sets, at most {} "
        "green laps on one); it gains {:.3f} s +- {:.3f} over the best plan ({})\n",
        pr.monte_carlo.mean_time_s, pr.monte_carlo.standard_error_s, pr.stats.mean_stops,
        pr.stats.most_tyre_sets, pr.stats.longest_set_laps, pr.gain_over_best_plan.mean_time_s,
        pr.gain_over_best_plan.standard_error_s, pr.best_plan);
  }
  out += "  a caution out on lap N: four new tyres from a set of this age (fuel filled with it):\n";
  std::string laps = "    lap ", ages = "    age ";
  for (size_t i = 0; i < pr.caution_laps.size(); ++i) {
    laps += fmt::format("{:>5}", pr.caution_laps[i]);
    ages += pr.four_tyres_from_age[i] < 0 ? fmt::format("{:>5}", "-")
                                          : fmt::format("{:>5}", pr.four_tyres_from_age[i]);
  }
  return out + laps + "\n" + ages + "\n";
}

}  // namespace

namespace {

nlohmann::json Celsius(const std::array<double, 4>& kelvin) {
  nlohmann::json out = nlohmann::json::array();
  for (double t : kelvin) out.push_back(RoundSignificant(t - 273.15, 6));
  return out;
}

nlohmann::json Scaled(const std::array<double, 4>& v, double scale) {
  nlohmann::json out = nlohmann::json::array();
  for (double x : v) out.push_back(RoundSignificant(x * scale, 6));
  return out;
}

// The plan's runs between tyre changes, each corner's figures in fl, fr, rl, rr order.
nlohmann::json RunsJson(const RacePlan& plan, const FallOff& f) {
  nlohmann::json out = nlohmann::json::array();
  for (const PlanRun& r : PlanRuns(plan, PlanLapStates(plan, f))) {
    out.push_back({{"first_lap", r.first_lap},
                   {"last_lap", r.last_lap},
                   {"fitted", r.first_lap == 1 ? "the starting set" : ServiceName(r.fitted)},
                   {"wear_mm", Scaled(r.wear_mm, 1.0)},
                   {"peak_tread_temp_C", Celsius(r.peak_tread_temp)},
                   {"peak_carcass_temp_C", Celsius(r.peak_carcass_temp)},
                   {"peak_disc_temp_C", Celsius(r.peak_disc_temp)},
                   {"end_pressure_kPa", Scaled(r.end_pressure, 1e-3)}});
  }
  return out;
}

// The optimal plan's runs on the terminal: each tyre's wear at the stop and its hottest lap's
// mean tread temperature.
std::string RunsText(const RacePlan& plan, const FallOff& f) {
  const std::vector<PlanRun> runs = PlanRuns(plan, PlanLapStates(plan, f));
  if (runs.empty()) return "";
  std::string out =
      "the optimal plan's runs (fl fr rl rr: wear at the end, mm; the hottest lap's mean tread, "
      "degC):\n";
  for (const PlanRun& r : runs) {
    out += fmt::format(
        "  laps {:>3}-{:<3}  wear {:.2f} {:.2f} {:.2f} {:.2f}  tread {:.0f} {:.0f} {:.0f} "
        "{:.0f}\n",
        r.first_lap, r.last_lap, r.wear_mm[0], r.wear_mm[1], r.wear_mm[2], r.wear_mm[3],
        r.peak_tread_temp[0] - 273.15, r.peak_tread_temp[1] - 273.15, r.peak_tread_temp[2] - 273.15,
        r.peak_tread_temp[3] - 273.15);
  }
  return out;
}

}  // namespace

nlohmann::json PlanJson(const RacePlan& plan, const FallOff& fall_off) {
  nlohmann::json stops = nlohmann::json::array();
  for (const PitStop& s : plan.stops) {
    stops.push_back({{"lap", s.lap},
                     {"service", ServiceName(s.service)},
                     {"time_lost_s", RoundSignificant(s.time_lost_s)}});
  }
  return {{"name", plan.name},
          {"race_time_s", RoundSignificant(plan.race_time_s)},
          {"optimality_gap_s", RoundSignificant(plan.optimality_gap_s)},
          {"tyre_sets_used", plan.tyre_sets_used},
          {"stops", stops},
          {"runs", RunsJson(plan, fall_off)}};
}

nlohmann::json RaceJson(const RaceRun& run, const CautionModel& cautions) {
  const RaceRules& r = run.rules;
  const FallOff& f = run.fall_off;
  const RacePlan& plan = run.plan;
  const std::vector<RacePlan>& fixed = run.fixed;
  const std::vector<MonteCarloResult>& monte_carlo = run.monte_carlo;
  nlohmann::json fixed_json = nlohmann::json::array();
  for (const RacePlan& p : fixed) fixed_json.push_back(PlanJson(p, f));
  nlohmann::json lap_times = nlohmann::json::array();
  for (double t : f.lap_time_s) lap_times.push_back(RoundSignificant(t));
  nlohmann::json heat_only = nlohmann::json::array();
  for (double t : f.heat_only_lap_time_s) heat_only.push_back(RoundSignificant(t));
  const double best = BestFixed(fixed);
  nlohmann::json mc = nullptr;
  if (!monte_carlo.empty()) {
    nlohmann::json plans = nlohmann::json::array();
    for (size_t i = 0; i < monte_carlo.size(); ++i) {
      plans.push_back({{"name", i == 0 ? plan.name : fixed[i - 1].name},
                       {"mean_time_s", RoundSignificant(monte_carlo[i].mean_time_s)},
                       {"standard_error_s", RoundSignificant(monte_carlo[i].standard_error_s)}});
    }
    mc = {{"races", monte_carlo[0].races},
          {"caution_rate_per_lap", RoundSignificant(cautions.rate_per_lap)},
          {"caution_laps", cautions.length_laps},
          {"mean_cautions", RoundSignificant(monte_carlo[0].mean_cautions)},
          {"plans", plans},
          {"gain_over_best_fixed",
           {{"mean_s", RoundSignificant(run.gain_under_cautions.mean_time_s)},
            {"standard_error_s", RoundSignificant(run.gain_under_cautions.standard_error_s)}}}};
  }
  nlohmann::json policy = nullptr;
  if (run.policy) {
    const PolicyRun& pr = *run.policy;
    nlohmann::json chart = nlohmann::json::array();
    for (size_t i = 0; i < pr.caution_laps.size(); ++i) {
      chart.push_back(
          {{"caution_lap", pr.caution_laps[i]},
           {"four_tyres_from_age_laps", pr.four_tyres_from_age[i] < 0
                                            ? nlohmann::json(nullptr)
                                            : nlohmann::json(pr.four_tyres_from_age[i])}});
    }
    policy = {{"expected_time_s", RoundSignificant(pr.policy.expected_time_s)},
              {"fuel_units_per_lap", pr.policy.green_burn},
              {"max_tyre_age_laps", pr.policy.max_age},
              {"caution_chart", chart}};
    if (pr.monte_carlo.races > 0) {
      policy["monte_carlo"] = {
          {"races", pr.monte_carlo.races},
          {"mean_time_s", RoundSignificant(pr.monte_carlo.mean_time_s)},
          {"standard_error_s", RoundSignificant(pr.monte_carlo.standard_error_s)},
          {"mean_stops", RoundSignificant(pr.stats.mean_stops)},
          {"longest_set_laps", pr.stats.longest_set_laps},
          {"most_tyre_sets", pr.stats.most_tyre_sets}};
      policy["gain_over_best_plan"] = {
          {"plan", pr.best_plan},
          {"mean_s", RoundSignificant(pr.gain_over_best_plan.mean_time_s)},
          {"standard_error_s", RoundSignificant(pr.gain_over_best_plan.standard_error_s)}};
    }
  }
  return {
      {"command", "race"},
      {"rules",
       {{"laps", r.laps},
        {"stage_ends", r.stage_ends},
        {"fuel_capacity_kg", r.fuel_capacity_kg},
        {"fuel_per_lap_kg", r.fuel_per_lap_kg},
        {"fuel_window_laps", r.FuelWindow()},
        {"tyre_sets", r.tyre_sets},
        {"pit_loss_s", r.pit_loss_s},
        {"caution_pit_loss_s", r.caution_pit_loss_s},
        {"tyre_service_s", r.tyre_service_s},
        {"right_side_stops", r.right_side_stops},
        {"right_tyre_service_s", r.right_tyre_service_s},
        {"fuel_rate_kg_per_s", r.fuel_rate_kg_per_s}}},
      {"fall_off",
       {{"laps", f.lap_time_s.size()},
        {"lap_time_s", lap_times},
        {"spread_s", RoundSignificant(f.Spread())},
        {"heat_only_lap_time_s", heat_only},
        {"heat_only_spread_s", RoundSignificant(f.HeatOnlySpread())},
        {"right_side_stops", RightStopsJson(f)},
        {"from_cache", run.fall_off_from_cache},
        {"cache_file", run.fall_off_cache.empty() ? nlohmann::json(nullptr)
                                                  : nlohmann::json(run.fall_off_cache.string())},
        {"restart_penalty_s", RoundSignificant(f.restart_penalty_s)},
        {"fuel_s_per_kg", RoundSignificant(f.fuel_s_per_kg)},
        {"reference_fuel_kg", f.reference_fuel_kg}}},
      {"side_check", SideCheckJson(run.side_check)},
      {"plan", PlanJson(plan, f)},
      {"fixed_plans", fixed_json},
      {"gain_over_best_fixed_s", fixed.empty()
                                     ? nlohmann::json(nullptr)
                                     : nlohmann::json(RoundSignificant(best - plan.race_time_s))},
      {"monte_carlo", mc},
      {"policy", policy}};
}

std::string RaceText(const RaceRun& run) {
  const RaceRules& r = run.rules;
  const FallOff& f = run.fall_off;
  const RacePlan& plan = run.plan;
  const std::vector<RacePlan>& fixed = run.fixed;
  const std::vector<MonteCarloResult>& monte_carlo = run.monte_carlo;
  std::string out = fmt::format(
      "fall-off: {} laps on a set, fastest {:.3f} s, last {:.3f} s ({:+.3f} s), fuel {:.4f} s/kg\n",
      f.lap_time_s.size(), *std::min_element(f.lap_time_s.begin(), f.lap_time_s.end()),
      f.lap_time_s.back(), f.Spread(), f.fuel_s_per_kg);
  if (!f.heat_only_lap_time_s.empty()) {
    out += fmt::format(
        "  of it the heat alone (grip not falling with wear): {:+.3f} s; the wear: {:+.3f} s\n",
        f.HeatOnlySpread(), f.Spread() - f.HeatOnlySpread());
  }
  if (f.restart_penalty_s != 0.0) {
    out +=
        fmt::format("  a caution's cooled tyres and brakes cost the {} laps after it {:+.3f} s\n",
                    FallOff::kRestartLaps, f.restart_penalty_s);
  }
  if (run.side_check) {
    const SideStopCheck& c = *run.side_check;
    out += fmt::format(
        "  a right-side stop after lap {} driven: the {} laps after it {:.3f} s from the two-age "
        "lap times at most ({:+.3f} s on average)\n",
        c.before, c.after, c.max_abs_difference_s, c.mean_difference_s);
  }
  out += fmt::format("rules: {} laps, stages end at {}, {} tyre sets, a cell lasts {} laps{}\n",
                     r.laps, fmt::join(r.stage_ends, ", "), r.tyre_sets, r.FuelWindow(),
                     r.right_side_stops ? ", right-side stops allowed" : "");
  const auto plan_text = [&](const RacePlan& p) {
    std::string stops;
    for (const PitStop& s : p.stops) {
      stops += fmt::format(" {}{}", s.lap, ServiceMark(s.service));
    }
    return fmt::format("  {:<14} {:>10.3f} s  {:>2} stops, {:>2} sets; stops after laps{}\n",
                       p.name, p.race_time_s, p.stops.size(), p.tyre_sets_used, stops);
  };
  out += r.right_side_stops
             ? "plans (stops after lap N; f: fuel only, r: right-side tyres and "
               "fuel, else four tyres and fuel):\n"
             : "plans (stops after lap N; f: fuel only, else four tyres and fuel):\n";
  out += plan_text(plan);
  if (plan.optimality_gap_s > 0.0) {
    out += fmt::format(
        "    (the tyre sets bind: priced per set, the plan is within {:.3f} s of the least time)\n",
        plan.optimality_gap_s);
  }
  for (const RacePlan& p : fixed) out += plan_text(p);
  out += RunsText(plan, f);
  if (!fixed.empty()) {
    out += fmt::format("the optimal plan gains {:.3f} s over the best fixed plan\n",
                       BestFixed(fixed) - plan.race_time_s);
  }
  if (!monte_carlo.empty()) {
    out += fmt::format("under cautions ({} races, {:.1f} cautions a race on average):\n",
                       monte_carlo[0].races, monte_carlo[0].mean_cautions);
    for (size_t i = 0; i < monte_carlo.size(); ++i) {
      out += fmt::format("  {:<14} {:>10.3f} s +- {:.3f} (standard error)\n",
                         i == 0 ? plan.name : fixed[i - 1].name, monte_carlo[i].mean_time_s,
                         monte_carlo[i].standard_error_s);
    }
    if (run.gain_under_cautions.races > 0) {
      out += fmt::format(
          "the optimal plan gains {:.3f} s +- {:.3f} over the best fixed plan under the same "
          "cautions\n",
          run.gain_under_cautions.mean_time_s, run.gain_under_cautions.standard_error_s);
    }
  }
  if (run.policy) out += PolicyText(*run.policy);
  return out;
}

}  // namespace hotlap::race
