#include "hotlap/ocp/optimal_run_text.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include <fmt/format.h>

#include "hotlap/common/units.h"

namespace hotlap::ocp {

std::string OptionalText(const std::optional<double>& v, const char* format) {
  return v ? fmt::format(fmt::runtime(format), *v) : std::string("-");
}

std::string SolvedLapText(const SolvedLap& s, const std::string& thermal_start) {
  std::string text;
  const auto out = std::back_inserter(text);
  const OptimalLapFigures& f = s.figures;
  fmt::format_to(
      out,
      "  lap {:.3f} s, top speed {:.2f} m/s, slowest {:.2f} m/s, front discs peak {:.1f} "
      "degC\n",
      f.lap_time_s, f.top_speed_mps, f.min_speed_mps, f.max_front_disc_temp_C);
  if (!s.warm_start_from.empty()) {
    fmt::format_to(out, "  from the cached lap '{}' (distance {:.3g})\n", s.warm_start_from,
                   s.warm_start_distance);
  }
  for (const OptimalLapRun::FailedStart& failed : s.run.failed_starts) {
    fmt::format_to(
        out, "  from {}: stopped after {} iterations ({}); solved again from the next start\n",
        failed.from, failed.iterations, failed.message);
  }
  {
    const LapSolution& sol = s.run.solution;
    std::string carcass, disc;
    for (int i = 0; i < 4 && !sol.corners[i].carcass_temp.empty(); ++i) {
      carcass +=
          fmt::format("{}{:.0f}", i ? "/" : "", KelvinToCelsius(sol.corners[i].carcass_temp[0]));
      disc += fmt::format("{}{:.0f}", i ? "/" : "", KelvinToCelsius(sol.corners[i].disc_temp[0]));
    }
    fmt::format_to(out,
                   "  thermal start {} ({} QSS laps): carcass fl/fr/rl/rr {} degC, discs {} degC\n",
                   thermal_start, s.run.start_laps, carcass, disc);
  }
  fmt::format_to(out,
                 "  brake work {:.0f} kJ, of it against the engine (drive above 2%) {:.2f} kJ\n",
                 1e-3 * f.brake_energy_J, 1e-3 * f.brake_energy_under_drive_J);
  for (const TurnApproach& t : s.approaches) {
    fmt::format_to(out, "  {}: lift at {} m, brake at {} m, slowest {:.2f} m/s at {:.0f} m\n",
                   t.turn, OptionalText(t.lift_m, "{:.0f}"), OptionalText(t.brake_m, "{:.0f}"),
                   t.min_speed_mps, t.min_speed_at_m);
  }
  fmt::format_to(out, "  {:<6} {:>12} {:>12} {:>10}\n", "corner", "disc pk C", "tread pk C",
                 "wear mm");
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    fmt::format_to(out, "  {:<6} {:>12.1f} {:>12.1f} {:>10.5f}\n", CornerName(c),
                   f.peak_disc_temp_C[i], f.peak_tread_temp_C[i], f.wear_mm[i]);
  }
  if (!s.run.mesh_rounds.empty()) {
    // The adaptive mesh: its nodes, intervals and estimated error, and its solves.
    const std::vector<double>& d = s.run.solution.distance;
    double shortest = 1e300, longest = 0.0;
    for (size_t k = 1; k < d.size(); ++k) {
      shortest = std::min(shortest, d[k] - d[k - 1]);
      longest = std::max(longest, d[k] - d[k - 1]);
    }
    int iterations = 0;
    for (size_t i = 1; i < s.run.mesh_rounds.size(); ++i) {
      iterations += s.run.mesh_rounds[i].iterations;
    }
    fmt::format_to(out,
                   "  adaptive mesh: {} nodes, intervals {:.2f} to {:.1f} m, estimated mesh error "
                   "{:+.3f} ms (sum of |e| {:.3f} ms), {} refinement solves, {} iterations\n",
                   s.run.solution.layout.nodes, shortest, longest,
                   1e3 * s.run.mesh_error.lap_time_error_s, 1e3 * s.run.mesh_error.abs_error_s,
                   s.run.mesh_rounds.size() - 1, iterations);
  }
  fmt::format_to(
      out,
      "  smooth-model effect on the temperatures (exact replay): tread {:.2f} K, disc {:.2f} "
      "K\n",
      s.run.max_tread_difference_K, s.run.max_disc_difference_K);
  if (!s.run.exact.audits.empty()) {
    // Each tyre's heat over the car's work on it, and the worst balance of the lap.
    std::string ratios;
    double worst = 0.0;
    for (const sim::CornerEnergyAudit& a : s.run.exact.audits[0]) {
      ratios += fmt::format("{}{:.2f}", ratios.empty() ? "" : "/", a.HeatOverWork());
      for (double closure : {a.TyreClosure(), a.RimClosure(), a.BrakeClosure()}) {
        worst = std::max(worst, std::abs(closure));
      }
    }
    fmt::format_to(out,
                   "  energy audit (exact replay): tyre heat / work fl/fr/rl/rr {}, balances close "
                   "within {:.1e}\n",
                   ratios, worst);
  }
  if (s.run.solution.frozen_wear_grip_difference > 0.0) {
    fmt::format_to(out, "  frozen wear's effect on the grip factor h(wear): {:.1e}\n",
                   s.run.solution.frozen_wear_grip_difference);
  }
  return text;
}

std::string DiscLimitCostText(const SolvedLap& free, const SolvedLap& limited) {
  std::string text;
  const auto out = std::back_inserter(text);
  const double delta = limited.figures.lap_time_s - free.figures.lap_time_s;
  fmt::format_to(out, "the {} limit costs {:.3f} s ({:.0f} ms); top speed {:.2f} -> {:.2f} m/s\n",
                 limited.label, delta, 1e3 * delta, free.figures.top_speed_mps,
                 limited.figures.top_speed_mps);
  for (size_t t = 0; t < free.approaches.size() && t < limited.approaches.size(); ++t) {
    const TurnApproach& x = free.approaches[t];
    const TurnApproach& y = limited.approaches[t];
    fmt::format_to(out, "  {}: lift {} -> {} m, brake {} -> {} m\n", x.turn,
                   OptionalText(x.lift_m, "{:.0f}"), OptionalText(y.lift_m, "{:.0f}"),
                   OptionalText(x.brake_m, "{:.0f}"), OptionalText(y.brake_m, "{:.0f}"));
  }
  return text + LimitCostSensitivitiesText(free, limited);
}

std::vector<const LapSensitivity*> RankedSensitivities(const SolvedLap& lap) {
  std::vector<const LapSensitivity*> ranked;
  for (const LapSensitivity& s : lap.sensitivities) ranked.push_back(&s);
  std::stable_sort(ranked.begin(), ranked.end(), [](const auto* a, const auto* b) {
    return std::abs(a->typical_effect_s()) > std::abs(b->typical_effect_s());
  });
  return ranked;
}

std::string SensitivitiesText(const SolvedLap& lap) {
  if (lap.sensitivities.empty()) return "";
  std::string out =
      "  set-up sensitivities (the lap time's first-order change for each step, from the solved "
      "lap's multipliers):\n";
  for (const LapSensitivity* s : RankedSensitivities(lap)) {
    const std::string step = s->parameter.step_text + " " + s->parameter.label + ":";
    const bool unitless = s->parameter.unit == "1";
    out += fmt::format("    {:<48} {:+9.3f} ms   ({:+.4g} ms per {}, at {:.4g}{})\n", step,
                       1e3 * s->typical_effect_s(), 1e3 * s->d_lap_time_per_unit,
                       unitless ? "unit" : s->parameter.unit, s->value,
                       unitless ? "" : " " + s->parameter.unit);
  }
  return out;
}

std::vector<LimitCostSensitivity> LimitCostSensitivities(const SolvedLap& free,
                                                         const SolvedLap& limited) {
  std::vector<LimitCostSensitivity> both;
  for (const LapSensitivity& f : free.sensitivities) {
    for (const LapSensitivity& l : limited.sensitivities) {
      if (l.parameter.key == f.parameter.key) both.push_back({&f, &l});
    }
  }
  std::stable_sort(both.begin(), both.end(), [](const auto& a, const auto& b) {
    return std::abs(a.typical_cost_effect_s()) > std::abs(b.typical_cost_effect_s());
  });
  return both;
}

std::string LimitCostSensitivitiesText(const SolvedLap& free, const SolvedLap& limited) {
  const std::vector<LimitCostSensitivity> both = LimitCostSensitivities(free, limited);
  if (both.empty()) return "";
  std::string out = fmt::format(
      "  what each step does to the {} limit's cost (the limited lap's change minus the free "
      "lap's):\n",
      limited.label);
  for (const LimitCostSensitivity& s : both) {
    const SetupParameter& p = s.free->parameter;
    out += fmt::format("    {:<48} {:+9.3f} ms   (free {:+.3f}, limited {:+.3f} ms)\n",
                       p.step_text + " " + p.label + ":", 1e3 * s.typical_cost_effect_s(),
                       1e3 * s.free->typical_effect_s(), 1e3 * s.limited->typical_effect_s());
  }
  return out;
}

}  // namespace hotlap::ocp
