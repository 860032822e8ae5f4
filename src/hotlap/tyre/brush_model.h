#pragma once
/// @file
/// The brush tyre model with a temperature-dependent tread and a compliant carcass (001 §4;
/// spec section 7): forces and aligning moment in steady state, and the stiffnesses and
/// relaxation length that follow from it.
///
/// How to use: fill BrushParams (or load them with LoadBrushParams, tyre_force_params_io.h) and
/// call CalcBrushForces with a TyreOperatingPoint whose `tread_temp` is set (kelvin). The model
/// uses `fz`, `slip_ratio`, `slip_angle` and `tread_temp`; camber, speed and pressure are ignored.
///
/// The model, in the signs of tyre_force.h (alpha > 0 gives Fy < 0 and Mz > 0):
/// - Contact half-length `a = a_ref (Fz / Fz_ref)^n` (a power law in the load, as the contact
///   length of (000:14); n = 0 gives the constant `a` of the textbook model).
/// - Bristle stiffness `k = p_g G(T)` (001:1-2), the same along x and y (isotropic bristles), one
///   friction coefficient `mu` for both directions, parabolic pressure.
/// - Combined slip by the theoretical slips `sigma_x = kappa / (1 + kappa)`,
///   `sigma_y = tan(alpha') / (1 + kappa)`, `sigma = |(sigma_x, sigma_y)|` (Pacejka, Tyre and
///   Vehicle Dynamics, 3rd ed., §3.2.5). With `theta = 2 a^2 k / (3 mu Fz)` and
///   `psi = theta sigma`, for psi < 1
///     F = mu Fz (1 - (1 - psi)^3),  Fx = F sigma_x / sigma,  Fy = -F sigma_y / sigma,
///     Mz = mu Fz a theta sigma_y (1 - psi)^3,
///   and for psi >= 1 (full sliding) F = mu Fz along the slip and Mz = 0. For pure side slip
///   this is spec section 7's textbook brush; the pneumatic trail is
///   t = (a/3) (1 - psi)^3 / (1 - psi + psi^2/3).
/// - Carcass torsion (001 Fig. 17): the aligning moment turns the tread base through
///   `Mz / c_ct(T)` towards the direction of travel, so the bristles see
///   `tan(alpha') = tan(alpha) - Mz(alpha') / c_ct(T)`. The spec writes `+ Mz / c_ct` with Mz
///   counted positive in the aligning sense against alpha; in these axes Mz > 0 for alpha > 0,
///   hence the minus, which gives the paper's reduced stiffness (001:3, 001:5)
///   `C'_Fa = C_Fa / (1 + C_Fa t0 / c_ct)`, t0 = a/3.
/// - Carcass lateral translation `c_cy(T)` leaves the steady force unchanged; it sets the
///   relaxation length `sigma_y = C_Fa / c_cy` for transient slip (CalcRelaxationLength).
/// - Both carcass stiffnesses are `c(T) = c_0 exp(-b (T - T_ref))` (001:6, Figs 15-16), taken
///   at the tread temperature (the paper's tyres were soaked to one uniform temperature).
///
/// Smoothness (for optimisers): every output is twice continuously differentiable in the slips
/// and parameters except (1) at psi = 1, the onset of full sliding, where F and Mz are C2 but
/// their third derivatives jump (the cubic `(1 - psi)^3` meets a constant), (2) at zero slip,
/// where sigma = |(sigma_x, sigma_y)| has a cone point but enters only multiplied by slips that
/// vanish there, so Fx, Fy and Mz stay smooth and derivatives are exact, (3) at Fz = 0 (zero
/// forces below it) and (4) at a locked or reversing wheel, 1 + kappa <= 0, taken as full sliding.
///
/// Torsional fixed point: solved in double by safeguarded Newton iteration inside the bracket
/// [0, tan(alpha)] (Mz has the sign of tan(alpha')), then chord steps (the converged slope) are
/// taken in the scalar type T from the converged value: one for Jets, which carries the
/// implicit-function derivative d(tan alpha') = -dh / h' exactly, and a second for SecondOrder,
/// which makes second derivatives exact too. If
/// `C_Fa t0 / c_ct >= 4` the fixed point may have several roots (h' can change sign); the
/// bracketed iteration returns one of them. Realistic tyres have C_Fa t0 / c_ct of order 1.

#include <tuple>

#include "hotlap/common/field_cast.h"
#include "hotlap/common/scalar.h"
#include "hotlap/tyre/rubber.h"
#include "hotlap/tyre/tyre_force.h"

namespace hotlap::tyre {

/// Parameters of the brush model; SI units, temperatures in K.
template <Scalar T>
struct BrushParams {
  T contact_half_length{};      ///< a_ref, m: half the contact length at the reference load
  T reference_load{};           ///< Fz_ref, N
  T contact_length_exponent{};  ///< n, 1: a = a_ref (Fz / Fz_ref)^n
  RubberParams<T> rubber;       ///< tread rubber: k = p_g G(T) (001:1-2)
  T friction{};                 ///< mu, 1, the same along x and y
  /// c_cy(T), N/m: carcass lateral translation stiffness (001 Fig. 15).
  TemperatureFactor<T> carcass_lateral_stiffness;
  /// c_ct(T), N m/rad: carcass torsional stiffness (001:6, Fig. 16).
  TemperatureFactor<T> carcass_torsional_stiffness;

  template <class Self>
  static auto FieldsOf(Self& s) {
    return std::tuple_cat(
        std::tie(s.contact_half_length, s.reference_load, s.contact_length_exponent),
        RubberParams<T>::FieldsOf(s.rubber), std::tie(s.friction),
        TemperatureFactor<T>::FieldsOf(s.carcass_lateral_stiffness),
        TemperatureFactor<T>::FieldsOf(s.carcass_torsional_stiffness));
  }
  /// The same parameters in another scalar type (derivative parts start at zero).
  template <Scalar U>
  BrushParams<U> Cast() const {
    BrushParams<U> out;
    CastFields(*this, out);
    return out;
  }
};

/// Intermediate results of one CalcBrushForces evaluation, for diagnostics and tests.
template <Scalar T>
struct BrushDetails {
  T half_length{};               ///< a, m
  T bristle_stiffness{};         ///< k, N/m^2
  T theta{};                     ///< 2 a^2 k / (3 mu Fz), 1
  T tan_effective_slip_angle{};  ///< tan(alpha') after the torsional fixed point, 1
  T psi{};                       ///< theta sigma, 1 (>= 1: full sliding)
  int newton_iterations = 0;     ///< double-precision iterations of the fixed point
};

/// Contact half-length a = a_ref (Fz / Fz_ref)^n, m; zero for Fz <= 0.
template <Scalar T>
T CalcContactHalfLength(const BrushParams<T>& params, const T& fz);

/// Cornering stiffness of the rigid-carcass brush, C_Fa = 2 k(T) a^2, N/rad: -dFy/d(tan alpha)
/// at zero slip without carcass torsion (001:5 with N -> infinity). Equal to the longitudinal
/// slip stiffness dFx/dkappa (isotropic bristles).
template <Scalar T>
T CalcCorneringStiffness(const BrushParams<T>& params, const T& fz, const T& temp);

/// Cornering stiffness with carcass torsion, C'_Fa = C_Fa / (1 + C_Fa t0 / c_ct(T)), t0 = a/3,
/// N/rad (001:3, 001:5).
template <Scalar T>
T CalcEffectiveCorneringStiffness(const BrushParams<T>& params, const T& fz, const T& temp);

/// Aligning stiffness with carcass torsion, dMz/d(tan alpha) at zero slip:
/// C_Mz = C_Fa t0 / (1 + C_Fa t0 / c_ct(T)), N m/rad (001:5).
template <Scalar T>
T CalcAligningStiffness(const BrushParams<T>& params, const T& fz, const T& temp);

/// Lateral relaxation length sigma_y = C_Fa / c_cy(T), m (spec section 7).
template <Scalar T>
T CalcRelaxationLength(const BrushParams<T>& params, const T& fz, const T& temp);

/// Steady-state Fx, Fy and Mz of the brush model at `op` (see the file comment); mx and my are
/// zero. Zero forces for Fz <= 0. If `details` is given, intermediate results are written there.
template <Scalar T>
TyreForces<T> CalcBrushForces(const BrushParams<T>& params, const TyreOperatingPoint<T>& op,
                              BrushDetails<T>* details = nullptr);

}  // namespace hotlap::tyre
