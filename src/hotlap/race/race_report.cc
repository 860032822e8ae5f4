#include "hotlap/race/race_report.h"

#include <algorithm>
#include <vector>

#include <fmt/format.h>

#include "hotlap/common/corner.h"
#include "hotlap/race/plan_runs.h"
#include "hotlap/report/html_report.h"

namespace hotlap::race {

namespace {

// The lap number of each lap of a race, 1 to n.
std::vector<double> Laps(size_t n) {
  std::vector<double> laps(n);
  for (size_t i = 0; i < n; ++i) laps[i] = static_cast<double>(i + 1);
  return laps;
}

// The laps run on the current right-side tyres (`right`) or left-side ones at the end of each lap
// of a plan.
std::vector<double> SetAges(const RacePlan& plan, bool right = true) {
  std::vector<double> age;
  int a = 0;
  size_t next = 0;
  for (size_t lap = 1; lap <= plan.lap_time_s.size(); ++lap) {
    age.push_back(++a);
    if (next < plan.stops.size() && plan.stops[next].lap == static_cast<int>(lap)) {
      const Service s = plan.stops[next].service;
      if (s == Service::kFourTyresAndFuel || (right && s == Service::kRightTyresAndFuel)) a = 0;
      ++next;
    }
  }
  return age;
}

// Each tyre's wear and lap-mean tread temperature over the race on the optimal plan, from the
// fall-off's laps at the tyre's age.
void AddTyreCharts(report::HtmlReport& page, const RaceRun& run, const std::vector<double>& laps) {
  const std::vector<SetLap> states = PlanLapStates(run.plan, run.fall_off);
  if (states.empty()) return;
  report::LineChart wear{.title = "Each tyre's wear over the race, the optimal plan",
                         .x_axis = {.label = "lap", .integer_ticks = true},
                         .y_axis = {.label = "wear", .unit = "mm"},
                         .x_link = "lap",
                         .width = report::ChartWidth::kFullRow};
  report::LineChart tread{.title = "Each tyre's tread temperature (lap mean), the optimal plan",
                          .x_axis = {.label = "lap", .integer_ticks = true},
                          .y_axis = {.label = "tread", .unit = "\u00b0C"},
                          .x_link = "lap",
                          .width = report::ChartWidth::kFullRow};
  for (Corner c : kAllCorners) {
    const size_t k = CornerIndex(c);
    std::vector<double> w, t;
    for (const SetLap& s : states) {
      w.push_back(s.wear_mm[k]);
      t.push_back(s.tread_temp[k] - 273.15);
    }
    wear.series.push_back({.label = std::string(CornerName(c)), .x = laps, .y = w});
    tread.series.push_back({.label = std::string(CornerName(c)), .x = laps, .y = t});
  }
  page.AddLineChart(wear);
  page.AddLineChart(tread);
}

// The plans' table and the optimal plan's gain under cautions.
void AddPlans(report::HtmlReport& page, const RaceRun& run) {
  page.AddHeading("Plans");
  std::vector<std::vector<std::string>> rows;
  const auto row = [&](const RacePlan& p, const MonteCarloResult* mc) {
    std::string stops;
    for (const PitStop& s : p.stops) {
      stops += fmt::format("{}{} ", s.lap, ServiceMark(s.service));
    }
    rows.push_back({p.name, fmt::format("{:.3f}", p.race_time_s), std::to_string(p.stops.size()),
                    std::to_string(p.tyre_sets_used), stops,
                    mc ? fmt::format("{:.2f} \u00b1 {:.2f}", mc->mean_time_s, mc->standard_error_s)
                       : std::string("-")});
  };
  const auto mc_of = [&](size_t i) {
    return i < run.monte_carlo.size() ? &run.monte_carlo[i] : nullptr;
  };
  row(run.plan, mc_of(0));
  for (size_t i = 0; i < run.fixed.size(); ++i) row(run.fixed[i], mc_of(i + 1));
  page.AddTable(
      {.title = run.rules.right_side_stops
                    ? "The optimal plan and the fixed plans (stops after lap "
                      "N; f: fuel only, r: right-side tyres and fuel)"
                    : "The optimal plan and the fixed plans (stops after lap "
                      "N; f: fuel only)",
       .header = {"plan", "race time s", "stops", "sets", "stops after laps", "under cautions s"},
       .rows = rows});
  if (run.gain_under_cautions.races > 0) {
    page.AddText(fmt::format(
        "Under the same cautions the optimal plan gains {:.2f} \u00b1 {:.2f} s over the best fixed "
        "plan ({} races).",
        run.gain_under_cautions.mean_time_s, run.gain_under_cautions.standard_error_s,
        run.gain_under_cautions.races));
  }
}

// The policy: its expected time, its races and the caution chart.
void AddPolicy(report::HtmlReport& page, const RaceRun& run) {
  if (!run.policy) return;
  const PolicyRun& pr = *run.policy;
  page.AddHeading("The policy under cautions");
  std::string text = fmt::format(
      "A stochastic dynamic programme over the laps, with the set's age, the fuel, the sets "
      "used and the caution in its state, says at the end of every lap whether to pit: expected "
      "race time {:.2f} s.",
      pr.policy.expected_time_s);
  if (pr.monte_carlo.races > 0) {
    text += fmt::format(
        " In the plans' {} races it averages {:.2f} ± {:.2f} s with {:.1f} stops and gains "
        "{:.2f} ± {:.2f} s over the best plan ({}).",
        pr.monte_carlo.races, pr.monte_carlo.mean_time_s, pr.monte_carlo.standard_error_s,
        pr.stats.mean_stops, pr.gain_over_best_plan.mean_time_s,
        pr.gain_over_best_plan.standard_error_s, pr.best_plan);
  }
  page.AddText(text);
  std::vector<std::vector<std::string>> chart;
  for (size_t i = 0; i < pr.caution_laps.size(); ++i) {
    chart.push_back({std::to_string(pr.caution_laps[i]),
                     pr.four_tyres_from_age[i] < 0
                         ? std::string("stay out")
                         : fmt::format("{} laps or older", pr.four_tyres_from_age[i])});
  }
  page.AddTable({.title = "A caution out on lap N: four new tyres (and fuel) from a set of this "
                          "age, the fuel filled with the set",
                 .header = {"caution on lap", "pit for four tyres"},
                 .rows = chart});
}

// The fall-off with its heat-only and right-side curves, and the right-side check.
void AddFallOff(report::HtmlReport& page, const RaceRun& run) {
  std::vector<double> ages;
  for (size_t a = 0; a < run.fall_off.lap_time_s.size(); ++a)
    ages.push_back(static_cast<double>(a));
  report::LineChart fall_off{
      .title = "Lap time on a set (the out lap first), from the QSS laps",
      .x_axis = {.label = "laps on the set (the right-side tyres after a right-side stop)",
                 .integer_ticks = true},
      .y_axis = {.label = "lap time", .unit = "s"},
      .series = {{.label = "fall-off", .x = ages, .y = run.fall_off.lap_time_s}}};
  if (run.fall_off.heat_only_lap_time_s.size() == ages.size()) {
    fall_off.series.push_back({.label = "the heat alone (no grip lost to wear)",
                               .x = ages,
                               .y = run.fall_off.heat_only_lap_time_s});
  }
  for (size_t i = 0; i < run.fall_off.right_stop_after_laps.size(); ++i) {
    const int after = run.fall_off.right_stop_after_laps[i];
    std::vector<double> x;
    for (size_t k = 0; k < run.fall_off.right_stop_lap_time_s[i].size(); ++k)
      x.push_back(static_cast<double>(k));
    fall_off.series.push_back(
        {.label = fmt::format("new right-side tyres after {} laps on the set", after),
         .x = x,
         .y = run.fall_off.right_stop_lap_time_s[i],
         .style = report::LineStyle::kDashed});
  }
  page.AddLineChart(fall_off);
  if (run.side_check) {
    const SideStopCheck& c = *run.side_check;
    std::vector<double> after;
    for (int k = 0; k < c.after; ++k) after.push_back(static_cast<double>(k));
    page.AddLineChart(
        {.title = fmt::format("A right-side stop after lap {}, driven, against the two-age lap "
                              "times (largest difference {:.3f} s)",
                              c.before, c.max_abs_difference_s),
         .x_axis = {.label = "laps on the new right-side tyres", .integer_ticks = true},
         .y_axis = {.label = "lap time", .unit = "s"},
         .series = {{.label = "driven (QSS)", .x = after, .y = c.driven_s},
                    {.label = "fall-off, two ages",
                     .x = after,
                     .y = c.fall_off_s,
                     .style = report::LineStyle::kDashed}}});
  }
}

// Every plan's lap times and runs over the race, each tyre on the optimal plan.
void AddRaceCharts(report::HtmlReport& page, const RaceRun& run) {
  report::LineChart trace{.title = "Lap times over the race (stops not included)",
                          .x_axis = {.label = "lap", .integer_ticks = true},
                          .y_axis = {.label = "lap time", .unit = "s"},
                          .x_link = "lap",
                          .width = report::ChartWidth::kFullRow};
  report::LineChart runs{.title = "Laps on the set: the runs between four-tyre stops",
                         .x_axis = {.label = "lap", .integer_ticks = true},
                         .y_axis = {.label = "laps on the set", .integer_ticks = true},
                         .x_link = "lap",
                         .width = report::ChartWidth::kFullRow};
  const std::vector<double> laps = Laps(run.plan.lap_time_s.size());
  trace.series.push_back({.label = run.plan.name, .x = laps, .y = run.plan.lap_time_s});
  runs.series.push_back({.label = run.plan.name, .x = laps, .y = SetAges(run.plan)});
  if (run.rules.right_side_stops) {
    runs.title = "Laps on the right-side tyres (and, dotted, the optimal plan's left-side ones)";
    runs.series.push_back({.label = run.plan.name + ", left side",
                           .x = laps,
                           .y = SetAges(run.plan, false),
                           .style = report::LineStyle::kDotted});
  }
  for (const RacePlan& p : run.fixed) {
    trace.series.push_back(
        {.label = p.name, .x = laps, .y = p.lap_time_s, .style = report::LineStyle::kDashed});
    runs.series.push_back(
        {.label = p.name, .x = laps, .y = SetAges(p), .style = report::LineStyle::kDashed});
  }
  page.AddLineChart(trace);
  page.AddLineChart(runs);
  AddTyreCharts(page, run, laps);
}

// The simulated races' cautions.
void AddCautionHistogram(report::HtmlReport& page, const RaceRun& run) {
  if (run.monte_carlo.empty() || run.monte_carlo[0].caution_histogram.empty()) return;
  const MonteCarloResult& mc = run.monte_carlo[0];
  std::vector<double> count, share;
  for (size_t k = 0; k < mc.caution_histogram.size(); ++k) {
    count.push_back(static_cast<double>(k));
    share.push_back(static_cast<double>(mc.caution_histogram[k]) / mc.races);
  }
  page.AddHeading("Cautions");
  page.AddLineChart({.title = fmt::format("Cautions in the {} simulated races", mc.races),
                     .x_axis = {.label = "cautions in a race", .integer_ticks = true},
                     .y_axis = {.label = "share of the races"},
                     .series = {{.label = "share", .x = count, .y = share}}});
}

}  // namespace

void WriteRaceReport(const std::filesystem::path& path, const RaceRun& run, const std::string& car,
                     const std::string& track) {
  report::HtmlReport page(fmt::format("hotlap race: {} on {}", car, track));
  page.AddMetadata("laps", std::to_string(run.rules.laps));
  page.AddMetadata("stages end", fmt::format("{}", fmt::join(run.rules.stage_ends, ", ")));
  page.AddMetadata("tyre sets", std::to_string(run.rules.tyre_sets));
  page.AddMetadata("fuel window", fmt::format("{} laps", run.rules.FuelWindow()));
  page.AddMetadata("version", HOTLAP_VERSION);
  AddPlans(page, run);
  AddPolicy(page, run);
  page.AddHeading("Fall-off and the race");
  AddFallOff(page, run);
  AddRaceCharts(page, run);
  AddCautionHistogram(page, run);
  page.Write(path);
}

}  // namespace hotlap::race
