#pragma once
/// @file
/// The parts of a car that make it go round a track: chassis mass and geometry, aerodynamics,
/// powertrain, brake balance, and each corner's tyre force model and set-up. Read from the
/// `chassis`, `aero`, `powertrain`, `brake_system` and `tyre_forces` sections of a car.yaml
/// (docs/vehicle.md); SI units inside.
///
/// Geometry conventions (ISO 8855): body axes x forward, y left, z up, origin at the centre of
/// gravity projected on the road. Corner positions: front axle at x = a, rear at x = -b
/// (a + b = wheelbase), left wheels at y = +track/2.

#include <array>
#include <filesystem>
#include <string>

#include "hotlap/common/corner.h"
#include "hotlap/tyre/tyre_force_model.h"

namespace hotlap {
class YamlReader;
}

namespace hotlap::vehicle {

/// Rigid chassis with quasi-static load transfer.
struct ChassisParams {
  double mass = 0.0;                   ///< with driver and fuel, kg
  double yaw_inertia = 0.0;            ///< about the vertical axis through the CoG, kg m^2
  double wheelbase = 0.0;              ///< m
  double front_weight_fraction = 0.0;  ///< static share of the weight on the front axle, 1
  double left_weight_fraction = 0.0;   ///< static share on the left wheels, 1 (ovals: > 0.5)
  double cog_height = 0.0;             ///< centre of gravity above the road, m
  double track_front = 0.0;            ///< m
  double track_rear = 0.0;             ///< m
  /// Front axle's share of the total roll stiffness: the share of the lateral load transfer the
  /// front axle takes, 1.
  double roll_stiffness_front_share = 0.0;

  /// CoG to front axle, m.
  double a() const { return wheelbase * (1.0 - front_weight_fraction); }
  /// CoG to rear axle, m.
  double b() const { return wheelbase * front_weight_fraction; }
  /// Lateral CoG offset from the centre line, m (> 0 toward the left), from the static split.
  double y_cog(double track) const { return (left_weight_fraction - 0.5) * track; }
};

/// Aerodynamic drag and downforce, quadratic in speed, acting through fixed shares per axle.
struct AeroParams {
  double air_density = 0.0;            ///< kg/m^3
  double drag_area = 0.0;              ///< C_D A, m^2
  double downforce_area = 0.0;         ///< C_L A (downforce positive), m^2
  double front_downforce_share = 0.0;  ///< aero balance: front axle's share of downforce, 1
};

/// A power-limited engine driving the rear axle through a locked differential (spool).
struct PowertrainParams {
  double engine_power = 0.0;          ///< peak engine power, W
  double driveline_efficiency = 0.0;  ///< engine to rear contact patches, 1

  /// Power at the rear contact patches, W.
  double WheelPower() const { return engine_power * driveline_efficiency; }
};

/// How brake torque is shared.
struct BrakeSystemParams {
  double front_share = 0.0;  ///< brake balance: front axle's share of the braking force, 1
};

/// One corner's tyre force model and set-up.
struct CornerSetup {
  tyre::TyreForceModel<double> forces;
  double pressure = 0.0;  ///< inflation pressure, Pa
  /// Inclination angle, rad, ISO sign (tyre/tyre_force.h): a positive angle tilts the wheel's
  /// top toward -y (right). An oval set-up leans every wheel's top into the left turns: < 0.
  double camber = 0.0;
  double rolling_radius = 0.0;  ///< effective rolling radius for slip and the spool, m
};

/// Everything the vehicle model needs beyond the thermal parts.
struct VehicleParams {
  ChassisParams chassis;
  AeroParams aero;
  PowertrainParams powertrain;
  BrakeSystemParams brakes;
  std::array<CornerSetup, 4> corners;  ///< indexed by CornerIndex

  const CornerSetup& corner(Corner c) const { return corners[CornerIndex(c)]; }
  /// Static weight, N.
  double Weight() const;
  /// Position of a corner's contact point in body axes, m.
  std::array<double, 2> CornerPosition(Corner c) const;
  /// Track width of the corner's axle, m.
  double Track(Corner c) const { return IsFront(c) ? chassis.track_front : chassis.track_rear; }
};

/// Reads the vehicle sections of a car file from `car` (which must have them): chassis, aero,
/// powertrain, brake_system, tyre_forces (per corner: file, pressure_kPa, camber_deg). Paths are
/// relative to the car file. InputError naming the file and field for anything out of range.
VehicleParams ReadVehicleParams(YamlReader& car);

}  // namespace hotlap::vehicle
