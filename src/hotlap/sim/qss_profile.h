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

/// Longitudinal resistance at a point besides the tyres' drive or brake force: drag, rolling
/// resistance and the grade, N (positive opposes forward motion).
double CalcResistance(const QssVehicle& car, const RoadPoint& point, double speed);

/// Highest speed at which the car holds its speed at `point` with every tyre inside its ellipse
/// and the power to overcome the resistance (bisection to 1 mm/s). 0 if not even a crawl works.
double CalcCorneringLimit(const QssVehicle& car, const RoadPoint& point,
                          const std::array<double, 4>& grip);

/// Largest total drive force (>= 0) at (point, speed) within the ellipses and the wheel power.
/// Sets `limit` to kPower or kTraction.
double CalcMaxDriveForce(const QssVehicle& car, const RoadPoint& point, double speed,
                         const std::array<double, 4>& grip, SpeedLimit* limit);

/// Largest total braking force (>= 0, i.e. sum Fx = -value) at (point, speed) within the ellipses.
double CalcMaxBrakeForce(const QssVehicle& car, const RoadPoint& point, double speed,
                         const std::array<double, 4>& grip);

struct SpeedProfile {
  std::vector<double> speed;            ///< m/s, per road point
  std::vector<double> cornering_limit;  ///< m/s
  std::vector<SpeedLimit> limit;
};

/// The closed-lap speed profile for per-point grip factors grip[c][i].
SpeedProfile CalcSpeedProfile(const QssVehicle& car, std::span<const RoadPoint> road,
                              const std::array<std::vector<double>, 4>& grip);

}  // namespace hotlap::sim
