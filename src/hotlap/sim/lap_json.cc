#include "hotlap/sim/lap_json.h"

#include "hotlap/common/json_output.h"
#include "hotlap/common/units.h"

namespace hotlap::sim {

nlohmann::json LapCornerJson(const CornerLapMeans& m, const CornerEnergyAudit& audit,
                             const tyre::TyreThermalParams<double>& tyre) {
  const auto celsius = [](double k) { return RoundSignificant(KelvinToCelsius(k)); };
  nlohmann::json j = {{"mean_tread_temp_C", celsius(m.tread)},
                      {"mean_carcass_temp_C", celsius(m.carcass)},
                      {"mean_disc_temp_C", celsius(m.disc)}};
  if (m.gas > 0.0) {
    j["mean_gas_temp_C"] = celsius(m.gas);
    j["mean_rim_temp_C"] = celsius(m.rim);
    j["mean_pressure_kPa"] = RoundSignificant(1e-3 * m.pressure);
    j["peak_pressure_kPa"] = RoundSignificant(1e-3 * m.peak_pressure);
    j["cold_pressure_kPa"] = RoundSignificant(1e-3 * tyre.cold_pressure);
    j["mean_pressure_build_psi"] = RoundSignificant((m.pressure - tyre.cold_pressure) / kPsi);
  }
  if (m.disc_bulk > 0.0) j["mean_disc_bulk_temp_C"] = celsius(m.disc_bulk);
  if (m.rolling_radius > 0.0) j["rolling_radius_mm"] = RoundSignificant(1e3 * m.rolling_radius);
  j["energy_audit"] = AuditJson(audit);
  return j;
}

nlohmann::json StintJson(const StintSummary& stint, const track::Track& track,
                         const vehicle::Car& car, const std::string& out_csv,
                         const std::string& out_report) {
  nlohmann::json laps = nlohmann::json::array();
  for (const LapFigures& f : stint.laps) {
    nlohmann::json lap_corners;
    for (Corner c : kAllCorners) {
      const int k = CornerIndex(c);
      lap_corners[std::string(CornerName(c))] =
          LapCornerJson(f.means[k], f.audit[k], car.tyre(c).params);
    }
    // The rear stagger as crew chiefs give it: right rear's rollout over the left rear's, mm.
    const double stagger = 2.0 * kPi *
                           (f.means[CornerIndex(Corner::kRearRight)].rolling_radius -
                            f.means[CornerIndex(Corner::kRearLeft)].rolling_radius);
    laps.push_back({{"lap_time_s", RoundSignificant(f.lap_time_s)},
                    {"top_speed_mps", RoundSignificant(f.top_speed)},
                    {"min_speed_mps", RoundSignificant(f.min_speed)},
                    {"rear_stagger_mm", RoundSignificant(1e3 * stagger)},
                    {"corners", lap_corners}});
  }
  nlohmann::json braking = nlohmann::json::array();
  for (const BrakingZone& z : stint.braking_zones) {
    braking.push_back({{"lap", z.lap},
                       {"start_m", RoundSignificant(z.start_m)},
                       {"end_m", RoundSignificant(z.end_m)},
                       {"entry_speed_mps", RoundSignificant(z.entry_speed)},
                       {"exit_speed_mps", RoundSignificant(z.exit_speed)},
                       {"peak_decel_mps2", RoundSignificant(z.peak_decel)}});
  }
  nlohmann::json corners;
  for (Corner c : kAllCorners) {
    const StintCorner& s = stint.corners[CornerIndex(c)];
    corners[std::string(CornerName(c))] = {
        {"peak_tread_temp_C", RoundSignificant(KelvinToCelsius(s.peak_tread_temp))},
        {"peak_carcass_temp_C", RoundSignificant(KelvinToCelsius(s.peak_carcass_temp))},
        {"peak_disc_temp_C", RoundSignificant(KelvinToCelsius(s.peak_disc_temp))},
        {"peak_calliper_temp_C", RoundSignificant(KelvinToCelsius(s.peak_calliper_temp))},
        {"wear_per_lap_mm", RoundSignificant(s.wear_per_lap_mm)},
        {"wear_total_mm", RoundSignificant(s.wear_total_mm)},
    };
  }
  const LapFigures& last = stint.laps.back();
  return {{"command", "lap"},
          {"method", "qss"},
          {"track", track.name()},
          {"track_length_m", RoundSignificant(track.length_m())},
          {"car", car.name},
          {"overrides", vehicle::OverridesJson(car.overrides)},
          {"laps", laps},
          {"lap_time_s", RoundSignificant(last.lap_time_s)},
          {"top_speed_mps", RoundSignificant(last.top_speed)},
          {"min_speed_mps", RoundSignificant(last.min_speed)},
          {"braking_zones", braking},
          {"corners", corners},
          {"slip_points_not_reached", stint.slip_points_not_reached},
          {"out_csv", out_csv},
          {"out_report", out_report}};
}

}  // namespace hotlap::sim
