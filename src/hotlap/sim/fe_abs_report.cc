#include "hotlap/sim/fe_abs_report.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "hotlap/report/html_report.h"

namespace hotlap::sim {

namespace {

report::LineChart TimeChart(const std::string& title, const std::string& label,
                            const std::string& unit) {
  return report::LineChart{.title = title,
                           .x_axis = {.label = "time", .unit = "s"},
                           .y_axis = {.label = label, .unit = unit},
                           .x_link = "time"};
}

}  // namespace

void WriteFeAbsReport(const std::filesystem::path& path, const std::vector<fe::HistoryRow>& history,
                      const CycleWindow& cycles, double loaded_radius_m,
                      const std::vector<std::pair<std::string, std::string>>& metadata,
                      const FeAbsLumpedRun* lumped) {
  if (history.empty()) throw std::invalid_argument("WriteFeAbsReport: empty history");
  const size_t n = history.size();
  std::vector<double> t(n), torque(n), vx(n), omega_r(n), slip(n), fx(n), balance(n);
  std::vector<double> kinetic(n), internal(n), friction(n), external(n);
  for (size_t k = 0; k < n; ++k) {
    const fe::HistoryRow& r = history[k];
    t[k] = r.time_s;
    torque[k] = r.brake_torque_Nm;
    vx[k] = r.rim_vx_mps;
    omega_r[k] = r.spin_rad_per_s * loaded_radius_m;
    slip[k] = r.slip;
    fx[k] = r.road_fx_N;
    kinetic[k] = r.energies.kinetic;
    internal[k] = r.energies.internal;
    friction[k] = r.energies.friction;
    external[k] = r.energies.external_work;
    balance[k] = r.energies.BalanceError();
  }
  report::HtmlReport page("hotlap fe abs: finite-element tyre braking event");
  for (const auto& [key, value] : metadata) page.AddMetadata(key, value);
  page.AddText(fmt::format("{:.3f} s of braking from {:.3f} m/s to {:.3f} m/s; peak slip {:.3f}.",
                           t.back() - t.front(), vx.front(), vx.back(),
                           *std::max_element(slip.begin(), slip.end())));
  if (cycles.second_cycle_start_s && cycles.fraction_time_lambda_below_0_135) {
    page.AddText(fmt::format(
        "{} control cycles ({:.2f} per second from the first). After the first cycle (it ends at "
        "{:.3f} s, where the controller begins the second) the slip stays below {:.3f} for "
        "{:.1f}% of the time, at most {:.3f}.",
        cycles.cycles, cycles.cycles_per_s, *cycles.second_cycle_start_s, kPaperSlipLimit,
        100.0 * *cycles.fraction_time_lambda_below_0_135,
        cycles.max_lambda_after_first_cycle.value_or(0.0)));
  } else {
    page.AddText(
        fmt::format("{} control cycle(s): no window after the first cycle.", cycles.cycles));
  }
  page.AddText(
      "The charts follow the FE/ABS paper's Figures 8 to 11 (the paper's Figure 11 draws the "
      "force and the slip together; here they are the two charts above it and beside it). "
      "docs/validation/fe-tyre.md says what was compared.");

  // The lumped run on the FE histories' clock (its t = 0 is the braking step's start).
  std::vector<double> lt, ltorque, lvx, lomega_r, lslip, lfx;
  if (lumped != nullptr && lumped->history != nullptr) {
    const AbsHistory& h = *lumped->history;
    for (size_t k = 0; k < h.size(); ++k) {
      lt.push_back(t.front() + h.time[k]);
      ltorque.push_back(-h.brake_torque[k]);
      lvx.push_back(h.speed[k]);
      lomega_r.push_back(h.wheel_speed[k] * lumped->loaded_radius_m);
      lslip.push_back(h.lambda[k]);
      lfx.push_back(h.fx[k]);
    }
    const auto opt = [](const std::optional<double>& v, double offset) {
      return v ? fmt::format("{:.3f}", *v + offset) : std::string("-");
    };
    const CycleWindow& c = lumped->cycles;
    const double t0 = t.front();
    page.AddText(fmt::format(
        "Beside the lumped `hotlap abs` run of the same event (same controller and hydraulics, "
        "rigid wheel, brush tyre), time from the braking step's start: first pressure release "
        "FE {} s, lumped {} s; second cycle FE {} s, lumped {} s; cycles FE {}, lumped {}; slip "
        "below {:.3f} after the first cycle FE {}, lumped {}; at most FE {}, lumped {}.",
        opt(cycles.first_cycle_start_s, -t0), opt(c.first_cycle_start_s, 0.0),
        opt(cycles.second_cycle_start_s, -t0), opt(c.second_cycle_start_s, 0.0), cycles.cycles,
        c.cycles, kPaperSlipLimit, opt(cycles.fraction_time_lambda_below_0_135, 0.0),
        opt(c.fraction_time_lambda_below_0_135, 0.0), opt(cycles.max_lambda_after_first_cycle, 0.0),
        opt(c.max_lambda_after_first_cycle, 0.0)));
  }
  const auto add_lumped = [&](report::LineChart& chart, const std::string& label,
                              const std::vector<double>& y) {
    if (lt.empty()) return;
    chart.series.push_back({.label = label,
                            .x = lt,
                            .y = y,
                            .colour = "#9c755f",
                            .style = report::LineStyle::kDotted});
  };

  page.AddHeading("Braking event (002 Figures 8 to 11)");
  report::LineChart fig8 = TimeChart("Brake torque (cf. 002 Fig. 8)", "torque", "N m");
  fig8.series.push_back({.label = "ABS brake torque", .x = t, .y = torque});
  add_lumped(fig8, "lumped hotlap abs", ltorque);
  page.AddLineChart(fig8);

  report::LineChart fig9 =
      TimeChart("Forward and circumferential speeds (cf. 002 Fig. 9)", "speed", "m/s");
  fig9.series.push_back({.label = "Vx (rim)", .x = t, .y = vx});
  fig9.series.push_back(
      {.label = "omega R_l", .x = t, .y = omega_r, .style = report::LineStyle::kDashed});
  add_lumped(fig9, "Vx (lumped)", lvx);
  add_lumped(fig9, "omega R_l (lumped)", lomega_r);
  page.AddLineChart(fig9);

  report::LineChart fig10 = TimeChart("Slip ratio (cf. 002 Fig. 10)", "slip", "");
  fig10.series.push_back({.label = "slip", .x = t, .y = slip});
  add_lumped(fig10, "slip (lumped)", lslip);
  fig10.series.push_back({.label = "0.135 (002 Fig. 10)",
                          .x = {t.front(), t.back()},
                          .y = {kPaperSlipLimit, kPaperSlipLimit},
                          .colour = "#e15759",
                          .style = report::LineStyle::kDashed});
  page.AddLineChart(fig10);

  report::LineChart fig11 =
      TimeChart("Road longitudinal force (cf. 002 Fig. 11)", "road force Fx", "N");
  fig11.series.push_back({.label = "road Fx on the tyre", .x = t, .y = fx});
  add_lumped(fig11, "Fx (lumped)", lfx);
  page.AddLineChart(fig11);

  page.AddHeading("Energies");
  report::LineChart energy = TimeChart("Energies of the braking step", "energy", "J");
  energy.series.push_back({.label = "kinetic", .x = t, .y = kinetic});
  energy.series.push_back({.label = "internal (strain)", .x = t, .y = internal});
  energy.series.push_back({.label = "friction dissipated", .x = t, .y = friction});
  energy.series.push_back(
      {.label = "external work", .x = t, .y = external, .style = report::LineStyle::kDashed});
  page.AddLineChart(energy);
  report::LineChart error = TimeChart("Energy balance error", "balance error", "J");
  error.series.push_back({.label = "balance error", .x = t, .y = balance});
  page.AddLineChart(error);
  page.Write(path);
}

}  // namespace hotlap::sim
