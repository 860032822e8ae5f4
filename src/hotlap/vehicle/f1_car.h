#pragma once
/// @file
/// The 3-DOF Formula 1 car of Perantoni and Limebeer (Vehicle System Dynamics 52, 2014) as the
/// peer program fastest-lap encodes it (its `limebeer-2014-f1.xml`, MIT licence): a rigid chassis
/// in the road plane (u, v, yaw rate r), four quasi-static wheels, normal loads from the vertical,
/// pitch and roll balances plus a roll-balance split, a simplified Pacejka tyre whose peak
/// friction and peak slips are interpolated linearly in the load between two reference loads, a
/// quadratic drag and downforce, a rear axle with a power-limited engine and a viscous
/// differential, brakes with a fixed front bias. No thermal states. docs/f1-peer.md derives every
/// equation and lists what differs from fastest-lap.
///
/// Axes: ISO 8855 (x forward, y left, z up), as the rest of hotlap; fastest-lap writes its model
/// with y to the right and z down. The equations are mirror-symmetric, so they are the same.
///
/// How to use: LoadF1Car("data/cars/f1-2014/car.yaml"), then the scalar-templated functions below
/// (double, ceres::Jet, SecondOrder) evaluate the model; ocp/f1_lap_problem.h builds the lap.

#include <array>
#include <cmath>
#include <filesystem>
#include <string>

namespace hotlap::vehicle {

/// fastest-lap's gravitational acceleration (its g0).
inline constexpr double kF1Gravity = 9.81;

/// fastest-lap's "tire-pacejka-simple" tyre.
struct F1TyreParams {
  double radius_m = 0.0;
  double load_1_N = 0.0;  ///< first reference load
  double load_2_N = 0.0;  ///< second reference load (> load_1)
  double mu_x_max_1 = 0.0, mu_x_max_2 = 0.0;
  double kappa_max_1 = 0.0, kappa_max_2 = 0.0;
  double mu_y_max_1 = 0.0, mu_y_max_2 = 0.0;
  double lambda_max_1_rad = 0.0, lambda_max_2_rad = 0.0;
  double qx = 0.0, qy = 0.0;  ///< shape factors
  /// The floor of the interpolated peak friction (fastest-lap's fixed _mu_min = 1.0), reached
  /// smoothly: mu = smooth_pos(mu_lin - mu_min, 1e-5) + mu_min.
  double mu_min = 1.0;
};

struct F1CarParams {
  std::string name;
  std::filesystem::path path;
  double mass_kg = 0.0;
  double yaw_inertia_kgm2 = 0.0;
  double cog_height_m = 0.0;
  double front_axle_x_m = 0.0;       ///< from the centre of mass, > 0
  double rear_axle_x_m = 0.0;        ///< from the centre of mass, < 0
  double pressure_centre_x_m = 0.0;  ///< from the centre of mass
  double track_front_m = 0.0, track_rear_m = 0.0;
  double air_density_kg_per_m3 = 0.0;
  double frontal_area_m2 = 0.0;
  double drag_coefficient = 0.0;
  double lift_coefficient = 0.0;       ///< downforce coefficient (> 0 pushes down)
  double roll_balance = 0.5;           ///< fastest-lap's roll_balance_coefficient D
  double brake_bias_front = 0.6;       ///< share of the brake torque on the front axle
  double brake_torque_front_Nm = 0.0;  ///< per front wheel at full brake and bias 1
  double brake_torque_rear_Nm = 0.0;   ///< per rear wheel at full brake and bias 1
  double engine_power_W = 0.0;
  double differential_stiffness_Nms = 0.0;  ///< N m s / rad
  double throttle_smoothing = 1e-5;         ///< eps2 of smooth_pos(+-throttle, eps2)
  F1TyreParams front_tyre, rear_tyre;

  double Weight() const { return mass_kg * kF1Gravity; }
  /// 0.5 rho Cd A and 0.5 rho Cl A, N / (m/s)^2.
  double DragFactor() const {
    return 0.5 * air_density_kg_per_m3 * drag_coefficient * frontal_area_m2;
  }
  double DownforceFactor() const {
    return 0.5 * air_density_kg_per_m3 * lift_coefficient * frontal_area_m2;
  }
  const F1TyreParams& tyre(int corner) const { return corner < 2 ? front_tyre : rear_tyre; }
  /// Contact patch of corner 0..3 (fl, fr, rl, rr) from the centre of mass, ISO (y left).
  std::array<double, 2> CornerPosition(int corner) const {
    const bool front = corner < 2;
    const double half = 0.5 * (front ? track_front_m : track_rear_m);
    return {front ? front_axle_x_m : rear_axle_x_m, corner % 2 == 0 ? half : -half};
  }
};

/// True when the car file says `model: limebeer-2014-f1` (InputError if it cannot be parsed).
bool IsF1CarFile(const std::filesystem::path& car_yaml);

/// Reads and validates a car file of model limebeer-2014-f1 (data/cars/f1-2014/car.yaml):
/// InputError naming the file and field for a missing or misspelt key or an out-of-range value.
F1CarParams LoadF1Car(const std::filesystem::path& car_yaml);

/// fastest-lap's smooth positive part: (x + sqrt(x^2 + eps2)) / 2.
template <class T>
T SmoothPos(const T& x, double eps2) {
  using std::sqrt;
  return 0.5 * (x + sqrt(x * x + eps2));
}

/// Tyre forces in the wheel frame (ISO): longitudinal and lateral, N.
template <class T>
struct F1TyreForce {
  T fx, fy;
};

/// The simplified Pacejka tyre at normal load fz (N), slip ratio kappa ((omega R - vx) / vx) and
/// lateral slip lambda (-vy / vx, wheel frame):
///   p(Fz) = p1 + (Fz - Fz1) (p2 - p1) / (Fz2 - Fz1) for the peaks (friction floored at mu_min),
///   rho = sqrt((kappa / kappa_max)^2 + (lambda / lambda_max)^2 + 1e-12),
///   Fx = mu_x(Fz) Fz sin(Qx atan(Sx rho)) (kappa / kappa_max) / rho, Sx = pi / (2 atan(Qx)),
///   and Fy likewise with mu_y, lambda, Qy.
template <class T>
F1TyreForce<T> CalcF1TyreForce(const F1TyreParams& p, const T& fz, const T& kappa,
                               const T& lambda) {
  using std::atan;
  using std::sin;
  using std::sqrt;
  const T t = (fz - p.load_1_N) / (p.load_2_N - p.load_1_N);
  const T mu_x =
      SmoothPos(p.mu_x_max_1 + t * (p.mu_x_max_2 - p.mu_x_max_1) - p.mu_min, 1e-5) + p.mu_min;
  const T mu_y =
      SmoothPos(p.mu_y_max_1 + t * (p.mu_y_max_2 - p.mu_y_max_1) - p.mu_min, 1e-5) + p.mu_min;
  const T kappa_max = p.kappa_max_1 + t * (p.kappa_max_2 - p.kappa_max_1);
  const T lambda_max = p.lambda_max_1_rad + t * (p.lambda_max_2_rad - p.lambda_max_1_rad);
  const T kn = kappa / kappa_max;
  const T ln = lambda / lambda_max;
  const T rho = sqrt(kn * kn + ln * ln + 1e-12);
  const double sx = M_PI / (2.0 * std::atan(p.qx));
  const double sy = M_PI / (2.0 * std::atan(p.qy));
  const T fx = mu_x * fz * sin(p.qx * atan(sx * rho)) * kn / rho;
  const T fy = mu_y * fz * sin(p.qy * atan(sy * rho)) * ln / rho;
  return {fx, fy};
}

/// The normal loads (N, upward, fl fr rl rr) at forward speed u with the tyres' body-axis totals
/// x_tyres and y_tyres (N), from fastest-lap's four balances: vertical (weight + downforce),
/// pitch, roll and roll balance:
///   N_f + N_r = m g + L,  L = 0.5 rho Cl A u^2
///   a N_f - b N_r = x_p L - h (X - D)   (D = drag; fastest-lap takes the aerodynamic force's
///                                        moment with the pressure centre's offset from the
///                                        centre of mass, so it acts at ground level)
///   wf (N_fl - N_fr) + wr (N_rl - N_rr) = -h Y   (w = half track)
///   (N_fl - N_fr) (1 - D_r) = (N_rl - N_rr) D_r   (roll balance D_r)
template <class T>
std::array<T, 4> CalcF1NormalLoads(const F1CarParams& p, const T& u, const T& x_tyres,
                                   const T& y_tyres) {
  const double a = p.front_axle_x_m, b = -p.rear_axle_x_m, h = p.cog_height_m;
  const T u2 = u * u;
  const T lift = p.DownforceFactor() * u2;
  const T drag = p.DragFactor() * u2;
  const T total = p.Weight() + lift;
  const T nf = (b * total + p.pressure_centre_x_m * lift - h * (x_tyres - drag)) / (a + b);
  const T nr = total - nf;
  const double wf = 0.5 * p.track_front_m, wr = 0.5 * p.track_rear_m, d = p.roll_balance;
  // Left-minus-right differences per axle.
  const T df = -h * y_tyres * d / (wf * d + wr * (1.0 - d));
  const T dr = df * ((1.0 - d) / d);
  return {0.5 * (nf + df), 0.5 * (nf - df), 0.5 * (nr + dr), 0.5 * (nr - dr)};
}

/// The throttle's split into drive and brake fractions: smooth_pos(+-throttle, eps2).
template <class T>
std::array<T, 2> F1ThrottleSplit(const F1CarParams& p, const T& throttle) {
  return {SmoothPos(throttle, p.throttle_smoothing), SmoothPos(-throttle, p.throttle_smoothing)};
}

}  // namespace hotlap::vehicle
