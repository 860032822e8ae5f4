#include "hotlap/sim/lap_output.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "hotlap/common/enum_names.h"
#include "hotlap/common/units.h"
#include "hotlap/track/track_point.h"

namespace hotlap::sim {

constexpr EnumNames<SpeedLimit, 5> kSpeedLimits{{{{SpeedLimit::kCornering, "cornering"},
                                                  {SpeedLimit::kTraction, "traction"},
                                                  {SpeedLimit::kPower, "power"},
                                                  {SpeedLimit::kBraking, "braking"},
                                                  {SpeedLimit::kPaceCar, "pace car"}}}};

const char* SpeedLimitName(SpeedLimit limit) { return kSpeedLimits.Name(limit); }

std::vector<BrakingZone> FindBrakingZones(const QssLap& lap, int lap_number, double min_decel) {
  std::vector<BrakingZone> zones;
  const size_t n = lap.speed.size();
  size_t i = 0;
  while (i < n) {
    if (!(lap.accel_long[i] < -min_decel)) {
      ++i;
      continue;
    }
    size_t j = i;
    // Extend while braking, bridging short gaps (< 10 m).
    while (true) {
      size_t k = j + 1;
      while (k < n && !(lap.accel_long[k] < -min_decel) &&
             lap.distance[k] - lap.distance[j] < 10.0) {
        ++k;
      }
      if (k < n && lap.accel_long[k] < -min_decel) {
        j = k;
      } else {
        break;
      }
    }
    BrakingZone z;
    z.lap = lap_number;
    z.start_m = lap.centre_distance[i] - lap.centre_distance[0];
    z.end_m = lap.centre_distance[j] - lap.centre_distance[0];
    z.entry_speed = lap.speed[i];
    z.exit_speed = lap.speed[j];
    z.duration_s = lap.time[j] - lap.time[i];
    for (size_t k = i; k <= j; ++k) z.peak_decel = std::max(z.peak_decel, -lap.accel_long[k]);
    zones.push_back(z);
    i = j + 1;
  }
  return zones;
}

LapFigures CalcLapFigures(const QssLap& lap) {
  LapFigures f;
  f.lap_time_s = lap.lap_time;
  f.top_speed = *std::max_element(lap.speed.begin(), lap.speed.end());
  f.min_speed = *std::min_element(lap.speed.begin(), lap.speed.end());
  for (int k = 0; k < 4; ++k) {
    const CornerHistory& h = lap.thermal.corners[k];
    const auto peak = [](const std::vector<double>& v) {
      return *std::max_element(v.begin(), v.end());
    };
    f.peak_tread_temp[k] = peak(h.tread_temp);
    f.peak_carcass_temp[k] = peak(h.carcass_temp);
    f.peak_disc_temp[k] = peak(h.disc_temp);
    f.peak_calliper_temp[k] = peak(h.calliper_temp);
    f.wear[k] = h.wear.back() - h.wear.front();
    CornerLapMeans& m = f.means[k];
    m.rolling_radius = lap.rolling_radius[k];
    const std::vector<double>& t = lap.thermal.time;
    m.tread = CalcHistoryStats(t, h.tread_temp).mean;
    m.carcass = CalcHistoryStats(t, h.carcass_temp).mean;
    m.disc = CalcHistoryStats(t, h.disc_temp).mean;
    if (!h.gas_temp.empty()) {
      m.gas = CalcHistoryStats(t, h.gas_temp).mean;
      m.rim = CalcHistoryStats(t, h.rim_temp).mean;
      const HistoryStats p = CalcHistoryStats(t, h.pressure);
      m.pressure = p.mean;
      m.peak_pressure = p.peak;
    }
    if (!h.disc_bulk_temp.empty()) m.disc_bulk = CalcHistoryStats(t, h.disc_bulk_temp).mean;
    if (!lap.thermal.audits.empty()) f.audit[k] = lap.thermal.audits.front()[k];
  }
  return f;
}

ColumnSet LapResultColumns(const QssResult& result, const track::Track& track, double ambient_temp,
                           double track_temp) {
  ColumnSet out;
  const auto column = [&](std::string name) {
    out.names.push_back(std::move(name));
    out.values.emplace_back();
    return out.names.size() - 1;
  };
  const size_t distance = column("distance_m"), path_col = column("path_distance_m"),
               offset_col = column("offset_m"), time = column("time_s"), lap_col = column("lap"),
               speed = column("speed_mps"), accel_long = column("accel_long_mps2"),
               accel_lat = column("accel_lat_mps2"), steer = column("steer_deg"), x = column("x_m"),
               y = column("y_m"), ambient = column("ambient_temp_C"),
               track_t = column("track_temp_C");
  struct CornerColumns {
    size_t speed, fx, fy, fz, alpha, kappa, tread, carcass, wear, grip, disc, calliper, power;
    std::vector<std::pair<size_t, std::vector<double> CornerHistory::*>> extra;  // the models' own
  };
  std::array<CornerColumns, 4> cc;
  for (Corner c : kAllCorners) {
    const std::string_view n = CornerName(c);
    CornerColumns& k = cc[CornerIndex(c)];
    k.speed = column(fmt::format("speed_{}_mps", n));
    k.fx = column(fmt::format("fx_{}_N", n));
    k.fy = column(fmt::format("fy_{}_N", n));
    k.fz = column(fmt::format("fz_{}_N", n));
    k.alpha = column(fmt::format("slip_angle_{}_deg", n));
    k.kappa = column(fmt::format("slip_ratio_{}", n));
    k.tread = column(fmt::format("tread_temp_{}_C", n));
    k.carcass = column(fmt::format("carcass_temp_{}_C", n));
    k.wear = column(fmt::format("wear_{}_mm", n));
    k.grip = column(fmt::format("grip_factor_{}", n));
    k.disc = column(fmt::format("disc_temp_{}_C", n));
    k.calliper = column(fmt::format("calliper_temp_{}_C", n));
    k.power = column(fmt::format("brake_power_{}_W", n));
    // The channels only the gas-and-rim tyre and the bulk disc have.
    const CornerHistory& first = result.laps.front().thermal.corners[CornerIndex(c)];
    for (const auto& [name, member] : ModelChannels()) {
      if (!(first.*member).empty())
        k.extra.emplace_back(column(fmt::format(fmt::runtime(name), n)), member);
    }
  }
  const auto push = [&](size_t col, double v) { out.values[col].push_back(v); };
  double distance0 = 0.0, path0 = 0.0, time0 = 0.0;
  for (size_t l = 0; l < result.laps.size(); ++l) {
    const QssLap& lap = result.laps[l];
    const size_t n = lap.speed.size() - (l + 1 < result.laps.size() ? 1 : 0);
    for (size_t i = 0; i < n; ++i) {
      push(distance, distance0 + lap.centre_distance[i] - lap.centre_distance[0]);
      push(path_col, path0 + lap.distance[i]);
      push(offset_col, lap.offset[i]);
      push(time, time0 + lap.time[i]);
      push(lap_col, static_cast<double>(l + 1));
      push(speed, lap.speed[i]);
      push(accel_long, lap.accel_long[i]);
      push(accel_lat, lap.accel_lat[i]);
      push(steer, RadToDeg(lap.steer[i]));
      const Eigen::Vector3d pos =
          track::PointAtOffset(track.At(lap.centre_distance[i]), lap.offset[i]);
      push(x, pos[0]);
      push(y, pos[1]);
      push(ambient, KelvinToCelsius(ambient_temp));
      push(track_t, KelvinToCelsius(track_temp));
      for (Corner c : kAllCorners) {
        const int k = CornerIndex(c);
        const CornerChannels& ch = lap.corners[k];
        const CornerHistory& h = lap.thermal.corners[k];
        push(cc[k].speed, ch.speed[i]);
        push(cc[k].fx, ch.fx[i]);
        push(cc[k].fy, ch.fy[i]);
        push(cc[k].fz, ch.fz[i]);
        push(cc[k].alpha, RadToDeg(ch.slip_angle[i]));
        push(cc[k].kappa, ch.slip_ratio[i]);
        push(cc[k].tread, KelvinToCelsius(h.tread_temp[i]));
        push(cc[k].carcass, KelvinToCelsius(h.carcass_temp[i]));
        push(cc[k].wear, h.wear[i]);
        push(cc[k].grip, h.grip_factor[i]);
        push(cc[k].disc, KelvinToCelsius(h.disc_temp[i]));
        push(cc[k].calliper, KelvinToCelsius(h.calliper_temp[i]));
        push(cc[k].power, h.brake_power[i]);
        for (const auto& [col, member] : cc[k].extra) {
          push(col, ModelChannelValue(member, (h.*member)[i]));
        }
      }
    }
    distance0 += lap.centre_distance.back() - lap.centre_distance.front();
    path0 += lap.distance.back();
    time0 += lap.time.back();
  }
  return out;
}

}  // namespace hotlap::sim
