#include "hotlap/sim/qss_profile.h"
#include "hotlap/common/special_values.h"

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

constexpr double kCapacitySpeed = 50.0;  // m/s at which the tyre peaks are tabulated

// A road point and its trigonometry, computed once for the many force balances of its searches.
struct PointTrig {
  explicit PointTrig(const RoadPoint& p)
      : point(&p),
        sin_bank(std::sin(p.bank)),
        cos_bank(std::cos(p.bank)),
        sin_grade(std::sin(p.grade)),
        cos_grade(std::cos(p.grade)) {}

  const RoadPoint* point;
  double sin_bank, cos_bank, sin_grade, cos_grade;

  vehicle::RoadGeometry<double> Road() const {
    return {point->bank, point->grade, point->curvature * sin_bank};
  }
  double PathCurvature() const { return point->curvature * cos_bank; }
};

double LateralForce(const QssVehicle& car, const PointTrig& at, double speed) {
  const double m = car.params->chassis.mass;
  return m * speed * speed * at.PathCurvature() - m * kGravity * at.sin_bank * at.cos_grade;
}

ForceDemand Demand(const QssVehicle& car, const PointTrig& at, double speed, double sum_fx,
                   const std::array<double, 4>& grip);

double Resistance(const QssVehicle& car, const PointTrig& at, double speed, double cornering_drag,
                  double rolling_coefficient);

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
  return LateralForce(car, PointTrig(point), speed);
}

double CalcCorneringDragCoefficient(const std::array<double, 4>& fy,
                                    const std::array<double, 4>& slip_angle) {
  double drag = 0.0, lateral = 0.0;
  for (int k = 0; k < 4; ++k) {
    drag -= fy[k] * std::sin(slip_angle[k]);
    lateral += fy[k];
  }
  return std::abs(lateral) < 100.0 ? 0.0 : drag / std::abs(lateral);
}

ForceDemand CalcForceDemand(const QssVehicle& car, const RoadPoint& point, double speed,
                            double sum_fx, const std::array<double, 4>& grip) {
  return Demand(car, PointTrig(point), speed, sum_fx, grip);
}

double CalcResistance(const QssVehicle& car, const RoadPoint& point, double speed,
                      double cornering_drag, double rolling_coefficient) {
  return Resistance(car, PointTrig(point), speed, cornering_drag, rolling_coefficient);
}

namespace {

ForceDemand Demand(const QssVehicle& car, const PointTrig& at, double speed, double sum_fx,
                   const std::array<double, 4>& grip) {
  const VehicleParams& p = *car.params;
  const double kappa_g = at.PathCurvature();
  ForceDemand d;
  d.sum_fy = LateralForce(car, at, speed);
  const vehicle::ChassisMotion<double> motion{speed, 0.0, speed * kappa_g, 0.0};
  d.fz = vehicle::CalcNormalLoads(p, motion, at.Road(), sum_fx, d.sum_fy);

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

double Resistance(const QssVehicle& car, const PointTrig& at, double speed, double cornering_drag,
                  double rolling_coefficient) {
  const VehicleParams& p = *car.params;
  const vehicle::AeroLoads<double> aero = vehicle::CalcAeroLoads(p.aero, speed);
  const double normal = p.chassis.mass * (kGravity * at.cos_bank * at.cos_grade +
                                          speed * speed * at.point->curvature * at.sin_bank) +
                        aero.downforce_front + aero.downforce_rear;
  double crr = rolling_coefficient;
  if (crr < 0.0) {
    crr = 0.0;
    for (double c : car.rolling_coefficient) crr += 0.25 * c;
  }
  const double lateral = cornering_drag == 0.0 ? 0.0 : LateralForce(car, at, speed);
  return aero.drag + crr * normal + p.chassis.mass * kGravity * at.sin_grade +
         cornering_drag * std::abs(lateral);
}

// The largest x in [lo, hi] with excess(x) <= 0, for an excess that grows with x, to within
// `tolerance`: false position with the Illinois modification (a few evaluations where the
// excess is smooth), each step kept inside the bracket and at least a tenth of it from its ends,
// so that kinks cost no more than bisection. Requires excess(lo) <= 0 < excess(hi). `slope`, where
// given, gets the excess's slope over the final bracket.
template <class Excess>
double LargestFeasible(double lo, double f_lo, double hi, double f_hi, double tolerance,
                       Excess excess, double* slope = nullptr) {
  double excess_lo = f_lo, excess_hi = f_hi;  // unscaled by the Illinois steps
  int side = 0;
  while (hi - lo > tolerance) {
    double x = lo - f_lo * (hi - lo) / (f_hi - f_lo);
    const double margin = 0.1 * (hi - lo);
    if (!(x > lo + margin)) x = lo + margin;
    if (!(x < hi - margin)) x = hi - margin;
    const double f = excess(x);
    if (f <= 0.0) {
      lo = x;
      f_lo = excess_lo = f;
      if (side == -1) f_hi *= 0.5;
      side = -1;
    } else {
      hi = x;
      f_hi = excess_hi = f;
      if (side == 1) f_lo *= 0.5;
      side = 1;
    }
  }
  if (slope != nullptr) *slope = (excess_hi - excess_lo) / (hi - lo);
  return lo;
}

// LargestFeasible over [lo, hi] searched from `search` (what a search at nearby inputs found).
// With the excess's slope known: a Newton step from the last answer, then the points a tenth of a
// tolerance below the step's root and a tolerance above that, which bracket the answer when the
// step was good (three evaluations; two where the last answer is such a point). Otherwise (or
// where they do not bracket it) the bracket is grown from the last point in steps that double from
// `step`, then narrowed by LargestFeasible. Returns hi where hi is feasible and lo - 1 where even
// lo is not; `search` gets the answer and its slope.
template <class Excess>
double LargestFeasibleFrom(LimitSearch* search, double step, double lo, double hi, double tolerance,
                           Excess excess) {
  double a = std::clamp(search->value, lo, hi);
  double f_a = excess(a);
  const auto found = [&](double x, double slope) {
    search->value = x;
    search->slope = slope;
    return x;
  };
  if (search->slope > 0.0 && std::isfinite(search->slope)) {
    // The step's root less a tenth of the tolerance (the Newton step is good to far better than
    // that), then a tolerance above: the answer lies at most a tenth of the tolerance below the
    // limit, as close as a search from scratch comes.
    const double root = a - f_a / search->slope;
    if (std::isfinite(root)) {
      double below = std::clamp(root - 0.1 * tolerance, lo, hi), f_below = f_a;
      if (f_a <= 0.0 && a >= below && a <= root) {
        below = a;  // the last answer is such a point already
      } else {
        f_below = excess(below);
      }
      if (f_below <= 0.0) {
        if (below >= hi) return found(hi, 0.0);
        const double above = std::min(below + tolerance, hi);
        const double f_above = excess(above);
        if (f_above > 0.0) return found(below, (f_above - f_below) / (above - below));
        a = above;
        f_a = f_above;
      } else {
        a = below;
        f_a = f_below;
      }
      step = tolerance;  // the answer is near: grow the bracket from a tolerance
    }
  }
  double b = a, f_b = f_a;
  if (f_a <= 0.0) {
    while (f_b <= 0.0) {
      if (b >= hi) return found(hi, 0.0);
      a = b;
      f_a = f_b;
      b = std::min(b + step, hi);
      f_b = excess(b);
      step *= 2.0;
    }
  } else {
    while (f_a > 0.0) {
      if (a <= lo) return found(lo - 1.0, 0.0);
      b = a;
      f_b = f_a;
      a = std::max(a - step, lo);
      f_a = excess(a);
      step *= 2.0;
    }
  }
  double slope = 0.0;
  const double x = LargestFeasible(a, f_a, b, f_b, tolerance, excess, &slope);
  return found(x, slope);
}

}  // namespace

namespace {

double CorneringLimitAt(const QssVehicle& car, const PointTrig& at,
                        const std::array<double, 4>& grip, double cornering_drag,
                        double rolling_coefficient, LimitSearch* search) {
  const double power = car.params->powertrain.WheelPower();
  // Excess over the limits: tyre utilisation beyond 1, or power beyond the wheel power.
  const auto excess = [&](double v) {
    const double fx = Resistance(car, at, v, cornering_drag, rolling_coefficient);
    const double u = Demand(car, at, v, fx, grip).max_utilization;
    return std::max(u - 1.0, (fx * v - power) / power);
  };
  const double lo = 0.5, hi = 150.0;
  if (search != nullptr && search->value > 0.0) {
    return std::max(LargestFeasibleFrom(search, 0.05, lo, hi, 1e-3, excess), 0.0);
  }
  LimitSearch none;
  LimitSearch& found = search != nullptr ? *search : none;
  found = {0.0, 0.0};
  const double f_lo = excess(lo), f_hi = excess(hi);
  if (!(f_lo <= 0.0)) return 0.0;
  if (f_hi <= 0.0) return found.value = hi;
  return found.value = LargestFeasible(lo, f_lo, hi, f_hi, 1e-3, excess, &found.slope);
}

double MaxDriveForceAt(const QssVehicle& car, const PointTrig& at, double speed,
                       const std::array<double, 4>& grip, SpeedLimit* limit, LimitSearch* search) {
  const double power_force = car.params->powertrain.WheelPower() / std::max(speed, 1.0);
  const auto excess = [&](double fx) {
    return Demand(car, at, speed, fx, grip).max_utilization - 1.0;
  };
  *limit = SpeedLimit::kPower;
  const double f_hi = excess(power_force);
  if (f_hi <= 0.0) return power_force;
  *limit = SpeedLimit::kTraction;
  if (search != nullptr && search->value >= 0.0) {
    return std::max(LargestFeasibleFrom(search, 20.0, 0.0, power_force, 0.5, excess), 0.0);
  }
  LimitSearch none;
  LimitSearch& found = search != nullptr ? *search : none;
  found = {0.0, 0.0};
  const double f_lo = excess(0.0);
  if (!(f_lo <= 0.0)) return 0.0;
  return found.value = LargestFeasible(0.0, f_lo, power_force, f_hi, 0.5, excess, &found.slope);
}

double MaxBrakeForceAt(const QssVehicle& car, const PointTrig& at, double speed,
                       const std::array<double, 4>& grip, LimitSearch* search) {
  const auto excess = [&](double brake) {
    return Demand(car, at, speed, -brake, grip).max_utilization - 1.0;
  };
  const double hi = 4.0 * car.params->Weight();
  if (search != nullptr && search->value >= 0.0) {
    return std::max(LargestFeasibleFrom(search, 20.0, 0.0, hi, 0.5, excess), 0.0);
  }
  LimitSearch none;
  LimitSearch& found = search != nullptr ? *search : none;
  found = {0.0, 0.0};
  const double f_lo = excess(0.0);
  if (!(f_lo <= 0.0)) return 0.0;
  const double f_hi = excess(hi);
  if (f_hi <= 0.0) return found.value = hi;
  return found.value = LargestFeasible(0.0, f_lo, hi, f_hi, 0.5, excess, &found.slope);
}

}  // namespace

double CalcCorneringLimit(const QssVehicle& car, const RoadPoint& point,
                          const std::array<double, 4>& grip, double cornering_drag,
                          double rolling_coefficient, LimitSearch* search) {
  return CorneringLimitAt(car, PointTrig(point), grip, cornering_drag, rolling_coefficient, search);
}

double CalcMaxDriveForce(const QssVehicle& car, const RoadPoint& point, double speed,
                         const std::array<double, 4>& grip, SpeedLimit* limit,
                         LimitSearch* search) {
  return MaxDriveForceAt(car, PointTrig(point), speed, grip, limit, search);
}

double CalcMaxBrakeForce(const QssVehicle& car, const RoadPoint& point, double speed,
                         const std::array<double, 4>& grip, LimitSearch* search) {
  return MaxBrakeForceAt(car, PointTrig(point), speed, grip, search);
}

SpeedProfile CalcSpeedProfile(const QssVehicle& car, std::span<const RoadPoint> road,
                              const std::array<std::vector<double>, 4>& grip,
                              std::span<const double> cornering_drag,
                              std::span<const double> rolling, const SpeedProfile* near) {
  const size_t n = road.size();
  if (!cornering_drag.empty() && cornering_drag.size() != n) {
    throw std::invalid_argument("CalcSpeedProfile: one cornering-drag coefficient per point");
  }
  if (!rolling.empty() && rolling.size() != n) {
    throw std::invalid_argument("CalcSpeedProfile: one rolling-resistance coefficient per point");
  }
  if (near != nullptr && near->searches.cornering.size() != n) {
    throw std::invalid_argument("CalcSpeedProfile: the profile to start from is of another road");
  }
  const auto drag_at = [&](size_t i) { return cornering_drag.empty() ? 0.0 : cornering_drag[i]; };
  const auto rolling_at = [&](size_t i) { return rolling.empty() ? -1.0 : rolling[i]; };
  const double ds = road[1].distance - road[0].distance;
  const double m = car.params->chassis.mass;
  const auto grip_at = [&](size_t i) {
    return std::array<double, 4>{grip[0][i], grip[1][i], grip[2][i], grip[3][i]};
  };
  const std::vector<PointTrig> trig(road.begin(), road.end());
  SpeedProfile out;
  ProfileSearches& searches = out.searches;
  if (near != nullptr) {
    searches = near->searches;
  } else {
    searches.cornering_drag.resize(n);
    searches.cornering.resize(n);
    searches.drive_speed.assign(n, -1.0);
    searches.drive.resize(n);
    searches.drive_limit.assign(n, SpeedLimit::kPower);
    searches.brake_speed.assign(n, -1.0);
    searches.brake.resize(n);
  }
  out.limit.assign(n, SpeedLimit::kCornering);
  out.cornering_limit.resize(n);
  for (size_t i = 0; i < n; ++i) {
    // A point whose coefficient is unchanged keeps its limit (the same search).
    if (near == nullptr || searches.cornering_drag[i] != drag_at(i)) {
      CorneringLimitAt(car, trig[i], grip_at(i), drag_at(i), rolling_at(i), &searches.cornering[i]);
      searches.cornering_drag[i] = drag_at(i);
    }
    out.cornering_limit[i] = searches.cornering[i].value;
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
    const double v = out.speed[prev];
    const double resistance = Resistance(car, trig[prev], v, drag_at(prev), rolling_at(prev));
    // Coasting (no drive: the least speed the car can reach) already leaves the point's limit
    // in force: the drive force is of no consequence, and not searched.
    if (std::sqrt(std::max(v * v - 2.0 * resistance / m * ds, 0.25)) >= out.speed[i] - 1e-6) {
      continue;
    }
    SpeedLimit why = SpeedLimit::kTraction;
    double drive = 0.0;
    if (near != nullptr && searches.drive_speed[prev] == v) {
      drive = searches.drive_limit[prev] == SpeedLimit::kPower  // the same search
                  ? car.params->powertrain.WheelPower() / std::max(v, 1.0)
                  : searches.drive[prev].value;
      why = searches.drive_limit[prev];
    } else {
      drive = MaxDriveForceAt(car, trig[prev], v, grip_at(prev), &why, &searches.drive[prev]);
      searches.drive_speed[prev] = v;
      searches.drive_limit[prev] = why;
    }
    const double a = (drive - resistance) / m;
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
    const double resistance = Resistance(car, trig[next], v, drag_at(next), rolling_at(next));
    // Without braking (the least speed the car can leave the point with) the point's speed is
    // already reachable: the brake force is of no consequence, and not searched.
    if (std::sqrt(std::max(v * v + 2.0 * resistance / m * ds, 0.25)) >= out.speed[i] - 1e-6) {
      continue;
    }
    double brake = 0.0;
    if (near != nullptr && searches.brake_speed[next] == v) {
      brake = searches.brake[next].value;  // the same search
    } else {
      brake = MaxBrakeForceAt(car, trig[next], v, grip_at(next), &searches.brake[next]);
      searches.brake_speed[next] = v;
    }
    const double d = (brake + resistance) / m;
    const double reachable = std::sqrt(std::max(v * v + 2.0 * d * ds, 0.25));
    if (reachable < out.speed[i] - 1e-6) {  // a limit search tolerance is not a limit
      out.speed[i] = reachable;
      out.limit[i] = SpeedLimit::kBraking;
    }
  }
  return out;
}

}  // namespace hotlap::sim
