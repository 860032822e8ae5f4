#include "hotlap/sim/qss_lap.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/sim/hot_pressure.h"
#include "hotlap/sim/qss_profile.h"
#include "hotlap/sim/qss_slips.h"
#include "hotlap/vehicle/slip_inversion.h"

namespace hotlap::sim {

namespace {

using vehicle::VehicleParams;

// The cornering drag's fixed point is taken as settled when a profile moves the speeds by less
// than this on average, m/s (or the lap time as QssOptions::drag_settled_lap_time says). A few
// points where a braking point moves by a sample keep moving by 0.02-0.04 m/s while the rest
// settle.
constexpr double kSettledSpeed = 1e-3;

void CheckRoad(std::span<const RoadPoint> road) {
  if (road.size() < 16) {
    throw InputError(
        fmt::format("QSS lap: the road has {} points; at least 16 are needed", road.size()));
  }
  const double ds = road[1].distance - road[0].distance;
  if (!(ds > 0.0)) throw InputError("QSS lap: road distances must increase");
  for (size_t i = 0; i < road.size(); ++i) {
    const RoadPoint& p = road[i];
    if (!std::isfinite(p.distance) || !std::isfinite(p.curvature) || !std::isfinite(p.bank) ||
        !std::isfinite(p.grade)) {
      throw InputError(fmt::format("QSS lap: road point {} is not finite", i));
    }
    if (i > 0 && std::abs(p.distance - road[i - 1].distance - ds) > 1e-6 * ds + 1e-9) {
      throw InputError(fmt::format(
          "QSS lap: road points must be evenly spaced; point {} is {:g} m after the previous, "
          "expected {:g} m",
          i, p.distance - road[i - 1].distance, ds));
    }
  }
}

// Per-corner grip factors of the compound at the given states.
std::array<double, 4> GripOf(const vehicle::Car& car, const ReplayInitialState& state) {
  std::array<double, 4> g{};
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    g[i] = car.tyre(c).compound->GripFactor(state.tyres[i].tread_temp, state.tyres[i].wear);
  }
  return g;
}

struct Prepared {
  const vehicle::Car* car;
  const VehicleParams* params;
  QssVehicle qss;
  std::vector<vehicle::InvertibleTyre> tyres;

  Prepared(const vehicle::Car& c, const VehicleParams& p) : car(&c), params(&p), qss(p) {
    for (Corner corner : kAllCorners) tyres.emplace_back(p.corner(corner));
  }
};

// A lap of n points and its closing sample, every channel sized.
QssLap SizedLap(size_t n) {
  QssLap lap;
  lap.distance.resize(n + 1);
  lap.centre_distance.resize(n + 1);
  lap.offset.resize(n + 1);
  lap.time.resize(n + 1);
  lap.speed.resize(n + 1);
  lap.accel_long.resize(n + 1);
  lap.accel_lat.resize(n + 1);
  lap.steer.resize(n + 1);
  lap.limit.resize(n + 1);
  for (auto& ch : lap.corners) {
    for (auto* v :
         {&ch.speed, &ch.fx, &ch.fy, &ch.fz, &ch.slip_angle, &ch.slip_ratio, &ch.brake_fx}) {
      v->resize(n + 1);
    }
  }
  for (auto& t : lap.tread_temp_used) t.resize(n + 1);
  return lap;
}

// Close the lap at the start line (point n) with the first sample's channels.
void CloseLap(QssLap& lap, size_t n, double ds, double track_length, double time) {
  lap.distance[n] = n * ds;
  lap.centre_distance[n] = lap.centre_distance[0] + track_length;
  lap.offset[n] = lap.offset[0];
  lap.time[n] = time;
  lap.lap_time = time;
  lap.speed[n] = lap.speed[0];
  lap.accel_long[n] = lap.accel_long[0];
  lap.accel_lat[n] = lap.accel_lat[0];
  lap.steer[n] = lap.steer[0];
  lap.limit[n] = lap.limit[0];
  for (int k = 0; k < 4; ++k) {
    CornerChannels& ch = lap.corners[k];
    for (auto* v :
         {&ch.speed, &ch.fx, &ch.fy, &ch.fz, &ch.slip_angle, &ch.slip_ratio, &ch.brake_fx}) {
      (*v)[n] = (*v)[0];
    }
    lap.tread_temp_used[k][n] = lap.tread_temp_used[k][0];
  }
}

// Channels of one lap from its speed profile: forces, loads, slips (step 3 of qss_lap.h).
// `cornering_drag`: the profile's coefficients (CalcResistance), one per point; `solved_drag`
// gets those that the lap's own forces and slip angles give. `slips`: each point's slips, solved
// along the lap where it comes empty, else updated from what it holds (the last profile's solve,
// UpdatePointSlips), a point solved afresh kept there.
QssLap BuildLap(const Prepared& prep, std::span<const RoadPoint> road, double track_length,
                const SpeedProfile& profile, const std::array<std::vector<double>, 4>& grip,
                const std::array<std::vector<double>, 4>& tread_temp,
                std::span<const double> cornering_drag, std::span<const double> rolling,
                std::vector<double>* solved_drag, std::vector<PointSlips>* slips) {
  const bool update = slips->size() == road.size();
  slips->resize(road.size());
  const VehicleParams& p = *prep.params;
  const size_t n = road.size();
  const double ds = road[1].distance - road[0].distance;
  const double m = p.chassis.mass;
  QssLap lap = SizedLap(n);
  PointSlips last;  // the last point's, the next one's guess
  double time = 0.0;
  solved_drag->assign(n, 0.0);
  for (size_t i = 0; i < n; ++i) {
    const RoadPoint& point = road[i];
    const double v = profile.speed[i];
    const double v_prev = profile.speed[(i + n - 1) % n], v_next = profile.speed[(i + 1) % n];
    const double accel = (v_next * v_next - v_prev * v_prev) / (4.0 * ds);
    const std::array<double, 4> g = {grip[0][i], grip[1][i], grip[2][i], grip[3][i]};
    const double sum_fx = m * accel + CalcResistance(prep.qss, point, v, cornering_drag[i],
                                                     rolling.empty() ? -1.0 : rolling[i]);
    const ForceDemand demand = CalcForceDemand(prep.qss, point, v, sum_fx, g);
    const double kappa_g = point.curvature * std::cos(point.bank);
    const double yaw_rate = v * kappa_g;

    PointTargets targets;
    for (Corner c : kAllCorners) {
      const int k = CornerIndex(c);
      const double y = p.CornerPosition(c)[1];
      targets.conditions[k] = {std::max(demand.fz[k], 1.0), std::max(v - yaw_rate * y, 0.5),
                               tread_temp[k][i], g[k]};
      targets.fx[k] = demand.fx[k];
      targets.fy[k] = demand.fy[k];
    }
    const std::array<vehicle::TyreConditions, 4>& cond = targets.conditions;
    PointSlips& point_slips = (*slips)[i];
    if (update) {
      last = UpdatePointSlips(prep.tyres, targets, point_slips);
    } else {
      last = SolvePointSlips(prep.tyres, targets, last);
      point_slips = last;
    }
    const std::array<vehicle::WheelSlips, 4>& slips_now = last.wheels;
    lap.max_force_deficit = std::max(lap.max_force_deficit, last.force_deficit);
    if (!last.Reached()) ++lap.slip_points_not_reached;

    lap.distance[i] = point.distance - road[0].distance;
    lap.centre_distance[i] = point.centre_distance;
    lap.offset[i] = point.offset;
    lap.time[i] = time;
    lap.speed[i] = v;
    lap.accel_long[i] = accel;
    lap.accel_lat[i] = v * v * kappa_g;
    lap.limit[i] = profile.limit[i];
    // Steady-state kinematics: delta = L kappa + alpha_rear - alpha_front (ISO slip angles).
    const double alpha_front = 0.5 * (slips_now[0].slip_angle + slips_now[1].slip_angle);
    const double alpha_rear = 0.5 * (slips_now[2].slip_angle + slips_now[3].slip_angle);
    lap.steer[i] = p.chassis.wheelbase * kappa_g + alpha_rear - alpha_front;
    (*solved_drag)[i] = CalcCorneringDragCoefficient(
        {slips_now[0].fy, slips_now[1].fy, slips_now[2].fy, slips_now[3].fy},
        {slips_now[0].slip_angle, slips_now[1].slip_angle, slips_now[2].slip_angle,
         slips_now[3].slip_angle});
    for (Corner c : kAllCorners) {
      const int k = CornerIndex(c);
      CornerChannels& ch = lap.corners[k];
      ch.speed[i] = cond[k].vx;
      ch.fx[i] = slips_now[k].fx;
      ch.fy[i] = slips_now[k].fy;
      ch.fz[i] = demand.fz[k];
      ch.slip_angle[i] = slips_now[k].slip_angle;
      ch.slip_ratio[i] = slips_now[k].slip_ratio;
      // Brakes: each front wheel has its own; the rear wheels share one axle torque on the spool,
      // so each rear disc takes half the axle's braking (the tyres' split is the spool's).
      if (IsFront(c)) {
        ch.brake_fx[i] = std::min(demand.fx[k], 0.0);
      } else {
        const int l = CornerIndex(Corner::kRearLeft), r = CornerIndex(Corner::kRearRight);
        ch.brake_fx[i] = std::min(0.5 * (demand.fx[l] + demand.fx[r]), 0.0);
      }
      lap.tread_temp_used[k][i] = tread_temp[k][i];
    }
    time += 2.0 * ds / (v + v_next);
  }
  CloseLap(lap, n, ds, track_length, time);
  return lap;
}

// The lap resampled at about `step` m (at least as coarse as the road, at least 16 points),
// curvature, bank and grade interpolated linearly round the closed lap.
std::vector<RoadPoint> Coarsen(std::span<const RoadPoint> road, double step) {
  const size_t n = road.size();
  const double ds = road[1].distance - road[0].distance, length = n * ds;
  const size_t m =
      std::max<size_t>(16, std::min(n, static_cast<size_t>(std::round(length / step))));
  std::vector<RoadPoint> out(m);
  for (size_t j = 0; j < m; ++j) {
    const double s = length * static_cast<double>(j) / static_cast<double>(m);
    const double x = s / ds;
    const size_t i = std::min(static_cast<size_t>(x), n - 1);
    const double w = x - static_cast<double>(i);
    const RoadPoint& a = road[i];
    const RoadPoint& b = road[(i + 1) % n];
    out[j] = {road[0].distance + s,
              a.curvature + w * (b.curvature - a.curvature),
              a.bank + w * (b.bank - a.bank),
              a.grade + w * (b.grade - a.grade),
              a.centre_distance + w * (b.centre_distance - a.centre_distance),
              a.offset + w * (b.offset - a.offset)};
  }
  return out;
}

// Values at the points of `from` interpolated linearly (periodic) onto the points of `to`; both
// roads cover the same closed lap from the same start.
std::vector<double> InterpolatePeriodic(std::span<const RoadPoint> from,
                                        const std::vector<double>& values,
                                        std::span<const RoadPoint> to) {
  const size_t m = from.size();
  const double step = from[1].distance - from[0].distance;
  std::vector<double> out(to.size());
  for (size_t i = 0; i < to.size(); ++i) {
    const double x = (to[i].distance - to[0].distance) / step;
    const size_t j = std::min(static_cast<size_t>(x), m - 1);
    const double w = x - static_cast<double>(j);
    out[i] = values[j] + w * (values[(j + 1) % m] - values[j]);
  }
  return out;
}

}  // namespace

std::vector<int> ParseLapList(const std::string& text, int laps, std::string_view option) {
  std::vector<int> out;
  if (text.empty()) return out;
  std::stringstream items(text);
  std::string item;
  while (std::getline(items, item, ',')) {
    const size_t dash = item.find('-');
    int first = 0, last = 0;
    try {
      size_t used = 0;
      first = std::stoi(item.substr(0, dash), &used);
      if (used != (dash == std::string::npos ? item.size() : dash)) throw std::invalid_argument("");
      last = first;
      if (dash != std::string::npos) {
        last = std::stoi(item.substr(dash + 1), &used);
        if (used != item.size() - dash - 1) throw std::invalid_argument("");
      }
    } catch (const std::exception&) {
      throw InputError(
          fmt::format("{} '{}': '{}' is not a lap or a range such as 11-15", option, text, item));
    }
    if (first < 1 || last > laps || last < first || (!out.empty() && first - 1 <= out.back())) {
      throw InputError(fmt::format("{} '{}': '{}' must be increasing laps within 1 to {}", option,
                                   text, item, laps));
    }
    for (int l = first; l <= last; ++l) out.push_back(l - 1);
  }
  return out;
}

double CheckCautionSpeed(double kph, std::string_view option) {
  if (!(kph > 20.0 && kph <= 250.0)) {
    throw InputError(fmt::format("{} {:g} must be in (20, 250] km/h", option, kph));
  }
  return kph / 3.6;
}

namespace {

// What every pass of a QSS lap shares. `prep` follows the lap's set-up (the hot pressures).
struct PassContext {
  const vehicle::Car& car;
  const Prepared& prep;
  const QssOptions& options;
  double track_length;
  bool own_rolling;
};

// One pass: speed profile, forces and slips, thermal replay from `from`. The profile and the
// forces are solved again with the cornering drag the last forces and slip angles gave, each
// profile's searches from the last one's and its slips updated from the last solve's, until
// the drag is settled (QssOptions::drag_settled_lap_time): from a lap's own first guess one or
// two profiles more, each moving the lap by about a sixth of the last one's move.
QssLap RunPass(const PassContext& x, std::span<const RoadPoint> r,
               const std::array<std::vector<double>, 4>& g,
               const std::array<std::vector<double>, 4>& t, const ReplayInitialState& from,
               std::vector<double>& drag, std::span<const double> rolling, int max_passes) {
  const Prepared& prep = x.prep;
  if (max_passes <= 1) std::fill(drag.begin(), drag.end(), 0.0);
  SpeedProfile profile = CalcSpeedProfile(prep.qss, r, g, drag, rolling);
  std::vector<double> solved;
  std::vector<PointSlips> slips;
  QssLap lap = BuildLap(prep, r, x.track_length, profile, g, t, drag, rolling, &solved, &slips);
  double last_change = 0.0;  // of the lap time, s
  for (int pass = 1; pass < max_passes; ++pass) {
    drag = solved;
    SpeedProfile next = CalcSpeedProfile(prep.qss, r, g, drag, rolling, &profile);
    // The mean change: a few points where the limit switches (a braking point moving by a
    // point) keep moving by 0.02-0.04 m/s while the rest settle.
    double moved = 0.0;
    for (size_t i = 0; i < r.size(); ++i) moved += std::abs(next.speed[i] - profile.speed[i]);
    moved /= static_cast<double>(r.size());
    profile = std::move(next);
    const double last_time = lap.lap_time;
    lap = BuildLap(prep, r, x.track_length, profile, g, t, drag, rolling, &solved, &slips);
    // Settled, or near enough that the moves left (each this one's share of the last, summed)
    // come to less than half the tolerance.
    const double change = std::abs(lap.lap_time - last_time);
    const double share = last_change > 0.0 ? change / last_change : 1.0;
    const double left = share < 1.0 ? change * share / (1.0 - share) : change;
    const double tolerance = x.options.drag_settled_lap_time;
    if (moved < kSettledSpeed || change < tolerance || left < 0.5 * tolerance) break;
    last_change = change;
  }
  drag = std::move(solved);
  ReplayInputs inputs;
  inputs.time = lap.time;
  inputs.corners = lap.corners;
  inputs.ambient_temp.assign(r.size() + 1, x.options.ambient_temp);
  inputs.track_temp.assign(r.size() + 1, x.options.track_temp);
  lap.thermal = RunReplay(x.car, inputs, from, x.options.replay);
  return lap;
}

// The grip and tread temperature a lap left at each point drive the next pass; so do the
// tyres' rolling-resistance coefficients, weighted by their loads there.
void TakeThermal(const PassContext& x, const QssLap& lap, std::array<std::vector<double>, 4>& g,
                 std::array<std::vector<double>, 4>& t, std::vector<double>& rolling) {
  for (int k = 0; k < 4; ++k) {
    const CornerHistory& h = lap.thermal.corners[k];
    g[k].assign(h.grip_factor.begin(), h.grip_factor.end() - 1);
    t[k].assign(h.tread_temp.begin(), h.tread_temp.end() - 1);
  }
  if (!x.own_rolling) return;
  const size_t m = lap.speed.size() - 1;
  rolling.assign(m, 0.0);
  for (size_t i = 0; i < m; ++i) {
    double load = 0.0, weighted = 0.0;
    for (int k = 0; k < 4; ++k) {
      const CornerHistory& h = lap.thermal.corners[k];
      const double fz = std::max(lap.corners[k].fz[i], 0.0);
      const double c = h.rolling_resistance.empty() ? x.prep.qss.rolling_coefficient[k]
                                                    : h.rolling_resistance[i];
      load += fz;
      weighted += c * fz;
    }
    rolling[i] = load > 0.0 ? weighted / load : -1.0;
  }
}

// What a pass over the full road starts from: each corner's grip and tread temperature at each
// point, the cornering-drag coefficients of the last solution (CalcResistance: the next lap's
// first guess, so that it needs one or two profiles where the first needs three) and the
// rolling-resistance coefficients the last lap's tyres had, where a tyre's thermal model carries
// its own (the gas-and-rim tyre: the car pays for its hysteresis; empty: the car's force
// models', CalcResistance).
struct RoadGuess {
  std::array<std::vector<double>, 4> grip, tread;
  std::vector<double> drag;
  std::vector<double> rolling;
};

// Thermal coupling of the first lap: a first pass on a road of about 4 m spacing (the
// temperatures it gives vary over tens of metres) from the starting temperatures, its grip
// and tread temperatures interpolated onto the full road for the real pass.
void CoupleFirstLap(const PassContext& x, std::span<const RoadPoint> road,
                    const ReplayInitialState& state, RoadGuess& guess) {
  const std::vector<RoadPoint> coarse = Coarsen(road, 4.0);
  std::array<std::vector<double>, 4> g, t;
  for (int k = 0; k < 4; ++k) {
    g[k].assign(coarse.size(), guess.grip[k][0]);
    t[k].assign(coarse.size(), guess.tread[k][0]);
  }
  std::vector<double> coarse_drag(coarse.size(), 0.0);
  std::vector<double> coarse_rolling;
  // Two profiles here: this pass only sets the grip the real one starts from.
  const QssLap first =
      RunPass(x, coarse, g, t, state, coarse_drag, {}, std::min(x.options.max_drag_passes, 2));
  TakeThermal(x, first, g, t, coarse_rolling);
  for (int k = 0; k < 4; ++k) {
    guess.grip[k] = InterpolatePeriodic(coarse, g[k], road);
    guess.tread[k] = InterpolatePeriodic(coarse, t[k], road);
  }
  guess.drag = InterpolatePeriodic(coarse, coarse_drag, road);  // the full road's first guess
  if (x.own_rolling) guess.rolling = InterpolatePeriodic(coarse, coarse_rolling, road);
}

}  // namespace

QssResult RunQssLap(const vehicle::Car& car, std::span<const RoadPoint> road,
                    const QssOptions& options) {
  const VehicleParams& params = vehicle::RequireVehicle(car, "the QSS lap");
  CheckRoad(road);
  if (options.laps < 1) throw InputError("QSS lap: laps must be >= 1");
  const size_t n = road.size();
  Prepared prep(car, params);
  // Gas-and-rim tyres: each lap's force models at the hot pressures the last lap had, the first's
  // at its start's (sim/hot_pressure.h); `hot_car` holds the set-up `prep` points into.
  vehicle::Car hot_car;
  // The centre line's length closes centre_distance; a centre-line road is its own.
  const double track_length =
      options.track_length > 0.0 ? options.track_length : n * (road[1].distance - road[0].distance);

  ReplayInitialState state = options.initial;
  RoadGuess guess;
  {
    const std::array<double, 4> g0 = GripOf(car, state);
    for (int k = 0; k < 4; ++k) {
      guess.grip[k].assign(n, g0[k]);
      guess.tread[k].assign(n, state.tyres[k].tread_temp);
    }
  }
  guess.drag.assign(n, 0.0);
  bool own_rolling = false;
  for (Corner c : kAllCorners) own_rolling = own_rolling || car.tyre(c).params.HasGasAndRim();
  const PassContext x{car, prep, options, track_length, own_rolling};

  QssResult result;
  for (int lap_index = 0; lap_index < options.laps; ++lap_index) {
    if (own_rolling) {
      hot_car =
          WithHotPressures(car, lap_index == 0 ? HotPressuresAt(car, state, 50.0)
                                               : MeanHotPressures(car, result.laps.back().thermal));
      prep = Prepared(hot_car, *hot_car.vehicle);
    }
    prep.qss.speed_cap = options.SpeedCapOfLap(lap_index);
    if (lap_index == 0 && options.couple_first_lap) CoupleFirstLap(x, road, state, guess);
    QssLap lap = RunPass(x, road, guess.grip, guess.tread, state, guess.drag, guess.rolling,
                         options.max_drag_passes);
    TakeThermal(x, lap, guess.grip, guess.tread, guess.rolling);
    for (int k = 0; k < 4; ++k) {
      lap.rolling_radius[k] =
          (own_rolling ? hot_car.vehicle : car.vehicle)->corners[k].rolling_radius;
    }
    state = EndState(lap.thermal);
    result.laps.push_back(std::move(lap));
  }
  return result;
}

}  // namespace hotlap::sim
