#pragma once
/// @file
/// The speed profile of the quasi-steady-state lap (sim/qss_lap.h, steps 1 and 2): per-point
/// force demand and tyre utilisation, the cornering limit, and the forward and backward passes.
/// Separate from qss_lap.cc so that the force balance can be tested on its own.

#include <array>
#include <span>
#include <vector>

#include "hotlap/sim/qss_lap.h"
#include "hotlap/vehicle/tyre_capacity.h"
#include "hotlap/vehicle/vehicle_params.h"

namespace hotlap::sim {

/// The car prepared for the QSS: its parameters, each corner's tyre capacity table and rolling
/// resistance coefficient.
struct QssVehicle {
  const vehicle::VehicleParams* params = nullptr;
  std::vector<vehicle::TyreCapacity> capacity;  ///< per corner (CornerIndex)
  std::array<double, 4> rolling_coefficient{};  ///< -My / (R Fz) at zero slip, nominal load
  /// The highest speed the driver takes anywhere, m/s (a caution lap behind the pace car); 0: none.
  double speed_cap = 0.0;

  explicit QssVehicle(const vehicle::VehicleParams& p);
};

/// Per-corner forces (wheel axes, with the car on the centre line and no steer, so wheel, body and
/// road axes coincide) that a speed and total longitudinal tyre force need at a point, and how
/// close each tyre is to its friction ellipse.
struct ForceDemand {
  std::array<double, 4> fx{}, fy{}, fz{};
  std::array<double, 4> utilization{};  ///< (Fx/Fx_peak)^2 + (Fy/Fy_peak)^2; inf if Fz <= 0
  double sum_fy = 0.0;                  ///< N
  double max_utilization = 0.0;

  bool Feasible() const { return max_utilization <= 1.0; }
};

/// Demand at `point` and speed `speed` with total longitudinal tyre force `sum_fx` (> 0 driving:
/// the rear wheels share it in proportion to their capacity; < 0 braking: the brake balance
/// splits it per axle, equally per wheel). `grip` is each corner's g(T) h(wear).
ForceDemand CalcForceDemand(const QssVehicle& car, const RoadPoint& point, double speed,
                            double sum_fx, const std::array<double, 4>& grip);

/// The lateral force the tyres make together at `point` and `speed`: m V^2 kappa_g less the
/// bank's share of the weight, N (left +).
double CalcLateralForce(const QssVehicle& car, const RoadPoint& point, double speed);

/// Longitudinal resistance at a point besides the tyres' drive or brake force: drag, rolling
/// resistance, the grade and the tyres' cornering drag, N (positive opposes forward motion).
/// Cornering drag: a tyre running at a slip angle alpha turns -Fy sin(alpha) of its lateral force
/// against the direction it travels (the power its lateral sliding dissipates, over the speed);
/// taken as `cornering_drag` times the magnitude of the total lateral force (CalcLateralForce),
/// the coefficient (the tyres' lateral-force-weighted mean of -sin(alpha)) measured at the point's
/// last solution (CalcCorneringDragCoefficient) so that it is exact there. Rolling resistance: the
/// normal load times `rolling_coefficient` (the tyres' own where their thermal model has one,
/// gas-and-rim tyres), or times the mean of the car's rolling_coefficient where it is negative.
double CalcResistance(const QssVehicle& car, const RoadPoint& point, double speed,
                      double cornering_drag = 0.0, double rolling_coefficient = -1.0);

/// The cornering-drag coefficient of CalcResistance at a solved point: sum of -Fy sin(alpha)
/// over the four tyres (wheel axes, ISO slip angles) over the magnitude of their total lateral
/// force (dimensionless: the slip angle the car's lateral force runs at, in effect); 0 where the
/// lateral force is below 100 N (a straight: no drag to speak of). Per unit of lateral force
/// rather than of its square, so that a coefficient carries over between laps and between the
/// coupling pass and the lap (other grip, other speeds): at the cornering limit the tyres run at
/// about their peak slip angles whatever their grip.
double CalcCorneringDragCoefficient(const std::array<double, 4>& fy,
                                    const std::array<double, 4>& slip_angle);

/// A limit search's answer and the slope of its excess there (the utilisation or power beyond
/// the limit, per m/s or per N), so that a search at nearby inputs (the next profile's, with other
/// cornering-drag coefficients) starts with a Newton step from it and brackets its answer to the
/// tolerance in about three evaluations of the force demand instead of 10-15.
struct LimitSearch {
  double value = -1.0;  ///< the answer; < 0: none yet (a search from scratch)
  double slope = 0.0;   ///< d excess / d value at the answer; 0: not known
};

/// Highest speed at which the car holds its speed at `point` with every tyre inside its ellipse
/// and the power to overcome the resistance (to 1 mm/s below it). 0 if not even a crawl works.
/// `search`: where given, the search starts from what it holds and leaves what it found there
/// (the answer is the same to the tolerance).
double CalcCorneringLimit(const QssVehicle& car, const RoadPoint& point,
                          const std::array<double, 4>& grip, double cornering_drag = 0.0,
                          double rolling_coefficient = -1.0, LimitSearch* search = nullptr);

/// Largest total drive force (>= 0) at (point, speed) within the ellipses and the wheel power
/// (to 0.5 N). Sets `limit` to kPower or kTraction. `search`: as for CalcCorneringLimit.
double CalcMaxDriveForce(const QssVehicle& car, const RoadPoint& point, double speed,
                         const std::array<double, 4>& grip, SpeedLimit* limit,
                         LimitSearch* search = nullptr);

/// Largest total braking force (>= 0, i.e. sum Fx = -value) at (point, speed) within the ellipses
/// (to 0.5 N). `search`: as for CalcCorneringLimit.
double CalcMaxBrakeForce(const QssVehicle& car, const RoadPoint& point, double speed,
                         const std::array<double, 4>& grip, LimitSearch* search = nullptr);

/// What a profile's limit searches found at each point, so that the next profile of the same road,
/// grip and rolling-resistance coefficients with other cornering-drag coefficients (the drag's
/// fixed point, qss_lap.h) starts its searches there.
struct ProfileSearches {
  std::vector<double> cornering_drag;   ///< the coefficient each cornering limit was found with
  std::vector<LimitSearch> cornering;   ///< m/s, before the speed cap
  std::vector<double> drive_speed;      ///< m/s, where the forward pass searched (< 0: not)
  std::vector<LimitSearch> drive;       ///< N
  std::vector<SpeedLimit> drive_limit;  ///< kPower or kTraction
  std::vector<double> brake_speed;      ///< m/s, where the backward pass searched (< 0: not)
  std::vector<LimitSearch> brake;       ///< N
};

struct SpeedProfile {
  std::vector<double> speed;            ///< m/s, per road point
  std::vector<double> cornering_limit;  ///< m/s
  std::vector<SpeedLimit> limit;
  ProfileSearches searches;
};

/// The closed-lap speed profile for per-point grip factors grip[c][i], cornering-drag
/// coefficients (CalcResistance; empty: none) and rolling-resistance coefficients (CalcResistance;
/// empty: the car's), never above the car's speed_cap where it has one. `near`: a profile of the
/// same road, grip, rolling coefficients and speed cap (other cornering-drag coefficients) whose
/// searches this one starts from (a point whose inputs are unchanged keeps its answer); the
/// profile is the same to the searches' tolerances, in a third of the time.
SpeedProfile CalcSpeedProfile(const QssVehicle& car, std::span<const RoadPoint> road,
                              const std::array<std::vector<double>, 4>& grip,
                              std::span<const double> cornering_drag = {},
                              std::span<const double> rolling = {},
                              const SpeedProfile* near = nullptr);

}  // namespace hotlap::sim
