#pragma once
/// @file
/// The quasi-steady-state (QSS) lap: the fastest speed profile the car's tyre, power and brake
/// limits allow round a banked track, the per-corner forces and slips that profile needs, and the
/// tyre and brake thermal models integrated along it, lap after lap.
///
/// How it works (docs/lap-simulation.md):
/// 1. At every point of the centre line (spacing ds), the cornering limit: the highest speed at
///    which the car, holding its speed, keeps every tyre inside its friction ellipse. The lateral
///    force the tyres must make is m V^2 kappa_g - m g sin(theta) cos(phi) (spec section 10);
///    front and rear axles share it by yaw-moment balance (b/L and a/L), the wheels of an axle in
///    proportion to their capacities; the loads follow from vehicle::CalcNormalLoads. Each tyre's
///    ellipse has the pure-slip peaks of its force model at its load (vehicle::TyreCapacity) times
///    its grip factor g(T_tread) h(wear).
/// 2. Forward pass (traction and power: the rear axle drives, P_wheel >= Fx V) and backward pass
///    (braking with the brake balance), each limited by the same ellipses, from the slowest
///    corner round the closed lap.
/// 3. At every point, the per-corner forces of that profile and the slips that make them
///    (vehicle/slip_inversion.h: free front wheels, rear wheels on a spool).
/// 4. The thermal, wear and brake models replayed along the lap (sim/replay.h).
/// Cornering drag: the lateral forces of tyres at a slip angle also act against the motion
/// (sum of -Fy sin(alpha), about 1.6 kN mid-turn at Darlington); steps 1-3 are solved again with
/// the drag the last forces and slip angles gave until the profile settles (qss_profile.h).
/// Thermal coupling: a lap's grip factors come from the previous lap's temperatures and wear at
/// the same point; the first lap is run twice, first at the starting temperatures.
///
/// Rolling resistance: a gas-and-rim tyre's own coefficient (its carcass hysteresis, falling with
/// carcass temperature and pressure), from the last lap at each point, weighted by the tyres'
/// loads; the paper's tyres roll with their force model's coefficient at nominal load.
///
/// Simplifications (stated, not hidden): the car follows the centre line with no body slip in
/// the limit search; yaw moments of the longitudinal forces and of the spool are left out of the
/// axle split; steady-state tyres (no relaxation).

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hotlap/sim/replay.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::sim {

/// The road at one point of the path the car drives (the centre line or a racing line; uniform
/// spacing along it, closed: the point after the last is the first).
struct RoadPoint {
  double distance = 0.0;   ///< along the path from the start line, m
  double curvature = 0.0;  ///< horizontal curvature kappa_h of the path, 1/m (> 0 turning left)
  double bank = 0.0;       ///< theta, rad (> 0: right edge up)
  double grade = 0.0;      ///< phi, rad (> 0: uphill)
  double centre_distance = 0.0;  ///< centre-line distance of the same cross-section, m
  double offset = 0.0;           ///< the path's lateral offset from the centre line, m (left +)
};

/// What limits the speed at a point.
enum class SpeedLimit {
  kCornering,  ///< tyres saturated at steady speed
  kTraction,   ///< accelerating out: rear tyres saturated
  kPower,      ///< accelerating: engine power
  kBraking,    ///< braking into the next corner
  kPaceCar,    ///< behind the pace car (QssOptions::caution_laps)
};

struct QssOptions {
  int laps = 1;
  double ambient_temp = 0.0;  ///< K
  double track_temp = 0.0;    ///< K
  ReplayInitialState initial;
  ReplayOptions replay;
  /// Recompute the first lap with the grip factors of its own first pass (thermal coupling).
  bool couple_first_lap = true;
  /// Centre-line length of the lap, m (closes centre_distance); 0: the road's own length.
  double track_length = 0.0;
  /// Most speed profiles a pass solves for the tyres' cornering drag (sim/qss_profile.h,
  /// CalcResistance): 1 leaves it out (the profile and forces without it); each further profile
  /// takes the coefficients the last forces and slip angles gave (its searches started from the
  /// last profile's, its slips updated from the last solve's: sim/qss_slips.h), until the drag is
  /// settled (drag_settled_lap_time).
  int max_drag_passes = 6;
  /// The cornering drag is settled when a profile moves the lap time by less than this, s, or the
  /// speeds by less than 1 mm/s on average, or when the moves still to come (each about the last
  /// one's share of the one before, summed) come to less than half of it.
  double drag_settled_lap_time = 5e-4;
  /// Laps run behind the pace car (0-based indices, increasing): every point of those laps at
  /// most `caution_speed`; the temperatures and pressures fall as they do under a caution.
  std::vector<int> caution_laps;
  double caution_speed = 0.0;  ///< m/s, > 0 where there are caution laps

  /// The speed cap of lap `index`, m/s (0: none).
  double SpeedCapOfLap(int index) const {
    for (int l : caution_laps) {
      if (l == index) return caution_speed;
    }
    return 0.0;
  }
};

/// One lap's profile and the per-corner channels the thermal models ran on; N + 1 samples (the
/// last closes the lap at the start line).
struct QssLap {
  std::vector<double> distance;         ///< m along the driven path, from this lap's start
  std::vector<double> centre_distance;  ///< m along the centre line (the cross-section)
  std::vector<double> offset;           ///< m, the path's lateral offset (left +)
  std::vector<double> time;             ///< s, from this lap's start
  std::vector<double> speed;            ///< m/s
  std::vector<double> accel_long;       ///< m/s^2
  std::vector<double> accel_lat;        ///< V^2 kappa_g, m/s^2
  std::vector<double> steer;            ///< derived road-wheel steer angle, rad
  std::vector<SpeedLimit> limit;        ///< what set the speed
  std::array<CornerChannels, 4> corners;
  std::array<std::vector<double>, 4> tread_temp_used;  ///< K, the grip factors' temperatures
  double lap_time = 0.0;                               ///< s
  /// m, each corner's rolling radius on this lap (a gas-and-rim tyre's at the lap's hot pressure,
  /// sim/hot_pressure.h; else the set-up's)
  std::array<double, 4> rolling_radius{};
  int slip_points_not_reached = 0;  ///< samples where a tyre could not make its target forces
  double max_force_deficit = 0.0;   ///< N, the largest such shortfall
  ReplayResult thermal;             ///< temperatures, wear, brake power along the lap
};

struct QssResult {
  std::vector<QssLap> laps;
};

/// The 0-based lap indices of a list such as "11-15,40" (1-based laps, ranges inclusive,
/// increasing, each in [1, laps]); empty text: none. InputError naming `option` otherwise.
std::vector<int> ParseLapList(const std::string& text, int laps, std::string_view option);
/// A caution's pace-car speed in km/h as m/s, checked in (20, 250] km/h (InputError naming
/// `option`).
double CheckCautionSpeed(double kph, std::string_view option);

/// Runs the QSS lap(s). `road` must have at least 16 points at uniform spacing. InputError if the
/// car has no vehicle sections or the road is malformed; NumericalError if no speed is feasible
/// somewhere (e.g. a corner tighter than the tyres can take at any speed).
QssResult RunQssLap(const vehicle::Car& car, std::span<const RoadPoint> road,
                    const QssOptions& options);

}  // namespace hotlap::sim
