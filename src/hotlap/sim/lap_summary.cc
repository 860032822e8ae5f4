#include "hotlap/sim/lap_summary.h"

#include <algorithm>

namespace hotlap::sim {

StintSummary SummarizeStint(const QssResult& result) {
  StintSummary s;
  for (size_t l = 0; l < result.laps.size(); ++l) {
    s.laps.push_back(CalcLapFigures(result.laps[l]));
    const auto z = FindBrakingZones(result.laps[l], static_cast<int>(l) + 1);
    s.braking_zones.insert(s.braking_zones.end(), z.begin(), z.end());
  }
  for (const QssLap& lap : result.laps) {
    s.slip_points_not_reached += lap.slip_points_not_reached;
    s.max_force_deficit = std::max(s.max_force_deficit, lap.max_force_deficit);
  }
  for (int k = 0; k < 4; ++k) {
    StintCorner& c = s.corners[k];
    for (const LapFigures& f : s.laps) {
      c.peak_tread_temp = std::max(c.peak_tread_temp, f.peak_tread_temp[k]);
      c.peak_carcass_temp = std::max(c.peak_carcass_temp, f.peak_carcass_temp[k]);
      c.peak_disc_temp = std::max(c.peak_disc_temp, f.peak_disc_temp[k]);
      c.peak_calliper_temp = std::max(c.peak_calliper_temp, f.peak_calliper_temp[k]);
      c.wear_per_lap_mm += f.wear[k];
    }
    c.wear_per_lap_mm /= static_cast<double>(s.laps.size());
    c.wear_total_mm = result.laps.back().thermal.corners[k].wear.back();
  }
  return s;
}

}  // namespace hotlap::sim
