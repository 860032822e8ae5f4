#pragma once
/// @file
/// The UniTire steady-state model with temperature-dependent cornering stiffness and pneumatic
/// trail (001 §5, 001:10-16; spec section 7).
///
/// How to use: fill UniTireParams (or load them with LoadUniTireParams,
/// tyre_force_params_io.h) and call CalcUniTireForces with a TyreOperatingPoint whose
/// `tread_temp` is set (kelvin). To fit, cast with `params.Cast<Jet>()` (see
/// ident/unitire_fit.h). The model uses fz, slip_ratio, slip_angle, camber, speed and tread_temp;
/// pressure is ignored.
///
/// The model, in the signs of tyre_force.h:
/// - Slips relative to the rolling speed Omega R_e = V_x (1 + kappa):
///     S_x = (Omega R_e - V_x) / (Omega R_e) = kappa / (1 + kappa),
///     S_y = -V_y / (Omega R_e) = -tan(alpha) / (1 + kappa),
///   using kappa = (Omega R_e - V_x) / V_x and tan(alpha) = V_y / V_x; so S_y < 0 and Fy < 0 for
///   alpha > 0, and S_x > 0 and Fx > 0 when driving. A locked or reversing wheel
///   (1 + kappa <= 0) has unbounded slips and is taken as full sliding along (kappa, -tan alpha).
/// - Normalised slips phi_x = K_x S_x / (mu_x Fz), phi_y = K_y S_y / (mu_y Fz),
///   phi = |(phi_x, phi_y)| (001:10).
/// - Resultant Fbar(phi; E) = 1 - exp(-phi - E phi^2 - (E^2 + 1/12) phi^3) (001:10). The
///   exponent's polynomial is increasing for every E, so Fbar rises monotonically from 0 to 1.
/// - Fx = Fbar(phi; E_x) mu_x Fz phi_x / phi, Fy = Fbar(phi; E_y) mu_y Fz phi_y / phi: each
///   direction takes its own curvature at the combined phi (this project's choice; with
///   E_x = E_y it is the single resultant of 001:10, and (Fx / mu_x)^2 + (Fy / mu_y)^2 <= Fz^2
///   always). For E < 1/2, Fbar / phi falls with phi, so adding slip in one direction lowers the
///   force in the other. Fbar / phi is evaluated from its series near phi = 0, so value and
///   derivatives are finite at zero slip. Fbar(phi) ~ phi + (E - 1/2) phi^2 makes the force C1
///   but not C2 in the slip at zero slip (the second derivative jumps by 2 (E - 1/2)).
/// - Mz = -Fy D_x, D_x = [(D_x0 + D_e) exp(-D1 phi - D2 phi^2) - D_e] f_D(T) (001:10, 001:14-16),
///   with D_x0 = d_0 (Fz / Fz_n)^q (this project's load law; the paper prints none). The moment
///   of Fx about the deflected contact centre is not modelled (the paper's model is cornering
///   only).
/// - K_y = s11 Fz sech(s12 Fzn^2 + s13 Fzn) (1 - s14 sin^2 gamma) f_K(T) (001:11-13),
///   Fzn = Fz / Fz_n. Camber only lowers K_y, as printed; no camber thrust is modelled.
/// - K_x = sx1 Fz sech(sx2 Fzn^2 + sx3 Fzn) f_K(T): this project's form, the load law of K_y
///   without camber and with the same temperature factor (the brush model's bristles are
///   isotropic and the paper measured cornering only).
/// - Friction mu_i = mu_i0 exp(-c_mu (Fzn - 1)) [r + (1 - r) exp(-h^2 ln^2(V_s / V_m))] f_mu(T)
///   for i = x, y: a smooth fall with load (this project's form), the UniTire sliding-speed law
///   of spec section 7 written with r = mu_s / mu_m (so mu_i0 is the peak, at V_s = V_m), and
///   sliding speed V_s = |V_x| |(kappa, tan alpha)|. V_s / V_m is floored at 1e-9 inside the
///   logarithm, which changes mu by less than exp(-429 h^2) of its range and keeps zero slip
///   finite. The paper fits no temperature factor on friction (its rig stayed within 2 deg of
///   slip); f_mu is provided with default b = 0 for tyres that need one.
/// - Temperature factors f(T) = a exp(-b (T - T_ref)) (rubber.h) on stiffness (001:12-13), trail
///   (001:15-16) and friction. The factor's `a` is redundant with s11 (and with d_0 and D_e) at
///   a fixed T_ref; fits hold a = 1.
///
/// Smoothness: C-infinity in slips and parameters except at zero slip (phi's cone point, entering
/// only multiplied by vanishing slips, so Fx, Fy and Mz are C1 there and their derivatives are
/// exact; see above for the second derivative), at Fz = 0 (zero forces below it), at
/// 1 + kappa = 0, where phi reaches 40 (taken as full sliding: Fbar = 1 within 5e-18) and where
/// V_s / V_m crosses the 1e-9 floor.

#include <array>
#include <string_view>
#include <tuple>

#include "hotlap/common/field_cast.h"
#include "hotlap/common/scalar.h"
#include "hotlap/tyre/rubber.h"
#include "hotlap/tyre/tyre_force.h"

namespace hotlap::tyre {

/// Parameters of the UniTire model; SI units, angles in rad, temperatures in K.
template <Scalar T>
struct UniTireParams {
  T nominal_load{};  ///< Fz_n, N
  // Cornering stiffness K_y (001:11).
  T cornering_stiffness_per_load{};   ///< s11, 1/rad: K_y / Fz as Fz -> 0
  T cornering_stiffness_load_quad{};  ///< s12, 1
  T cornering_stiffness_load_lin{};   ///< s13, 1
  T cornering_stiffness_camber{};     ///< s14, 1: K_y falls by s14 sin^2(gamma)
  // Longitudinal slip stiffness K_x (this project's form, see the file comment).
  T slip_stiffness_per_load{};   ///< sx1, 1: K_x / Fz as Fz -> 0
  T slip_stiffness_load_quad{};  ///< sx2, 1
  T slip_stiffness_load_lin{};   ///< sx3, 1
  // Friction.
  T friction_x{};              ///< mu_x0, 1: peak longitudinal friction at Fz_n
  T friction_y{};              ///< mu_y0, 1: peak lateral friction at Fz_n
  T friction_load_decay{};     ///< c_mu, 1: mu ~ exp(-c_mu (Fzn - 1))
  T friction_sliding_ratio{};  ///< r = mu_s / mu_m, 1 (1: no sliding-speed effect)
  T friction_peak_speed{};     ///< V_m, m/s: sliding speed of the peak
  T friction_speed_shape{};    ///< h, 1
  // Curvature of Fbar (001:10).
  T curvature_x{};  ///< E_x, 1
  T curvature_y{};  ///< E_y, 1
  // Pneumatic trail (001:10, 001:14).
  T trail{};                ///< d_0, m: D_x0 at Fz_n
  T trail_load_exponent{};  ///< q, 1: D_x0 = d_0 Fzn^q
  T trail_offset{};         ///< D_e, m: D_x -> -D_e at large slip
  T trail_decay_lin{};      ///< D1, 1
  T trail_decay_quad{};     ///< D2, 1
  // Temperature factors (001:12-13, 001:15-16).
  TemperatureFactor<T> stiffness_temperature;  ///< f_K(T) on K_y and K_x, 1
  TemperatureFactor<T> trail_temperature;      ///< f_D(T) on D_x, 1
  TemperatureFactor<T> friction_temperature;   ///< f_mu(T) on mu_x and mu_y, 1

  template <class Self>
  static auto FieldsOf(Self& s) {
    return std::tuple_cat(
        std::tie(s.nominal_load, s.cornering_stiffness_per_load, s.cornering_stiffness_load_quad,
                 s.cornering_stiffness_load_lin, s.cornering_stiffness_camber,
                 s.slip_stiffness_per_load, s.slip_stiffness_load_quad, s.slip_stiffness_load_lin,
                 s.friction_x, s.friction_y, s.friction_load_decay, s.friction_sliding_ratio,
                 s.friction_peak_speed, s.friction_speed_shape, s.curvature_x, s.curvature_y,
                 s.trail, s.trail_load_exponent, s.trail_offset, s.trail_decay_lin,
                 s.trail_decay_quad),
        TemperatureFactor<T>::FieldsOf(s.stiffness_temperature),
        TemperatureFactor<T>::FieldsOf(s.trail_temperature),
        TemperatureFactor<T>::FieldsOf(s.friction_temperature));
  }
  /// The same parameters in another scalar type (derivative parts start at zero).
  template <Scalar U>
  UniTireParams<U> Cast() const {
    UniTireParams<U> out;
    CastFields(*this, out);
    return out;
  }
};

/// The names of UniTireParams' fields in FieldsOf order (nested factors as
/// `stiffness_temperature.decay`), for fit reports and for choosing which fields a fit frees.
inline constexpr std::array<std::string_view, 30> kUniTireFieldNames = {
    "nominal_load",
    "cornering_stiffness_per_load",
    "cornering_stiffness_load_quad",
    "cornering_stiffness_load_lin",
    "cornering_stiffness_camber",
    "slip_stiffness_per_load",
    "slip_stiffness_load_quad",
    "slip_stiffness_load_lin",
    "friction_x",
    "friction_y",
    "friction_load_decay",
    "friction_sliding_ratio",
    "friction_peak_speed",
    "friction_speed_shape",
    "curvature_x",
    "curvature_y",
    "trail",
    "trail_load_exponent",
    "trail_offset",
    "trail_decay_lin",
    "trail_decay_quad",
    "stiffness_temperature.scale",
    "stiffness_temperature.decay",
    "stiffness_temperature.reference_temp",
    "trail_temperature.scale",
    "trail_temperature.decay",
    "trail_temperature.reference_temp",
    "friction_temperature.scale",
    "friction_temperature.decay",
    "friction_temperature.reference_temp",
};

/// Friction coefficients at one load, sliding speed and temperature.
template <Scalar T>
struct UniTireFriction {
  T x{};  ///< mu_x, 1
  T y{};  ///< mu_y, 1
};

/// Intermediate results of one CalcUniTireForces evaluation, for diagnostics and tests.
template <Scalar T>
struct UniTireDetails {
  T cornering_stiffness{};  ///< K_y, N/rad (with camber and temperature)
  T slip_stiffness{};       ///< K_x, N (with temperature)
  UniTireFriction<T> friction;
  T sliding_speed{};  ///< V_s, m/s
  T phi_x{};          ///< 1 (0 when saturated)
  T phi_y{};          ///< 1 (0 when saturated)
  T phi{};            ///< 1 (a large value when saturated)
  T resultant{};      ///< |(Fx / mu_x, Fy / mu_y)| / Fz, 1 (Fbar when E_x = E_y)
  T trail{};          ///< D_x, m
};

/// Cornering stiffness K_y = -dFy/d(tan alpha) at zero slip, N/rad (001:11-13).
template <Scalar T>
T CalcUniTireCorneringStiffness(const UniTireParams<T>& params, const T& fz, const T& camber,
                                const T& temp);

/// Longitudinal slip stiffness K_x = dFx/dkappa at zero slip, N.
template <Scalar T>
T CalcUniTireSlipStiffness(const UniTireParams<T>& params, const T& fz, const T& temp);

/// Friction coefficients at load `fz` (N), sliding speed `sliding_speed` (m/s) and `temp` (K).
template <Scalar T>
UniTireFriction<T> CalcUniTireFriction(const UniTireParams<T>& params, const T& fz,
                                       const T& sliding_speed, const T& temp);

/// Pneumatic trail D_x at normalised slip `phi`, m (001:14-16).
template <Scalar T>
T CalcUniTireTrail(const UniTireParams<T>& params, const T& fz, const T& phi, const T& temp);

/// Fbar(phi) / phi for phi >= 0 with curvature E (001:10); 1 at phi = 0, smooth there.
template <Scalar T>
T CalcUniTireResultantOverPhi(const T& phi, const T& curvature);

/// Steady-state Fx, Fy and Mz of the UniTire model at `op` (see the file comment); mx and my are
/// zero. Zero forces for Fz <= 0. If `details` is given, intermediate results are written there.
template <Scalar T>
TyreForces<T> CalcUniTireForces(const UniTireParams<T>& params, const TyreOperatingPoint<T>& op,
                                UniTireDetails<T>* details = nullptr);

}  // namespace hotlap::tyre
