#include "hotlap/tyre/brush_model.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace hotlap::tyre {

namespace {

// |(x, y)| with a zero derivative at the origin, where the true derivative does not exist. Every
// use multiplies the result (or a function of it) by a slip that vanishes there, so the
// derivatives of the model's outputs are exact (see the file comment of brush_model.h).
template <class S>
S SafeNorm(const S& x, const S& y) {
  using std::sqrt;
  const S r2 = x * x + y * y;
  if (!(ValueOf(r2) > 0.0)) return S(0.0);
  return sqrt(r2);
}

// The rigid-carcass brush at the bristle slips (kappa, u = tan(alpha')), given mu Fz, theta and a.
template <class S>
struct RigidBrush {
  S fx, fy, mz, psi;
};

template <class S>
RigidBrush<S> CalcRigidBrush(const S& mu_fz, const S& theta, const S& a, const S& kappa,
                             const S& u) {
  const S d = 1.0 + kappa;  // r omega / Vx; sigma = (kappa, u) / d
  const S n = SafeNorm(kappa, u);
  const S theta_n = theta * n;
  // Full sliding: psi = theta n / d >= 1, or a locked or reversing wheel (d <= 0). Then n > 0.
  if (!(ValueOf(d) > 0.0) || ValueOf(theta_n) >= ValueOf(d)) {
    return {mu_fz * kappa / n, -mu_fz * u / n, S(0.0), ValueOf(d) > 0.0 ? theta_n / d : S(1.0)};
  }
  const S sx = kappa / d;
  const S sy = u / d;
  const S psi = theta_n / d;
  // F / sigma = mu Fz theta (3 - 3 psi + psi^2), since 1 - (1 - psi)^3 = psi (3 - 3 psi + psi^2):
  // no division by sigma, so the small-slip limit needs no special case.
  const S f_over_sigma = mu_fz * theta * (3.0 + psi * (psi - 3.0));
  const S one_minus_psi = 1.0 - psi;
  const S cube = one_minus_psi * one_minus_psi * one_minus_psi;
  return {f_over_sigma * sx, -f_over_sigma * sy, mu_fz * a * theta * sy * cube, psi};
}

// Residual of the torsional fixed point, h(u) = u - tan(alpha) + Mz(u) / c_ct.
template <class S>
S FixedPointResidual(const S& mu_fz, const S& theta, const S& a, const S& kappa, const S& tan_alpha,
                     const S& inv_c_ct, const S& u) {
  return u - tan_alpha + CalcRigidBrush(mu_fz, theta, a, kappa, u).mz * inv_c_ct;
}

struct FixedPoint {
  double u = 0.0;
  double slope = 1.0;  // h'(u)
  int iterations = 0;
};

// Solves h(u) = 0 in double. The root lies between 0 and tan(alpha): with lo = min(0, tan(alpha))
// and hi = max(0, tan(alpha)), h(lo) <= 0 <= h(hi) because Mz has the sign of u. Newton steps are
// taken inside this bracket, which shrinks on the sign of h; a step that leaves it, or one that
// failed to halve |h|, is replaced by bisection. h and h' are returned at the final u.
FixedPoint SolveFixedPoint(double mu_fz, double theta, double a, double kappa, double tan_alpha,
                           double inv_c_ct) {
  using J = ceres::Jet<double, 1>;
  auto eval = [&](double u, double* h, double* dh) {
    const J r =
        FixedPointResidual(J(mu_fz), J(theta), J(a), J(kappa), J(tan_alpha), J(inv_c_ct), J(u, 0));
    *h = r.a;
    *dh = r.v[0];
  };
  FixedPoint out;
  double lo = std::min(0.0, tan_alpha);
  double hi = std::max(0.0, tan_alpha);
  // Start from the linear-range solution u = tan(alpha) / (1 + C_Fa t0 / c_ct), where
  // C_Fa t0 = 2 k a^3 / 3 = mu Fz theta a.
  double u = tan_alpha / (1.0 + mu_fz * theta * a * inv_c_ct);
  double h = 0.0, dh = 1.0;
  eval(u, &h, &dh);
  if (tan_alpha != 0.0 && inv_c_ct != 0.0) {
    const double tol = 1e-14 * std::abs(tan_alpha);
    constexpr int kMaxIterations = 100;
    bool bisect = false;
    while (out.iterations < kMaxIterations && std::abs(h) > tol &&
           hi - lo > 1e-15 * std::abs(tan_alpha)) {
      (h < 0.0 ? lo : hi) = u;
      double next = 0.5 * (lo + hi);
      if (!bisect && dh > 0.0) {
        const double newton = u - h / dh;
        if (newton > lo && newton < hi) next = newton;
      }
      const double h_old = h;
      u = next;
      eval(u, &h, &dh);
      bisect = std::abs(h) > 0.5 * std::abs(h_old);
      ++out.iterations;
    }
  }
  out.u = u;
  out.slope = dh;
  return out;
}

// Exponential of the power (x / x_ref)^n for x > 0, differentiable in n for Jets.
template <Scalar T>
T PowerRatio(const T& x, const T& x_ref, const T& n) {
  using std::exp;
  using std::log;
  return exp(n * log(x / x_ref));
}

}  // namespace

template <Scalar T>
T CalcContactHalfLength(const BrushParams<T>& params, const T& fz) {
  if (!(ValueOf(fz) > 0.0)) return T(0.0);
  return params.contact_half_length *
         PowerRatio(fz, params.reference_load, params.contact_length_exponent);
}

template <Scalar T>
T CalcCorneringStiffness(const BrushParams<T>& params, const T& fz, const T& temp) {
  const T a = CalcContactHalfLength(params, fz);
  return 2.0 * CalcBristleStiffness(params.rubber, temp) * a * a;  // (001:5), N -> infinity
}

template <Scalar T>
T CalcEffectiveCorneringStiffness(const BrushParams<T>& params, const T& fz, const T& temp) {
  const T c = CalcCorneringStiffness(params, fz, temp);
  const T t0 = CalcContactHalfLength(params, fz) / 3.0;
  const T c_ct = CalcTemperatureFactor(params.carcass_torsional_stiffness, temp);
  return c / (1.0 + c * t0 / c_ct);  // (001:3, 001:5)
}

template <Scalar T>
T CalcAligningStiffness(const BrushParams<T>& params, const T& fz, const T& temp) {
  const T c = CalcCorneringStiffness(params, fz, temp);
  const T t0 = CalcContactHalfLength(params, fz) / 3.0;
  const T c_ct = CalcTemperatureFactor(params.carcass_torsional_stiffness, temp);
  return c * t0 / (1.0 + c * t0 / c_ct);  // (001:5)
}

template <Scalar T>
T CalcRelaxationLength(const BrushParams<T>& params, const T& fz, const T& temp) {
  return CalcCorneringStiffness(params, fz, temp) /
         CalcTemperatureFactor(params.carcass_lateral_stiffness, temp);
}

template <Scalar T>
TyreForces<T> CalcBrushForces(const BrushParams<T>& params, const TyreOperatingPoint<T>& op,
                              BrushDetails<T>* details) {
  using std::tan;
  TyreForces<T> out;
  if (!(ValueOf(op.fz) > 0.0)) {
    if (details != nullptr) *details = BrushDetails<T>{};
    return out;
  }
  // Tread and contact at this load and temperature.
  const T a = CalcContactHalfLength(params, op.fz);
  const T k = CalcBristleStiffness(params.rubber, op.tread_temp);
  const T mu_fz = params.friction * op.fz;
  const T theta = 2.0 * a * a * k / (3.0 * mu_fz);
  const T c_ct = CalcTemperatureFactor(params.carcass_torsional_stiffness, op.tread_temp);
  const T inv_c_ct = 1.0 / c_ct;
  const T tan_alpha = tan(op.slip_angle);

  // Torsional fixed point tan(alpha') = tan(alpha) - Mz(alpha') / c_ct: converge in double, then
  // Newton (chord) steps in T from the converged value with its slope. The first makes the first
  // derivatives exact (implicit function: -dh / h'); each chord step raises the order of the
  // error in the perturbation by one, so a second one makes second derivatives exact too (the
  // SecondOrder scalar of the optimal control carries Hessians). In double, the converged value
  // is kept.
  const FixedPoint fp =
      SolveFixedPoint(ValueOf(mu_fz), ValueOf(theta), ValueOf(a), ValueOf(op.slip_ratio),
                      ValueOf(tan_alpha), ValueOf(inv_c_ct));
  T u(fp.u);
  if constexpr (!std::is_same_v<T, double>) {
    // Jets need first derivatives only: one step; SecondOrder carries Hessians: two.
    constexpr int kSteps = IsSecondOrder<T>::value ? 2 : 1;
    for (int step = 0; step < kSteps; ++step) {
      u -= FixedPointResidual(mu_fz, theta, a, op.slip_ratio, tan_alpha, inv_c_ct, u) / fp.slope;
    }
  }

  const RigidBrush<T> b = CalcRigidBrush(mu_fz, theta, a, op.slip_ratio, u);
  out.fx = b.fx;
  out.fy = b.fy;
  out.mz = b.mz;
  if (details != nullptr) {
    details->half_length = a;
    details->bristle_stiffness = k;
    details->theta = theta;
    details->tan_effective_slip_angle = u;
    details->psi = b.psi;
    details->newton_iterations = fp.iterations;
  }
  return out;
}

#define HOTLAP_INSTANTIATE_BRUSH_MODEL(T)                                                        \
  template T CalcContactHalfLength<T>(const BrushParams<T>&, const T&);                          \
  template T CalcCorneringStiffness<T>(const BrushParams<T>&, const T&, const T&);               \
  template T CalcEffectiveCorneringStiffness<T>(const BrushParams<T>&, const T&, const T&);      \
  template T CalcAligningStiffness<T>(const BrushParams<T>&, const T&, const T&);                \
  template T CalcRelaxationLength<T>(const BrushParams<T>&, const T&, const T&);                 \
  template TyreForces<T> CalcBrushForces<T>(const BrushParams<T>&, const TyreOperatingPoint<T>&, \
                                            BrushDetails<T>*);

HOTLAP_FOR_EACH_SCALAR(HOTLAP_INSTANTIATE_BRUSH_MODEL)
// The optimal-control tyre element's scalar: tyre forces over (Fz, kappa, alpha).
HOTLAP_INSTANTIATE_BRUSH_MODEL(::hotlap::SecondOrder<3>)

}  // namespace hotlap::tyre
