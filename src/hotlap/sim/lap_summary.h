#pragma once
/// @file
/// What `hotlap lap --method qss` reports of a stint (docs/lap-simulation.md): each lap's figures,
/// the braking zones, per corner the peaks over the stint and the wear, and where the tyres fell
/// short of the speed profile's forces. The JSON summary is lap_json.h, the HTML page
/// lap_report.h.

#include <array>
#include <vector>

#include "hotlap/sim/lap_output.h"
#include "hotlap/sim/qss_lap.h"

namespace hotlap::sim {

/// One corner over the stint.
struct StintCorner {
  double peak_tread_temp = 0.0, peak_carcass_temp = 0.0;  ///< K
  double peak_disc_temp = 0.0, peak_calliper_temp = 0.0;  ///< K
  double wear_per_lap_mm = 0.0;                           ///< the laps' mean
  double wear_total_mm = 0.0;                             ///< at the end of the stint
};

struct StintSummary {
  std::vector<LapFigures> laps;            ///< CalcLapFigures of each lap
  std::vector<BrakingZone> braking_zones;  ///< FindBrakingZones of every lap, in lap order
  std::array<StintCorner, 4> corners;      ///< fl fr rl rr
  int slip_points_not_reached = 0;         ///< summed over the laps
  double max_force_deficit = 0.0;          ///< N, the largest of the laps'
};

/// The stint's summary. `result` must hold at least one lap.
StintSummary SummarizeStint(const QssResult& result);

}  // namespace hotlap::sim
