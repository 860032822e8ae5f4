#include "hotlap/sim/qss_slips.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "hotlap/common/corner.h"

namespace hotlap::sim {

namespace {

constexpr int kFl = CornerIndex(Corner::kFrontLeft);
constexpr int kFr = CornerIndex(Corner::kFrontRight);
constexpr int kRl = CornerIndex(Corner::kRearLeft);
constexpr int kRr = CornerIndex(Corner::kRearRight);

// The largest step of a slip ratio or slip angle (rad) taken to first order: the force models'
// curvature over it leaves well under the solve's tolerance of 1 N.
constexpr double kMaxLinearStep = 1e-3;

// The load's share of a force change at fixed slips: the force in proportion to the load.
double LoadScale(double fz_now, double fz_base) { return fz_base > 0.0 ? fz_now / fz_base : 1.0; }

}  // namespace

PointSlips SolvePointSlips(std::span<const vehicle::InvertibleTyre> tyres,
                           const PointTargets& targets, const PointSlips& guess) {
  const auto& cond = targets.conditions;
  PointSlips out;
  out.solved = true;
  out.reached = true;
  // Front wheels roll or brake independently.
  for (const int k : {kFl, kFr}) {
    const vehicle::FreeWheelSolution s = vehicle::SolveFreeWheelSlips(
        tyres[k], cond[k], targets.fx[k], targets.fy[k], guess.wheels[k]);
    out.wheels[k] = s.wheel;
    out.front_jacobian[k == kFl ? 0 : 1] = s.jacobian;
    out.reached = out.reached && s.reached;
    out.force_deficit = std::max({out.force_deficit, std::abs(s.wheel.fx - targets.fx[k]),
                                  std::abs(s.wheel.fy - targets.fy[k])});
  }
  // Rear wheels turn together on the spool.
  vehicle::SpoolAxleSolution rear_guess;
  rear_guess.wheels = {guess.wheels[kRl], guess.wheels[kRr]};
  rear_guess.wheel_speed = guess.rear_wheel_speed;
  const double fx_total = targets.fx[kRl] + targets.fx[kRr];
  const vehicle::SpoolAxleSolution s =
      vehicle::SolveSpoolAxleSlips(tyres[kRl], tyres[kRr], cond[kRl], cond[kRr], targets.fy[kRl],
                                   targets.fy[kRr], fx_total, rear_guess);
  out.wheels[kRl] = s.wheels[0];
  out.wheels[kRr] = s.wheels[1];
  out.rear_wheel_speed = s.wheel_speed;
  out.rear_jacobian = s.jacobian;
  out.reached = out.reached && s.reached;
  out.force_deficit = std::max({out.force_deficit, std::abs(s.wheels[0].fy - targets.fy[kRl]),
                                std::abs(s.wheels[1].fy - targets.fy[kRr]),
                                std::abs(s.wheels[0].fx + s.wheels[1].fx - fx_total)});
  for (int k = 0; k < 4; ++k) out.fz[k] = cond[k].fz;
  return out;
}

PointSlips UpdatePointSlips(std::span<const vehicle::InvertibleTyre> tyres,
                            const PointTargets& targets, const PointSlips& base) {
  if (!base.solved || !base.reached) return SolvePointSlips(tyres, targets, base);
  const auto& cond = targets.conditions;
  PointSlips out = base;
  out.solved = false;
  out.force_deficit = 0.0;
  // Front wheels: (d kappa, d alpha) = J^-1 (target - base force at the new load).
  for (const int k : {kFl, kFr}) {
    const std::array<double, 4>& j = base.front_jacobian[k == kFl ? 0 : 1];
    const vehicle::WheelSlips& w = base.wheels[k];
    const double scale = LoadScale(cond[k].fz, base.fz[k]);
    const double rx = targets.fx[k] - scale * w.fx, ry = targets.fy[k] - scale * w.fy;
    const double det = j[0] * j[3] - j[1] * j[2];
    const double dk = (j[3] * rx - j[1] * ry) / det, da = (j[0] * ry - j[2] * rx) / det;
    // Past a force peak (ISO-W: Fy falls as alpha rises below it), or too far to go linearly.
    if (!(j[0] > 0.0 && j[3] < 0.0) || !(std::abs(dk) <= kMaxLinearStep) ||
        !(std::abs(da) <= kMaxLinearStep)) {
      return SolvePointSlips(tyres, targets, base);
    }
    out.wheels[k] = {w.slip_ratio + dk, w.slip_angle + da, targets.fx[k], targets.fy[k]};
  }
  // Rear axle: (ds, d alpha_left, d alpha_right) from the two Fy and the axle's Fx.
  const Eigen::Map<const Eigen::Matrix<double, 4, 3, Eigen::RowMajor>> j(base.rear_jacobian.data());
  const vehicle::WheelSlips& l = base.wheels[kRl];
  const vehicle::WheelSlips& r = base.wheels[kRr];
  const double scale_l = LoadScale(cond[kRl].fz, base.fz[kRl]);
  const double scale_r = LoadScale(cond[kRr].fz, base.fz[kRr]);
  Eigen::Matrix3d axle;
  axle << j.row(0), j.row(1), j.row(2) + j.row(3);
  const Eigen::Vector3d residual(
      targets.fy[kRl] - scale_l * l.fy, targets.fy[kRr] - scale_r * r.fy,
      targets.fx[kRl] + targets.fx[kRr] - scale_l * l.fx - scale_r * r.fx);
  const Eigen::Vector3d step = axle.partialPivLu().solve(residual);
  if (!(j(0, 1) < 0.0 && j(1, 2) < 0.0 && j(2, 0) > 0.0 && j(3, 0) > 0.0) ||
      !(step.cwiseAbs().maxCoeff() <= kMaxLinearStep)) {
    return SolvePointSlips(tyres, targets, base);
  }
  // The spool's slip s = omega R_mean / vx_mean - 1 at the base, from its wheel speed and the
  // wheels' slip ratios (kappa_i + 1 = (1 + s) (vx_mean / vx_i) (R_i / R_mean)).
  const double rl = tyres[kRl].setup->rolling_radius, rr = tyres[kRr].setup->rolling_radius;
  const double r_mean = 0.5 * (rl + rr);
  const double v_mean = 0.5 * (cond[kRl].vx + cond[kRr].vx);
  const double s_base = base.rear_wheel_speed * r_mean /
                            (0.5 * (base.rear_wheel_speed * rl / (l.slip_ratio + 1.0) +
                                    base.rear_wheel_speed * rr / (r.slip_ratio + 1.0))) -
                        1.0;
  const double omega = (1.0 + s_base + step[0]) * v_mean / r_mean;
  const Eigen::Vector3d dl = j.row(2), dr = j.row(3);
  out.rear_wheel_speed = omega;
  out.wheels[kRl] = {omega * rl / cond[kRl].vx - 1.0, l.slip_angle + step[1],
                     scale_l * l.fx + dl.dot(step), targets.fy[kRl]};
  out.wheels[kRr] = {omega * rr / cond[kRr].vx - 1.0, r.slip_angle + step[2],
                     scale_r * r.fx + dr.dot(step), targets.fy[kRr]};
  return out;
}

}  // namespace hotlap::sim
