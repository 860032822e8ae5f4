#include "hotlap/tyre/unitire.h"

#include <cmath>
#include <tuple>

namespace hotlap::tyre {

namespace {

static_assert(std::tuple_size_v<decltype(UniTireParams<double>::FieldsOf(
                      std::declval<UniTireParams<double>&>()))> == kUniTireFieldNames.size(),
              "kUniTireFieldNames must list every field of UniTireParams");

// |(x, y)| with a zero derivative at the origin, where the true derivative does not exist; every
// use is multiplied by a slip that vanishes there (see unitire.h).
template <Scalar T>
T SafeNorm(const T& x, const T& y) {
  using std::sqrt;
  const T r2 = x * x + y * y;
  if (!(ValueOf(r2) > 0.0)) return T(0.0);
  return sqrt(r2);
}

// sech(x) = 1 / cosh(x).
template <Scalar T>
T Sech(const T& x) {
  using std::cosh;
  return 1.0 / cosh(x);
}

// The normalised slip used once the slips are unbounded (locked wheel) or so large that
// Fbar = 1 in double: beyond 40, exp(-phi) < 5e-18.
constexpr double kSaturatedPhi = 40.0;

// V_s / V_m below this is taken as this inside the logarithm of the friction law.
constexpr double kMinSpeedRatio = 1e-9;

}  // namespace

template <Scalar T>
T CalcUniTireCorneringStiffness(const UniTireParams<T>& p, const T& fz, const T& camber,
                                const T& temp) {
  using std::sin;
  const T fzn = fz / p.nominal_load;
  const T s = sin(camber);
  // (001:11-13)
  return p.cornering_stiffness_per_load * fz *
         Sech(fzn * (p.cornering_stiffness_load_quad * fzn + p.cornering_stiffness_load_lin)) *
         (1.0 - p.cornering_stiffness_camber * s * s) *
         CalcTemperatureFactor(p.stiffness_temperature, temp);
}

template <Scalar T>
T CalcUniTireSlipStiffness(const UniTireParams<T>& p, const T& fz, const T& temp) {
  const T fzn = fz / p.nominal_load;
  return p.slip_stiffness_per_load * fz *
         Sech(fzn * (p.slip_stiffness_load_quad * fzn + p.slip_stiffness_load_lin)) *
         CalcTemperatureFactor(p.stiffness_temperature, temp);
}

template <Scalar T>
UniTireFriction<T> CalcUniTireFriction(const UniTireParams<T>& p, const T& fz,
                                       const T& sliding_speed, const T& temp) {
  using std::exp;
  using std::log;
  const T fzn = fz / p.nominal_load;
  T ratio = sliding_speed / p.friction_peak_speed;
  if (!(ValueOf(ratio) > kMinSpeedRatio)) ratio = T(kMinSpeedRatio);
  const T l = log(ratio);
  const T h = p.friction_speed_shape;
  const T speed =
      p.friction_sliding_ratio + (1.0 - p.friction_sliding_ratio) * exp(-(h * h) * (l * l));
  const T common = exp(-p.friction_load_decay * (fzn - 1.0)) * speed *
                   CalcTemperatureFactor(p.friction_temperature, temp);
  return {p.friction_x * common, p.friction_y * common};
}

template <Scalar T>
T CalcUniTireTrail(const UniTireParams<T>& p, const T& fz, const T& phi, const T& temp) {
  using std::exp;
  using std::log;
  const T fzn = fz / p.nominal_load;
  const T dx0 = p.trail * exp(p.trail_load_exponent * log(fzn));
  // (001:14-16)
  return ((dx0 + p.trail_offset) * exp(-phi * (p.trail_decay_lin + p.trail_decay_quad * phi)) -
          p.trail_offset) *
         CalcTemperatureFactor(p.trail_temperature, temp);
}

template <Scalar T>
T CalcUniTireResultantOverPhi(const T& phi, const T& e) {
  using std::expm1;
  // Exponent g = phi (1 + E phi + (E^2 + 1/12) phi^2) (001:10); g > 0 for phi > 0, any E.
  const T g_over_phi = 1.0 + phi * (e + (e * e + 1.0 / 12.0) * phi);
  const T g = phi * g_over_phi;
  // (1 - exp(-g)) / g: series below 1e-3 (next term g^5/720 < 2e-18), else expm1.
  T one_minus_exp_over_g;
  if (ValueOf(g) < 1e-3) {
    one_minus_exp_over_g = 1.0 + g * (-0.5 + g * (1.0 / 6.0 + g * (-1.0 / 24.0 + g / 120.0)));
  } else {
    one_minus_exp_over_g = -expm1(-g) / g;
  }
  return g_over_phi * one_minus_exp_over_g;
}

template <Scalar T>
TyreForces<T> CalcUniTireForces(const UniTireParams<T>& p, const TyreOperatingPoint<T>& op,
                                UniTireDetails<T>* details) {
  using std::abs;
  using std::tan;
  TyreForces<T> out;
  if (!(ValueOf(op.fz) > 0.0)) {
    if (details != nullptr) *details = UniTireDetails<T>{};
    return out;
  }
  const T& fz = op.fz;
  const T ky = CalcUniTireCorneringStiffness(p, fz, op.camber, op.tread_temp);
  const T kx = CalcUniTireSlipStiffness(p, fz, op.tread_temp);
  const T tan_alpha = tan(op.slip_angle);
  const T& kappa = op.slip_ratio;
  // Sliding speed |V_x - Omega R_e, -V_y| = |V_x| |(kappa, tan alpha)|.
  const T sliding_speed = abs(op.speed) * SafeNorm(kappa, tan_alpha);
  const UniTireFriction<T> mu = CalcUniTireFriction(p, fz, sliding_speed, op.tread_temp);

  // phi_i (1 + kappa): the normalised slips times the rolling-speed ratio, (001:10).
  const T nx = kx * kappa / (mu.x * fz);
  const T ny = -ky * tan_alpha / (mu.y * fz);
  const T n = SafeNorm(nx, ny);
  const T d = 1.0 + kappa;

  T phi_x(0.0), phi_y(0.0), phi, resultant;
  if (!(ValueOf(d) > 0.0) || ValueOf(n) >= kSaturatedPhi * ValueOf(d)) {
    // Locked wheel or full sliding: Fbar = 1 along the slip direction.
    phi = T(kSaturatedPhi);
    resultant = T(1.0);
    out.fx = mu.x * fz * nx / n;
    out.fy = mu.y * fz * ny / n;
  } else {
    phi_x = nx / d;
    phi_y = ny / d;
    phi = n / d;
    // Each direction with its own curvature: Fbar(phi; E_i) / phi (see unitire.h).
    const T qx = CalcUniTireResultantOverPhi(phi, p.curvature_x);
    const T qy = CalcUniTireResultantOverPhi(phi, p.curvature_y);
    out.fx = qx * mu.x * fz * phi_x;
    out.fy = qy * mu.y * fz * phi_y;
    // The resultant |(Fx / mu_x, Fy / mu_y)| / Fz.
    resultant = SafeNorm(qx * phi_x, qy * phi_y);
  }
  const T trail = CalcUniTireTrail(p, fz, phi, op.tread_temp);
  out.mz = -out.fy * trail;  // (001:10)
  if (details != nullptr) {
    details->cornering_stiffness = ky;
    details->slip_stiffness = kx;
    details->friction = mu;
    details->sliding_speed = sliding_speed;
    details->phi_x = phi_x;
    details->phi_y = phi_y;
    details->phi = phi;
    details->resultant = resultant;
    details->trail = trail;
  }
  return out;
}

#define HOTLAP_INSTANTIATE_UNITIRE(T)                                                             \
  template T CalcUniTireCorneringStiffness<T>(const UniTireParams<T>&, const T&, const T&,        \
                                              const T&);                                          \
  template T CalcUniTireSlipStiffness<T>(const UniTireParams<T>&, const T&, const T&);            \
  template UniTireFriction<T> CalcUniTireFriction<T>(const UniTireParams<T>&, const T&, const T&, \
                                                     const T&);                                   \
  template T CalcUniTireTrail<T>(const UniTireParams<T>&, const T&, const T&, const T&);          \
  template T CalcUniTireResultantOverPhi<T>(const T&, const T&);                                  \
  template TyreForces<T> CalcUniTireForces<T>(const UniTireParams<T>&,                            \
                                              const TyreOperatingPoint<T>&, UniTireDetails<T>*);

HOTLAP_FOR_EACH_SCALAR(HOTLAP_INSTANTIATE_UNITIRE)
// The optimal-control tyre element's scalar: tyre forces over (Fz, kappa, alpha).
HOTLAP_INSTANTIATE_UNITIRE(::hotlap::SecondOrder<3>)

}  // namespace hotlap::tyre
