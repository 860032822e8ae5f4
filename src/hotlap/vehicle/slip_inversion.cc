#include "hotlap/vehicle/slip_inversion.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace hotlap::vehicle {

namespace {

constexpr double kMaxSlipRatio = 0.6;
constexpr double kMaxSlipAngle = 0.5;

// Forces and their derivatives with respect to (slip ratio, slip angle).
struct TyreEval {
  double fx, fy;
  double dfx_dk, dfx_da, dfy_dk, dfy_da;
};

TyreEval Evaluate(const InvertibleTyre& tyre, const TyreConditions& c, double kappa, double alpha) {
  tyre::TyreOperatingPoint<Jet2> op;
  op.fz = Jet2(c.fz);
  op.slip_ratio = Jet2(kappa, 0);
  op.slip_angle = Jet2(alpha, 1);
  op.camber = Jet2(tyre.setup->camber);
  op.speed = Jet2(c.vx);
  op.pressure = Jet2(tyre.setup->pressure);
  op.tread_temp = Jet2(c.tread_temp);
  const tyre::TyreForces<Jet2> f = tyre::CalcTyreForces(tyre.model_jet, op);
  const double g = c.grip_factor;
  return {g * f.fx.a, g * f.fy.a, g * f.fx.v[0], g * f.fx.v[1], g * f.fy.v[0], g * f.fy.v[1]};
}

// Forces only, in double precision (grip factor applied).
std::array<double, 2> EvaluateForces(const InvertibleTyre& tyre, const TyreConditions& c,
                                     double kappa, double alpha) {
  tyre::TyreOperatingPoint<double> op;
  op.fz = c.fz;
  op.slip_ratio = kappa;
  op.slip_angle = alpha;
  op.camber = tyre.setup->camber;
  op.speed = c.vx;
  op.pressure = tyre.setup->pressure;
  op.tread_temp = c.tread_temp;
  const tyre::TyreForces<double> f = tyre::CalcTyreForces(tyre.setup->forces, op);
  return {c.grip_factor * f.fx, c.grip_factor * f.fy};
}

double FreeWheelTolerance(const TyreConditions& c) { return std::max(1.0, 1e-4 * c.fz); }

double SpoolTolerance(const TyreConditions& l, const TyreConditions& r) {
  return std::max(1.0, 1e-4 * (l.fz + r.fz));
}

// Levenberg-Marquardt on n unknowns with bounds (clamped steps). `residual(x, J, extra)` returns
// r, fills J and whatever the caller keeps per evaluation in `extra`. Returns the number of
// iterations; x and extra hold the best point's.
template <int N, class Extra, class Residual>
int SolveBounded(Eigen::Matrix<double, N, 1>& x, const Eigen::Matrix<double, N, 1>& lower,
                 const Eigen::Matrix<double, N, 1>& upper, double tolerance, Extra& extra,
                 Residual residual) {
  using Vec = Eigen::Matrix<double, N, 1>;
  using Mat = Eigen::Matrix<double, N, N>;
  Mat jac;
  Vec r = residual(x, jac, extra);
  double cost = r.squaredNorm();
  double lambda = 1e-4;
  int it = 0;
  for (; it < 40 && r.cwiseAbs().maxCoeff() > tolerance; ++it) {
    const Mat jtj = jac.transpose() * jac;
    const Vec g = jac.transpose() * r;
    bool improved = false;
    for (int attempt = 0; attempt < 12 && !improved; ++attempt) {
      Mat a = jtj;
      for (int i = 0; i < N; ++i) a(i, i) += lambda * std::max(jtj(i, i), 1e-12);
      const Vec step = a.ldlt().solve(-g);
      const Vec trial = (x + step).cwiseMax(lower).cwiseMin(upper);
      Mat trial_jac;
      Extra trial_extra;
      const Vec trial_r = residual(trial, trial_jac, trial_extra);
      const double trial_cost = trial_r.squaredNorm();
      if (std::isfinite(trial_cost) && trial_cost < cost) {
        x = trial;
        r = trial_r;
        jac = trial_jac;
        extra = trial_extra;
        cost = trial_cost;
        lambda = std::max(lambda / 5.0, 1e-9);
        improved = true;
      } else {
        lambda *= 8.0;
      }
    }
    if (!improved) break;  // at a (constrained) minimum that does not meet the targets
  }
  return it;
}

// Whether the tyre is below its force peaks at this point: the side force still grows with the
// slip angle (ISO-W: Fy falls as alpha rises) and the longitudinal force with the slip ratio.
bool OnRisingBranch(const TyreEval& e) { return e.dfy_da < 0.0 && e.dfx_dk > 0.0; }

// A starting point that does not depend on a previous solution: each slip from its own force
// alone, by the secant slope at a small slip scaled so that the linear estimate cannot pass the
// pure-slip peak region.
std::pair<double, double> FreshGuess(const InvertibleTyre& tyre, const TyreConditions& c,
                                     double fx_target, double fy_target) {
  const TyreEval e = Evaluate(tyre, c, 0.0, 0.0);
  const double kx = std::max(std::abs(e.dfx_dk), 1.0);
  const double ky = std::max(std::abs(e.dfy_da), 1.0);
  const double kappa = std::clamp((fx_target - e.fx) / kx, -0.08, 0.08);
  const double alpha = std::clamp(-(fy_target - e.fy) / ky, -0.08, 0.08);
  return {kappa, alpha};
}

}  // namespace

InvertibleTyre::InvertibleTyre(const CornerSetup& corner)
    : setup(&corner), model_jet(corner.forces.Cast<Jet2>()) {}

FreeWheelSolution SolveFreeWheelSlips(const InvertibleTyre& tyre, const TyreConditions& c,
                                      double fx_target, double fy_target, const WheelSlips& guess) {
  using Vec = Eigen::Vector2d;
  const double tolerance = FreeWheelTolerance(c);
  const auto residual = [&](const Vec& v, Eigen::Matrix2d& jac, TyreEval& e) {
    e = Evaluate(tyre, c, v[0], v[1]);
    jac << e.dfx_dk, e.dfx_da, e.dfy_dk, e.dfy_da;
    return Vec(e.fx - fx_target, e.fy - fy_target);
  };
  bool stable = true;  // of the last solve_from
  const auto solve_from = [&](double kappa, double alpha) {
    Vec x(std::clamp(kappa, -kMaxSlipRatio, kMaxSlipRatio),
          std::clamp(alpha, -kMaxSlipAngle, kMaxSlipAngle));
    FreeWheelSolution out;
    TyreEval e{};
    out.iterations = SolveBounded<2>(x, Vec(-kMaxSlipRatio, -kMaxSlipAngle),
                                     Vec(kMaxSlipRatio, kMaxSlipAngle), tolerance, e, residual);
    out.wheel = {x[0], x[1], e.fx, e.fy};
    out.jacobian = {e.dfx_dk, e.dfx_da, e.dfy_dk, e.dfy_da};
    out.reached =
        std::abs(e.fx - fx_target) <= tolerance && std::abs(e.fy - fy_target) <= tolerance;
    stable = OnRisingBranch(e);
    return out;
  };
  const auto error = [&](const FreeWheelSolution& s) {
    return std::hypot(s.wheel.fx - fx_target, s.wheel.fy - fy_target);
  };
  // From the previous solution first (cheap when the targets change little), else afresh; also
  // afresh when the continuation has carried the solution past the force peak: a force below the
  // peak is made at two slips, and the one beyond the peak (sliding, hot) is not what a driver
  // asks of the tyre.
  FreeWheelSolution best = solve_from(guess.slip_ratio, guess.slip_angle);
  if (!best.reached || !stable) {
    const auto [kappa, alpha] = FreshGuess(tyre, c, fx_target, fy_target);
    FreeWheelSolution fresh = solve_from(kappa, alpha);
    fresh.iterations += best.iterations;
    if (fresh.reached || (!best.reached && error(fresh) < error(best))) {
      best = fresh;
    }
  }
  return best;
}

SpoolAxleSolution SolveSpoolAxleSlips(const InvertibleTyre& left, const InvertibleTyre& right,
                                      const TyreConditions& cl, const TyreConditions& cr,
                                      double fy_left, double fy_right, double fx_total,
                                      const SpoolAxleSolution& guess) {
  using Vec = Eigen::Vector3d;
  const double rl = left.setup->rolling_radius, rr = right.setup->rolling_radius;
  // Unknowns: omega scaled as "slip of the mean wheel" s = omega R_mean / v_mean - 1, so that all
  // three are of order 0.1.
  const double r_mean = 0.5 * (rl + rr), v_mean = 0.5 * (cl.vx + cr.vx);
  const auto omega_of = [&](double s) { return (1.0 + s) * v_mean / r_mean; };
  double s0 = 0.0;
  if (guess.wheel_speed > 0.0) s0 = guess.wheel_speed * r_mean / v_mean - 1.0;
  const double tolerance = SpoolTolerance(cl, cr);
  const auto kappas = [&](double s) {
    const double omega = omega_of(s);
    return std::array<double, 2>{omega * rl / cl.vx - 1.0, omega * rr / cr.vx - 1.0};
  };
  // d kappa_i / d s = (v_mean / r_mean) R_i / vx_i.
  const double dkl = v_mean / r_mean * rl / cl.vx, dkr = v_mean / r_mean * rr / cr.vx;
  // Rows: fy_left, fy_right, fx_left, fx_right; columns: s, alpha_left, alpha_right.
  const auto jacobian = [&](const TyreEval& a, const TyreEval& b) {
    Eigen::Matrix<double, 4, 3, Eigen::RowMajor> jac;
    jac << a.dfy_dk * dkl, a.dfy_da, 0.0,  //
        b.dfy_dk * dkr, 0.0, b.dfy_da,     //
        a.dfx_dk * dkl, a.dfx_da, 0.0,     //
        b.dfx_dk * dkr, 0.0, b.dfx_da;
    return jac;
  };
  const auto residual = [&](const Vec& v, Eigen::Matrix3d& jac, std::array<TyreEval, 2>& ab) {
    const auto k = kappas(v[0]);
    ab[0] = Evaluate(left, cl, std::clamp(k[0], -0.99, 2.0), v[1]);
    ab[1] = Evaluate(right, cr, std::clamp(k[1], -0.99, 2.0), v[2]);
    const TyreEval& a = ab[0];
    const TyreEval& b = ab[1];
    const Eigen::Matrix<double, 4, 3, Eigen::RowMajor> wheels = jacobian(a, b);
    jac << wheels.row(0), wheels.row(1), wheels.row(2) + wheels.row(3);
    return Vec(a.fy - fy_left, b.fy - fy_right, a.fx + b.fx - fx_total);
  };
  bool stable = true;  // of the last solve_from
  const auto solve_from = [&](Vec x) {
    x = x.cwiseMax(Vec(-kMaxSlipRatio, -kMaxSlipAngle, -kMaxSlipAngle))
            .cwiseMin(Vec(kMaxSlipRatio, kMaxSlipAngle, kMaxSlipAngle));
    SpoolAxleSolution out;
    std::array<TyreEval, 2> ab{};
    out.iterations =
        SolveBounded<3>(x, Vec(-kMaxSlipRatio, -kMaxSlipAngle, -kMaxSlipAngle),
                        Vec(kMaxSlipRatio, kMaxSlipAngle, kMaxSlipAngle), tolerance, ab, residual);
    Eigen::Map<Eigen::Matrix<double, 4, 3, Eigen::RowMajor>>(out.jacobian.data()) =
        jacobian(ab[0], ab[1]);
    const auto k = kappas(x[0]);
    const TyreEval& a = ab[0];
    const TyreEval& b = ab[1];
    out.wheel_speed = omega_of(x[0]);
    out.wheels[0] = {k[0], x[1], a.fx, a.fy};
    out.wheels[1] = {k[1], x[2], b.fx, b.fy};
    out.reached = std::abs(a.fy - fy_left) <= tolerance && std::abs(b.fy - fy_right) <= tolerance &&
                  std::abs(a.fx + b.fx - fx_total) <= tolerance;
    stable = OnRisingBranch(a) && OnRisingBranch(b);
    return out;
  };
  const auto error = [&](const SpoolAxleSolution& s) {
    return std::hypot(s.wheels[0].fy - fy_left, s.wheels[1].fy - fy_right,
                      s.wheels[0].fx + s.wheels[1].fx - fx_total);
  };
  SpoolAxleSolution best =
      solve_from(Vec(s0, guess.wheels[0].slip_angle, guess.wheels[1].slip_angle));
  if (!best.reached || !stable) {  // afresh, as for a free wheel
    // Afresh: each wheel's slip angle from its own Fy, the axle slip from the mean Fx.
    const auto [kl, al] = FreshGuess(left, cl, 0.5 * fx_total, fy_left);
    const auto [kr, ar] = FreshGuess(right, cr, 0.5 * fx_total, fy_right);
    SpoolAxleSolution fresh = solve_from(Vec(0.5 * (kl + kr), al, ar));
    fresh.iterations += best.iterations;
    if (fresh.reached || (!best.reached && error(fresh) < error(best))) {
      best = fresh;
    }
  }
  return best;
}

bool RefineFreeWheelSlips(const InvertibleTyre& tyre, const TyreConditions& c, double fx_target,
                          double fy_target, const std::array<double, 4>& jacobian,
                          WheelSlips* slips, int max_steps) {
  const double tolerance = 0.1 * FreeWheelTolerance(c);
  const double det = jacobian[0] * jacobian[3] - jacobian[1] * jacobian[2];
  for (int step = 0; step <= max_steps; ++step) {
    const std::array<double, 2> f = EvaluateForces(tyre, c, slips->slip_ratio, slips->slip_angle);
    slips->fx = f[0];
    slips->fy = f[1];
    const double rx = fx_target - f[0], ry = fy_target - f[1];
    if (std::abs(rx) <= tolerance && std::abs(ry) <= tolerance) return true;
    if (step == max_steps || !(det != 0.0)) break;
    slips->slip_ratio = std::clamp(slips->slip_ratio + (jacobian[3] * rx - jacobian[1] * ry) / det,
                                   -kMaxSlipRatio, kMaxSlipRatio);
    slips->slip_angle = std::clamp(slips->slip_angle + (jacobian[0] * ry - jacobian[2] * rx) / det,
                                   -kMaxSlipAngle, kMaxSlipAngle);
  }
  return false;
}

bool RefineSpoolAxleSlips(const InvertibleTyre& left, const InvertibleTyre& right,
                          const TyreConditions& cl, const TyreConditions& cr, double fy_left,
                          double fy_right, double fx_total, const std::array<double, 12>& jacobian,
                          SpoolAxleSolution* axle, int max_steps) {
  const double rl = left.setup->rolling_radius, rr = right.setup->rolling_radius;
  const double r_mean = 0.5 * (rl + rr), v_mean = 0.5 * (cl.vx + cr.vx);
  const double tolerance = 0.1 * SpoolTolerance(cl, cr);
  const Eigen::Map<const Eigen::Matrix<double, 4, 3, Eigen::RowMajor>> wheels(jacobian.data());
  Eigen::Matrix3d jac;
  jac << wheels.row(0), wheels.row(1), wheels.row(2) + wheels.row(3);
  Eigen::Vector3d x(axle->wheel_speed * r_mean / v_mean - 1.0, axle->wheels[0].slip_angle,
                    axle->wheels[1].slip_angle);
  Eigen::Vector3d x_last = Eigen::Vector3d::Zero(), f_last = Eigen::Vector3d::Zero();
  for (int step = 0; step <= max_steps; ++step) {
    const double omega = (1.0 + x[0]) * v_mean / r_mean;
    const double kl = omega * rl / cl.vx - 1.0, kr = omega * rr / cr.vx - 1.0;
    const std::array<double, 2> a = EvaluateForces(left, cl, std::clamp(kl, -0.99, 2.0), x[1]);
    const std::array<double, 2> b = EvaluateForces(right, cr, std::clamp(kr, -0.99, 2.0), x[2]);
    axle->wheel_speed = omega;
    axle->wheels[0] = {kl, x[1], a[0], a[1]};
    axle->wheels[1] = {kr, x[2], b[0], b[1]};
    const Eigen::Vector3d forces(a[1], b[1], a[0] + b[0]);
    const Eigen::Vector3d r = Eigen::Vector3d(fy_left, fy_right, fx_total) - forces;
    // Met, and (by the Jacobian as updated) still below both wheels' force peaks.
    if (r.cwiseAbs().maxCoeff() <= tolerance) return jac(0, 1) < 0.0 && jac(1, 2) < 0.0;
    if (step == max_steps) break;
    if (step > 0) {  // Broyden's update, as for a free wheel
      const Eigen::Vector3d dx = x - x_last;
      jac += (forces - f_last - jac * dx) * dx.transpose() / dx.squaredNorm();
    }
    const Eigen::Vector3d dx = jac.partialPivLu().solve(r);
    if (!dx.allFinite() || dx.squaredNorm() == 0.0) break;
    x_last = x;
    f_last = forces;
    x = (x + dx)
            .cwiseMax(Eigen::Vector3d(-kMaxSlipRatio, -kMaxSlipAngle, -kMaxSlipAngle))
            .cwiseMin(Eigen::Vector3d(kMaxSlipRatio, kMaxSlipAngle, kMaxSlipAngle));
  }
  return false;
}

}  // namespace hotlap::vehicle
