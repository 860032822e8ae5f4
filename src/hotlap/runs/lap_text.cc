#include "hotlap/runs/lap_text.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include <fmt/format.h>

#include "hotlap/common/units.h"
#include "hotlap/sim/lap_output.h"

namespace hotlap::runs {

namespace {

double Celsius(double kelvin) { return KelvinToCelsius(kelvin); }

// The last lap's means and energy audit per corner (docs/lap-simulation.md, "Heat over a run").
void AppendLastLapHeat(std::string& out, const sim::LapFigures& f, const vehicle::Car& car) {
  fmt::format_to(std::back_inserter(out), "last lap means and energy audit:\n");
  fmt::format_to(std::back_inserter(out),
                 "{:<6} {:>7} {:>9} {:>6} {:>6} {:>8} {:>9} {:>8} {:>8} {:>7} {:>9} {:>9}\n",
                 "corner", "tread C", "carcass C", "gas C", "rim C", "hot kPa", "build psi",
                 "bulk C", "work kW", "heat kW", "heat/work", "closure");
  for (Corner c : kAllCorners) {
    const int k = CornerIndex(c);
    const sim::CornerLapMeans& m = f.means[k];
    const sim::CornerEnergyAudit& a = f.audit[k];
    const double span = a.duration_s > 0.0 ? a.duration_s : 1.0;
    const auto opt = [](bool has, double v, const char* fmt_spec) {
      return has ? fmt::format(fmt::runtime(fmt_spec), v) : std::string("-");
    };
    const bool gas = m.gas > 0.0;
    fmt::format_to(
        std::back_inserter(out),
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

}  // namespace

std::string LapRunHeader(const vehicle::Car& car, const track::Track& track,
                         const LapRunOptions& options, const LapPlan& plan) {
  const std::vector<sim::RoadPoint>& road = plan.road;
  return fmt::format(
      "hotlap lap: car '{}' on {} ({:.1f} m; {} line, {:.1f} m, {} points), {} lap{}, "
      "quasi-steady-state\n",
      car.name, track.name(), track.length_m(), options.line,
      road.size() * (road[1].distance - road[0].distance), road.size(), options.laps,
      options.laps > 1 ? "s" : "");
}

std::string LapRunText(const LapRun& run, const vehicle::Car& car, int laps) {
  const sim::StintSummary& stint = run.stint;
  std::string out;
  auto it = std::back_inserter(out);
  fmt::format_to(it, "{:>4} {:>9} {:>9} {:>9}\n", "lap", "time s", "top m/s", "min m/s");
  for (size_t l = 0; l < stint.laps.size(); ++l) {
    const sim::LapFigures& f = stint.laps[l];
    fmt::format_to(it, "{:>4} {:>9.3f} {:>9.2f} {:>9.2f}\n", l + 1, f.lap_time_s, f.top_speed,
                   f.min_speed);
  }
  fmt::format_to(it, "braking zones{}:\n", laps > 1 ? " (last lap)" : "");
  for (const sim::BrakingZone& z : stint.braking_zones) {
    if (z.lap != laps) continue;
    fmt::format_to(it,
                   "  {:6.0f} m to {:6.0f} m: {:.1f} -> {:.1f} m/s, peak {:.2f} m/s^2, {:.2f} s\n",
                   z.start_m, z.end_m, z.entry_speed, z.exit_speed, z.peak_decel, z.duration_s);
  }
  fmt::format_to(it, "{:<6} {:>10} {:>11} {:>9} {:>12} {:>12}\n", "corner", "tread pk C",
                 "carcass pk C", "disc pk C", "calliper pk C", "wear mm/lap");
  for (Corner c : kAllCorners) {
    const sim::StintCorner& s = stint.corners[CornerIndex(c)];
    fmt::format_to(it, "{:<6} {:>10.1f} {:>11.1f} {:>9.1f} {:>12.1f} {:>12.5f}\n", CornerName(c),
                   Celsius(s.peak_tread_temp), Celsius(s.peak_carcass_temp),
                   Celsius(s.peak_disc_temp), Celsius(s.peak_calliper_temp), s.wear_per_lap_mm);
  }
  AppendLastLapHeat(out, stint.laps.back(), car);
  if (stint.slip_points_not_reached > 0) {
    fmt::format_to(
        it,
        "note: at {} samples a tyre could not make the force the speed profile gave it (largest "
        "shortfall {:.0f} N): the combined-slip envelope is inside the friction ellipse there\n",
        stint.slip_points_not_reached, stint.max_force_deficit);
  }
  return out;
}

}  // namespace hotlap::runs
