#include "hotlap/abs/fe_abs_report.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "hotlap/report/html_report.h"

namespace hotlap::sim {

namespace {

// The FE run's channels, sample by sample.
struct FeChannels {
  std::vector<double> t, torque, vx, omega_r, slip, fx, balance;
  std::vector<double> kinetic, internal, friction, external;
};

FeChannels FeChannelsOf(const std::vector<fe::HistoryRow>& history, double loaded_radius_m) {
  const size_t n = history.size();
  FeChannels ch;
  for (auto* v : {&ch.t, &ch.torque, &ch.vx, &ch.omega_r, &ch.slip, &ch.fx, &ch.balance,
                  &ch.kinetic, &ch.internal, &ch.friction, &ch.external}) {
    v->resize(n);
  }
  for (size_t k = 0; k < n; ++k) {
    const fe::HistoryRow& r = history[k];
    ch.t[k] = r.time_s;
    ch.torque[k] = r.brake_torque_Nm;
    ch.vx[k] = r.rim_vx_mps;
    ch.omega_r[k] = r.spin_rad_per_s * loaded_radius_m;
    ch.slip[k] = r.slip;
    ch.fx[k] = r.road_fx_N;
    ch.kinetic[k] = r.energies.kinetic;
    ch.internal[k] = r.energies.internal;
    ch.friction[k] = r.energies.friction;
    ch.external[k] = r.energies.external_work;
    ch.balance[k] = r.energies.BalanceError();
  }
  return ch;
}

// A lumped run's channels on the FE histories' clock (its t = 0 is the braking step's start,
// t0 on the FE clock); empty without a lumped history.
struct LumpedChannels {
  std::vector<double> t, torque, vx, omega_r, slip, fx;
};

LumpedChannels LumpedChannelsOf(const FeAbsLumpedRun& lumped, double t0) {
  LumpedChannels l;
  if (lumped.history == nullptr) return l;
  const AbsHistory& h = *lumped.history;
  for (size_t k = 0; k < h.size(); ++k) {
    l.t.push_back(t0 + h.time[k]);
    l.torque.push_back(-h.brake_torque[k]);
    l.vx.push_back(h.speed[k]);
    l.omega_r.push_back(h.wheel_speed[k] * lumped.loaded_radius_m);
    l.slip.push_back(h.lambda[k]);
    l.fx.push_back(h.fx[k]);
  }
  return l;
}

// The event and its control cycles in words.
void AddEventText(report::HtmlReport& page, const FeChannels& ch, const CycleWindow& cycles) {
  page.AddText(fmt::format("{:.3f} s of braking from {:.3f} m/s to {:.3f} m/s; peak slip {:.3f}.",
                           ch.t.back() - ch.t.front(), ch.vx.front(), ch.vx.back(),
                           *std::max_element(ch.slip.begin(), ch.slip.end())));
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
}

// The FE run's cycles beside a lumped run's, in time from the braking step's start (t0).
void AddLumpedText(report::HtmlReport& page, const CycleWindow& cycles,
                   const FeAbsLumpedRun& lumped, double t0) {
  const auto opt = [](const std::optional<double>& v, double offset) {
    return v ? fmt::format("{:.3f}", *v + offset) : std::string("-");
  };
  const CycleWindow& c = lumped.cycles;
  page.AddText(fmt::format(
      "Beside the `hotlap abs` run of the same event ({}: rigid wheel, brush tyre), time from "
      "the braking step's start: first pressure release FE {} s, lumped {} s; second cycle FE "
      "{} s, lumped {} s; cycles FE {}, lumped {}; slip below {:.3f} after the first cycle FE "
      "{}, lumped {}; at most FE {}, lumped {}.",
      lumped.label, opt(cycles.first_cycle_start_s, -t0), opt(c.first_cycle_start_s, 0.0),
      opt(cycles.second_cycle_start_s, -t0), opt(c.second_cycle_start_s, 0.0), cycles.cycles,
      c.cycles, kPaperSlipLimit, opt(cycles.fraction_time_lambda_below_0_135, 0.0),
      opt(c.fraction_time_lambda_below_0_135, 0.0), opt(cycles.max_lambda_after_first_cycle, 0.0),
      opt(c.max_lambda_after_first_cycle, 0.0)));
}

// 002's Figures 8 to 11, with the lumped runs dotted.
void AddBrakingCharts(report::HtmlReport& page, const FeChannels& ch,
                      const std::vector<FeAbsLumpedRun>& lumped) {
  const std::vector<double>& t = ch.t;
  std::vector<LumpedChannels> ls;
  for (const FeAbsLumpedRun& run : lumped) ls.push_back(LumpedChannelsOf(run, t.front()));
  const auto add_lumped = [&](report::LineChart& chart, const std::string& what,
                              std::vector<double> LumpedChannels::*channel) {
    static const char* kColours[] = {"#9c755f", "#b07aa1", "#76b7b2"};
    for (size_t k = 0; k < ls.size(); ++k) {
      if (ls[k].t.empty()) continue;
      chart.series.push_back({.label = fmt::format("{} ({})", what, lumped[k].label),
                              .x = ls[k].t,
                              .y = ls[k].*channel,
                              .colour = kColours[k % 3],
                              .style = report::LineStyle::kDotted});
    }
  };
  page.AddHeading("Braking event (002 Figures 8 to 11)");
  report::LineChart fig8 = report::TimeChart("Brake torque (cf. 002 Fig. 8)", "torque", "N m");
  fig8.series.push_back({.label = "ABS brake torque", .x = t, .y = ch.torque});
  add_lumped(fig8, "torque", &LumpedChannels::torque);
  page.AddLineChart(fig8);

  report::LineChart fig9 =
      report::TimeChart("Forward and circumferential speeds (cf. 002 Fig. 9)", "speed", "m/s");
  fig9.series.push_back({.label = "Vx (rim)", .x = t, .y = ch.vx});
  fig9.series.push_back(
      {.label = "omega R_l", .x = t, .y = ch.omega_r, .style = report::LineStyle::kDashed});
  add_lumped(fig9, "Vx", &LumpedChannels::vx);
  add_lumped(fig9, "omega R_l", &LumpedChannels::omega_r);
  page.AddLineChart(fig9);

  report::LineChart fig10 = report::TimeChart("Slip ratio (cf. 002 Fig. 10)", "slip", "");
  fig10.series.push_back({.label = "slip", .x = t, .y = ch.slip});
  add_lumped(fig10, "slip", &LumpedChannels::slip);
  fig10.series.push_back({.label = "0.135 (002 Fig. 10)",
                          .x = {t.front(), t.back()},
                          .y = {kPaperSlipLimit, kPaperSlipLimit},
                          .colour = "#e15759",
                          .style = report::LineStyle::kDashed});
  page.AddLineChart(fig10);

  report::LineChart fig11 =
      report::TimeChart("Road longitudinal force (cf. 002 Fig. 11)", "road force Fx", "N");
  fig11.series.push_back({.label = "road Fx on the tyre", .x = t, .y = ch.fx});
  add_lumped(fig11, "Fx", &LumpedChannels::fx);
  page.AddLineChart(fig11);
}

void AddEnergyCharts(report::HtmlReport& page, const FeChannels& ch) {
  const std::vector<double>& t = ch.t;
  page.AddHeading("Energies");
  report::LineChart energy = report::TimeChart("Energies of the braking step", "energy", "J");
  energy.series.push_back({.label = "kinetic", .x = t, .y = ch.kinetic});
  energy.series.push_back({.label = "internal (strain)", .x = t, .y = ch.internal});
  energy.series.push_back({.label = "friction dissipated", .x = t, .y = ch.friction});
  energy.series.push_back(
      {.label = "external work", .x = t, .y = ch.external, .style = report::LineStyle::kDashed});
  page.AddLineChart(energy);
  report::LineChart error = report::TimeChart("Energy balance error", "balance error", "J");
  error.series.push_back({.label = "balance error", .x = t, .y = ch.balance});
  page.AddLineChart(error);
}

}  // namespace

void WriteFeAbsReport(const std::filesystem::path& path, const std::vector<fe::HistoryRow>& history,
                      const CycleWindow& cycles, double loaded_radius_m,
                      const std::vector<std::pair<std::string, std::string>>& metadata,
                      const std::vector<FeAbsLumpedRun>& lumped) {
  if (history.empty()) throw std::invalid_argument("WriteFeAbsReport: empty history");
  const FeChannels ch = FeChannelsOf(history, loaded_radius_m);
  report::HtmlReport page("hotlap fe abs: finite-element tyre braking event");
  for (const auto& [key, value] : metadata) page.AddMetadata(key, value);
  AddEventText(page, ch, cycles);
  for (const FeAbsLumpedRun& run : lumped) {
    if (run.history != nullptr) AddLumpedText(page, cycles, run, ch.t.front());
  }
  AddBrakingCharts(page, ch, lumped);
  AddEnergyCharts(page, ch);
  page.Write(path);
}

}  // namespace hotlap::sim
