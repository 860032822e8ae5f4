#include "hotlap/sim/lap_json.h"

#include "hotlap/common/json_output.h"
#include "hotlap/common/units.h"

namespace hotlap::sim {

nlohmann::json StintJson(const StintSummary& stint, const track::Track& track,
                         const vehicle::Car& car, const std::string& out_csv,
                         const std::string& out_report) {
  nlohmann::json laps = nlohmann::json::array();
  for (const LapFigures& f : stint.laps) {
    laps.push_back({{"lap_time_s", RoundSignificant(f.lap_time_s)},
                    {"top_speed_mps", RoundSignificant(f.top_speed)},
                    {"min_speed_mps", RoundSignificant(f.min_speed)}});
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
