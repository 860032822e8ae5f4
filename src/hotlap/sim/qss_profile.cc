#include "hotlap/sim/qss_profile.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/vehicle/vehicle_model.h"

namespace hotlap::sim {

namespace {

using vehicle::VehicleParams;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kCapacitySpeed = 50.0;  // m/s at which the tyre peaks are tabulated

vehicle::RoadGeometry<double> Road(const RoadPoint& point) {
  return {point.bank, point.grade, point.curvature * std::sin(point.bank)};
}

double PathCurvature(const RoadPoint& point) { return point.curvature * std::cos(point.bank); }

}  // namespace

QssVehicle::QssVehicle(const VehicleParams& p) : params(&p) {
  const double max_load = 1.2 * p.Weight() + 20000.0;
  for (Corner c : kAllCorners) {
    const vehicle::CornerSetup& setup = p.corner(c);
    capacity.emplace_back(setup, max_load, 48, kCapacitySpeed);
    // Rolling resistance coefficient at a quarter of the weight, free rolling.
    rolling_coefficient[CornerIndex(c)] =
        vehicle::CalcFreeRollingCoefficient(setup, 0.25 * p.Weight());
  }
}

double CalcLateralForce(const QssVehicle& car, const RoadPoint& point, double speed) {
  const double m = car.params->chassis.mass;
  return m * speed * speed * PathCurvature(point) -
         m * kGravity * std::sin(point.bank) * std::cos(point.grade);
}

double CalcCorneringDragCoefficient(const std::array<double, 4>& fy,
                                    const std::array<double, 4>& slip_angle) {
  double drag = 0.0, lateral = 0.0;
  for (int k = 0; k < 4; ++k) {
    drag -= fy[k] * std::sin(slip_angle[k]);
    lateral += fy[k];
  }
  return std::abs(lateral) < 100.0 ? 0.0 : drag / (lateral * lateral);
}

ForceDemand CalcForceDemand(const QssVehicle& car, const RoadPoint& point, double speed,
                            double sum_fx, const std::array<double, 4>& grip) {
  const VehicleParams& p = *car.params;
  const double kappa_g = PathCurvature(point);
  ForceDemand d;
  d.sum_fy = CalcLateralForce(car, point, speed);
  const vehicle::ChassisMotion<double> motion{speed, 0.0, speed * kappa_g, 0.0};
  d.fz = vehicle::CalcNormalLoads(p, motion, Road(point), sum_fx, d.sum_fy);

  std::array<vehicle::TyrePeaks, 4> peaks;
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    peaks[i] = car.capacity[i].At(d.fz[i]);
    for (double* v : {&peaks[i].drive, &peaks[i].brake, &peaks[i].left, &peaks[i].right}) {
      *v *= grip[i];
    }
  }
  const auto lateral_capacity = [&](int i) {
    return d.sum_fy >= 0.0 ? peaks[i].left : peaks[i].right;
  };
  // Lateral: axles by yaw-moment balance, wheels by capacity.
  const double L = p.chassis.wheelbase;
  const std::array<std::pair<Corner, Corner>, 2> axles = {
      std::pair{Corner::kFrontLeft, Corner::kFrontRight},
      std::pair{Corner::kRearLeft, Corner::kRearRight}};
  for (const auto& [left, right] : axles) {
    const bool front = IsFront(left);
    const double axle_fy = d.sum_fy * (front ? p.chassis.b() : p.chassis.a()) / L;
    const int il = CornerIndex(left), ir = CornerIndex(right);
    const double cl = lateral_capacity(il), cr = lateral_capacity(ir);
    const double share = cl + cr > 0.0 ? cl / (cl + cr) : 0.5;
    d.fy[il] = axle_fy * share;
    d.fy[ir] = axle_fy * (1.0 - share);
    // Longitudinal.
    if (sum_fx >= 0.0) {
      if (!front) {
        const double dl = peaks[il].drive, dr = peaks[ir].drive;
        const double s = dl + dr > 0.0 ? dl / (dl + dr) : 0.5;
        d.fx[il] = sum_fx * s;
        d.fx[ir] = sum_fx * (1.0 - s);
      }
    } else {
      const double axle_fx = sum_fx * (front ? p.brakes.front_share : 1.0 - p.brakes.front_share);
      d.fx[il] = d.fx[ir] = 0.5 * axle_fx;
    }
  }
  d.max_utilization = 0.0;
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    double u = kInf;
    if (d.fz[i] > 0.0) {
      const double cx = d.fx[i] >= 0.0 ? peaks[i].drive : peaks[i].brake;
      const double cy = d.fy[i] >= 0.0 ? peaks[i].left : peaks[i].right;
      const double ux = d.fx[i] == 0.0 ? 0.0 : (cx > 0.0 ? d.fx[i] / cx : kInf);
      const double uy = d.fy[i] == 0.0 ? 0.0 : (cy > 0.0 ? d.fy[i] / cy : kInf);
      u = ux * ux + uy * uy;
    }
    d.utilization[i] = u;
    d.max_utilization = std::max(d.max_utilization, u);
  }
  return d;
}

double CalcResistance(const QssVehicle& car, const RoadPoint& point, double speed,
                      double cornering_drag, double rolling_coefficient) {
  const VehicleParams& p = *car.params;
  const vehicle::AeroLoads<double> aero = vehicle::CalcAeroLoads(p.aero, speed);
  const double normal = p.chassis.mass * (kGravity * std::cos(point.bank) * std::cos(point.grade) +
                                          speed * speed * point.curvature * std::sin(point.bank)) +
                        aero.downforce_front + aero.downforce_rear;
  double crr = rolling_coefficient;
  if (crr < 0.0) {
    crr = 0.0;
    for (double c : car.rolling_coefficient) crr += 0.25 * c;
  }
  const double lateral = cornering_drag == 0.0 ? 0.0 : CalcLateralForce(car, point, speed);
  return aero.drag + crr * normal + p.chassis.mass * kGravity * std::sin(point.grade) +
         cornering_drag * lateral * lateral;
}

namespace {

// The largest x in [lo, hi] with excess(x) <= 0, for an excess that grows with x, to within
// `tolerance`: false position with the Illinois modification (a few evaluations where the
// excess is smooth), each step kept inside the bracket and at least a tenth of it from its ends,
// so that kinks cost no more than bisection. Requires excess(lo) <= 0 < excess(hi).
template <class Excess>
double LargestFeasible(double lo, double f_lo, double hi, double f_hi, double tolerance,
                       Excess excess) {
  int side = 0;
  while (hi - lo > tolerance) {
    double x = lo - f_lo * (hi - lo) / (f_hi - f_lo);
    const double margin = 0.1 * (hi - lo);
    if (!(x > lo + margin)) x = lo + margin;
    if (!(x < hi - margin)) x = hi - margin;
    const double f = excess(x);
    if (f <= 0.0) {
      lo = x;
      f_lo = f;
      if (side == -1) f_hi *= 0.5;
      side = -1;
    } else {
      hi = x;
      f_hi = f;
      if (side == 1) f_lo *= 0.5;
      side = 1;
    }
  }
  return lo;
}

}  // namespace

double CalcCorneringLimit(const QssVehicle& car, const RoadPoint& point,
                          const std::array<double, 4>& grip, double cornering_drag,
                          double rolling_coefficient) {
  const double power = car.params->powertrain.WheelPower();
  // Excess over the limits: tyre utilisation beyond 1, or power beyond the wheel power.
  const auto excess = [&](double v) {
    const double fx = CalcResistance(car, point, v, cornering_drag, rolling_coefficient);
    const double u = CalcForceDemand(car, point, v, fx, grip).max_utilization;
    return std::max(u - 1.0, (fx * v - power) / power);
  };
  const double lo = 0.5, hi = 150.0;
  const double f_lo = excess(lo), f_hi = excess(hi);
  if (!(f_lo <= 0.0)) return 0.0;
  if (f_hi <= 0.0) return hi;
  return LargestFeasible(lo, f_lo, hi, f_hi, 1e-3, excess);
}

double CalcMaxDriveForce(const QssVehicle& car, const RoadPoint& point, double speed,
                         const std::array<double, 4>& grip, SpeedLimit* limit) {
  const double power_force = car.params->powertrain.WheelPower() / std::max(speed, 1.0);
  const auto excess = [&](double fx) {
    return CalcForceDemand(car, point, speed, fx, grip).max_utilization - 1.0;
  };
  *limit = SpeedLimit::kPower;
  const double f_hi = excess(power_force);
  if (f_hi <= 0.0) return power_force;
  *limit = SpeedLimit::kTraction;
  const double f_lo = excess(0.0);
  if (!(f_lo <= 0.0)) return 0.0;
  return LargestFeasible(0.0, f_lo, power_force, f_hi, 0.5, excess);
}

double CalcMaxBrakeForce(const QssVehicle& car, const RoadPoint& point, double speed,
                         const std::array<double, 4>& grip) {
  const auto excess = [&](double brake) {
    return CalcForceDemand(car, point, speed, -brake, grip).max_utilization - 1.0;
  };
  const double f_lo = excess(0.0);
  if (!(f_lo <= 0.0)) return 0.0;
  const double hi = 4.0 * car.params->Weight();
  const double f_hi = excess(hi);
  if (f_hi <= 0.0) return hi;
  return LargestFeasible(0.0, f_lo, hi, f_hi, 0.5, excess);
}

SpeedProfile CalcSpeedProfile(const QssVehicle& car, std::span<const RoadPoint> road,
                              const std::array<std::vector<double>, 4>& grip,
                              std::span<const double> cornering_drag,
                              std::span<const double> rolling) {
  const size_t n = road.size();
  if (!cornering_drag.empty() && cornering_drag.size() != n) {
    throw std::invalid_argument("CalcSpeedProfile: one cornering-drag coefficient per point");
  }
  if (!rolling.empty() && rolling.size() != n) {
    throw std::invalid_argument("CalcSpeedProfile: one rolling-resistance coefficient per point");
  }
  const auto drag_at = [&](size_t i) { return cornering_drag.empty() ? 0.0 : cornering_drag[i]; };
  const auto rolling_at = [&](size_t i) { return rolling.empty() ? -1.0 : rolling[i]; };
  const double ds = road[1].distance - road[0].distance;
  const double m = car.params->chassis.mass;
  const auto grip_at = [&](size_t i) {
    return std::array<double, 4>{grip[0][i], grip[1][i], grip[2][i], grip[3][i]};
  };
  SpeedProfile out;
  out.cornering_limit.resize(n);
  out.limit.assign(n, SpeedLimit::kCornering);
  for (size_t i = 0; i < n; ++i) {
    out.cornering_limit[i] =
        CalcCorneringLimit(car, road[i], grip_at(i), drag_at(i), rolling_at(i));
    if (!(out.cornering_limit[i] > 0.0)) {
      throw NumericalError(fmt::format(
          "QSS lap: no speed is feasible at {:.1f} m (curvature {:.5f} 1/m, bank {:.1f} deg): "
          "the tyres cannot hold the car there",
          road[i].distance, road[i].curvature, RadToDeg(road[i].bank)));
    }
  }
  if (car.speed_cap > 0.0) {
    for (size_t i = 0; i < n; ++i) {
      if (out.cornering_limit[i] > car.speed_cap) {
        out.cornering_limit[i] = car.speed_cap;
        out.limit[i] = SpeedLimit::kPaceCar;
      }
    }
  }
  // Start both passes at the slowest corner, where the speed is its cornering limit.
  const size_t start =
      static_cast<size_t>(std::min_element(out.cornering_limit.begin(), out.cornering_limit.end()) -
                          out.cornering_limit.begin());
  out.speed = out.cornering_limit;
  // Forward: accelerate as hard as traction and power allow.
  for (size_t k = 1; k <= n; ++k) {
    const size_t prev = (start + k - 1) % n, i = (start + k) % n;
    SpeedLimit why = SpeedLimit::kTraction;
    const double v = out.speed[prev];
    const double drive = CalcMaxDriveForce(car, road[prev], v, grip_at(prev), &why);
    const double a =
        (drive - CalcResistance(car, road[prev], v, drag_at(prev), rolling_at(prev))) / m;
    const double reachable = std::sqrt(std::max(v * v + 2.0 * a * ds, 0.25));
    if (reachable < out.speed[i] - 1e-6) {  // a limit search tolerance is not a limit
      out.speed[i] = reachable;
      out.limit[i] = why;
    }
  }
  // Backward: brake as late as the tyres allow.
  for (size_t k = 1; k <= n; ++k) {
    const size_t next = (start + n - k + 1) % n, i = (start + n - k) % n;
    const double v = out.speed[next];
    const double brake = CalcMaxBrakeForce(car, road[next], v, grip_at(next));
    const double d =
        (brake + CalcResistance(car, road[next], v, drag_at(next), rolling_at(next))) / m;
    const double reachable = std::sqrt(std::max(v * v + 2.0 * d * ds, 0.25));
    if (reachable < out.speed[i] - 1e-6) {  // a limit search tolerance is not a limit
      out.speed[i] = reachable;
      out.limit[i] = SpeedLimit::kBraking;
    }
  }
  return out;
}

}  // namespace hotlap::sim
