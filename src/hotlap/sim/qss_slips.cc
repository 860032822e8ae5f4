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
// The largest step checked (vehicle::Refine*Slips) rather than solved.
constexpr double kMaxCheckedStep = 2e-2;

// How a unit's first-order update went.
enum class Update {
  kTaken,  // a small step from a good base
  kCheck,  // a good base, but a step too large to take unchecked
  kSolve,  // a base that was no solve, missed its targets or lies past a force peak, or a step
};

// The load's share of a force change at fixed slips: the force in proportion to the load.
double LoadScale(double fz_now, double fz_base) { return fz_base > 0.0 ? fz_now / fz_base : 1.0; }

}  // namespace

namespace {

// Solves one front wheel (index k) of `out` from `guess`.
void SolveFront(std::span<const vehicle::InvertibleTyre> tyres, const PointTargets& targets, int k,
                const vehicle::WheelSlips& guess, PointSlips& out) {
  const int unit = k == kFl ? PointSlips::kFrontLeftUnit : PointSlips::kFrontRightUnit;
  const vehicle::FreeWheelSolution s = vehicle::SolveFreeWheelSlips(
      tyres[k], targets.conditions[k], targets.fx[k], targets.fy[k], guess);
  out.wheels[k] = s.wheel;
  out.front_jacobian[unit] = s.jacobian;
  out.fz[k] = targets.conditions[k].fz;
  out.solved[unit] = true;
  out.reached[unit] = s.reached;
  out.force_deficit = std::max({out.force_deficit, std::abs(s.wheel.fx - targets.fx[k]),
                                std::abs(s.wheel.fy - targets.fy[k])});
}

// Solves the rear axle of `out` from `guess`'s rear wheels and wheel speed.
void SolveRear(std::span<const vehicle::InvertibleTyre> tyres, const PointTargets& targets,
               const PointSlips& guess, PointSlips& out) {
  const auto& cond = targets.conditions;
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
  out.fz[kRl] = cond[kRl].fz;
  out.fz[kRr] = cond[kRr].fz;
  out.solved[PointSlips::kRearAxleUnit] = true;
  out.reached[PointSlips::kRearAxleUnit] = s.reached;
  out.force_deficit = std::max({out.force_deficit, std::abs(s.wheels[0].fy - targets.fy[kRl]),
                                std::abs(s.wheels[1].fy - targets.fy[kRr]),
                                std::abs(s.wheels[0].fx + s.wheels[1].fx - fx_total)});
}

// The first-order update of front wheel k from `base` into `out` (out then holds the step's
// slips, also where it is not taken: a check's or a solve's starting point).
Update UpdateFront(const PointTargets& targets, int k, const PointSlips& base, PointSlips& out) {
  const int unit = k == kFl ? PointSlips::kFrontLeftUnit : PointSlips::kFrontRightUnit;
  const std::array<double, 4>& j = base.front_jacobian[unit];
  const vehicle::WheelSlips& w = base.wheels[k];
  const double scale = LoadScale(targets.conditions[k].fz, base.fz[k]);
  const double rx = targets.fx[k] - scale * w.fx, ry = targets.fy[k] - scale * w.fy;
  const double det = j[0] * j[3] - j[1] * j[2];
  const double dk = (j[3] * rx - j[1] * ry) / det, da = (j[0] * ry - j[2] * rx) / det;
  out.solved[unit] = false;
  out.reached[unit] = true;
  out.wheels[k] = {w.slip_ratio + dk, w.slip_angle + da, targets.fx[k], targets.fy[k]};
  if (!std::isfinite(dk) || !std::isfinite(da)) out.wheels[k] = w;
  // Past a force peak: ISO-W, Fy falls as alpha rises below it.
  if (!(base.solved[unit] && base.reached[unit] && j[0] > 0.0 && j[3] < 0.0)) {
    return Update::kSolve;
  }
  const double step = std::max(std::abs(dk), std::abs(da));
  return step <= kMaxLinearStep    ? Update::kTaken
         : step <= kMaxCheckedStep ? Update::kCheck
                                   : Update::kSolve;
}

// The first-order update of the rear axle from `base` into `out`, as UpdateFront.
Update UpdateRear(std::span<const vehicle::InvertibleTyre> tyres, const PointTargets& targets,
                  const PointSlips& base, PointSlips& out) {
  const auto& cond = targets.conditions;
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
  const int unit = PointSlips::kRearAxleUnit;
  out.solved[unit] = false;
  out.reached[unit] = true;
  if (!step.allFinite()) return Update::kSolve;
  // The spool's slip s = omega R_mean / vx_mean - 1 at the base, from its wheel speed and the
  // wheels' slip ratios (vx_i = omega R_i / (kappa_i + 1)); at a given s a wheel's slip ratio
  // depends on the wheels' speeds only through their ratio.
  const double rl = tyres[kRl].setup->rolling_radius, rr = tyres[kRr].setup->rolling_radius;
  const double r_mean = 0.5 * (rl + rr);
  const double omega_base = base.rear_wheel_speed;
  const double v_mean_base =
      0.5 * (omega_base * rl / (l.slip_ratio + 1.0) + omega_base * rr / (r.slip_ratio + 1.0));
  const double s_base = omega_base * r_mean / v_mean_base - 1.0;
  const double omega = (1.0 + s_base + step[0]) * 0.5 * (cond[kRl].vx + cond[kRr].vx) / r_mean;
  const Eigen::Vector3d dl = j.row(2), dr = j.row(3);
  out.rear_wheel_speed = omega;
  out.wheels[kRl] = {omega * rl / cond[kRl].vx - 1.0, l.slip_angle + step[1],
                     scale_l * l.fx + dl.dot(step), targets.fy[kRl]};
  out.wheels[kRr] = {omega * rr / cond[kRr].vx - 1.0, r.slip_angle + step[2],
                     scale_r * r.fx + dr.dot(step), targets.fy[kRr]};
  if (!(base.solved[unit] && base.reached[unit] && j(0, 1) < 0.0 && j(1, 2) < 0.0 &&
        j(2, 0) > 0.0 && j(3, 0) > 0.0 && std::isfinite(omega))) {
    return Update::kSolve;
  }
  const double size = step.cwiseAbs().maxCoeff();
  return size <= kMaxLinearStep    ? Update::kTaken
         : size <= kMaxCheckedStep ? Update::kCheck
                                   : Update::kSolve;
}

}  // namespace

PointSlips SolvePointSlips(std::span<const vehicle::InvertibleTyre> tyres,
                           const PointTargets& targets, const PointSlips& guess) {
  PointSlips out;
  // Front wheels roll or brake independently; the rear wheels turn together on the spool.
  for (const int k : {kFl, kFr}) SolveFront(tyres, targets, k, guess.wheels[k], out);
  SolveRear(tyres, targets, guess, out);
  return out;
}

PointSlips UpdatePointSlips(std::span<const vehicle::InvertibleTyre> tyres,
                            const PointTargets& targets, PointSlips& base) {
  const auto& cond = targets.conditions;
  PointSlips out = base;
  out.force_deficit = 0.0;
  for (const int k : {kFl, kFr}) {
    const int unit = k == kFl ? PointSlips::kFrontLeftUnit : PointSlips::kFrontRightUnit;
    const Update update = UpdateFront(targets, k, base, out);
    if (update == Update::kTaken) continue;
    if (update == Update::kCheck &&
        vehicle::RefineFreeWheelSlips(tyres[k], cond[k], targets.fx[k], targets.fy[k],
                                      base.front_jacobian[unit], &out.wheels[k])) {
      out.force_deficit = std::max({out.force_deficit, std::abs(out.wheels[k].fx - targets.fx[k]),
                                    std::abs(out.wheels[k].fy - targets.fy[k])});
      continue;
    }
    SolveFront(tyres, targets, k, base.wheels[k], out);  // from the last profile's slips
    base.wheels[k] = out.wheels[k];
    base.front_jacobian[unit] = out.front_jacobian[unit];
    base.fz[k] = out.fz[k];
    base.solved[unit] = true;
    base.reached[unit] = out.reached[unit];
  }
  const Update update = UpdateRear(tyres, targets, base, out);
  if (update == Update::kTaken) return out;
  if (update == Update::kCheck) {
    vehicle::SpoolAxleSolution axle;
    axle.wheels = {out.wheels[kRl], out.wheels[kRr]};
    axle.wheel_speed = out.rear_wheel_speed;
    const double fx_total = targets.fx[kRl] + targets.fx[kRr];
    if (vehicle::RefineSpoolAxleSlips(tyres[kRl], tyres[kRr], cond[kRl], cond[kRr], targets.fy[kRl],
                                      targets.fy[kRr], fx_total, base.rear_jacobian, &axle)) {
      out.wheels[kRl] = axle.wheels[0];
      out.wheels[kRr] = axle.wheels[1];
      out.rear_wheel_speed = axle.wheel_speed;
      out.force_deficit =
          std::max({out.force_deficit, std::abs(axle.wheels[0].fy - targets.fy[kRl]),
                    std::abs(axle.wheels[1].fy - targets.fy[kRr]),
                    std::abs(axle.wheels[0].fx + axle.wheels[1].fx - fx_total)});
      return out;
    }
  }
  SolveRear(tyres, targets, base, out);  // from the last profile's slips
  base.wheels[kRl] = out.wheels[kRl];
  base.wheels[kRr] = out.wheels[kRr];
  base.rear_wheel_speed = out.rear_wheel_speed;
  base.rear_jacobian = out.rear_jacobian;
  base.fz[kRl] = out.fz[kRl];
  base.fz[kRr] = out.fz[kRr];
  base.solved[PointSlips::kRearAxleUnit] = true;
  base.reached[PointSlips::kRearAxleUnit] = out.reached[PointSlips::kRearAxleUnit];
  return out;
}

}  // namespace hotlap::sim
