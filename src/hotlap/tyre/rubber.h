#pragma once
/// @file
/// Tread rubber stiffness against temperature, and the exponential temperature factor that the
/// carcass stiffnesses and the UniTire temperature corrections share (001:1-2, 001:6-8,
/// 001:12-16; spec section 7).
///
/// How to use: evaluate CalcShearModulus / CalcBristleStiffness for the brush model's tread, and
/// CalcTemperatureFactor for any quantity that scales as `f(T) = a exp(-b (T - T_ref))`. All
/// temperatures are kelvin; only differences enter, so a reference temperature given in degC in
/// a file is converted to kelvin at load time.

#include <tuple>

#include "hotlap/common/field_cast.h"
#include "hotlap/common/scalar.h"

namespace hotlap::tyre {

/// `f(T) = a exp(-b (T - T_ref))`: the factor the UniTire paper fits to cornering stiffness
/// (001:12), pneumatic trail (001:15) and, through the brush model, to the carcass stiffnesses
/// (001:6, 001 Figs 15-16). The printed `k1 exp(k2 - k3 T/T0)` is the same family with
/// `a = k1 exp(k2 - k3 T_ref/T0)` and `b = k3/T0`; writing it about a reference temperature drops
/// the printed form's redundant constant. `a` carries the unit of the quantity it gives (1 for a
/// pure factor, N/m for a stiffness, ...).
template <Scalar T>
struct TemperatureFactor {
  T scale{};           ///< a, the value at T_ref, in the unit of the quantity
  T decay{};           ///< b, 1/K (> 0: the quantity falls as the temperature rises)
  T reference_temp{};  ///< T_ref, K

  template <class Self>
  static auto FieldsOf(Self& s) {
    return std::tie(s.scale, s.decay, s.reference_temp);
  }
};

/// `a exp(-b (T - T_ref))` at temperature `temp`, K.
template <Scalar T>
T CalcTemperatureFactor(const TemperatureFactor<T>& factor, const T& temp);

/// The tread rubber of the brush model (001:1-2).
template <Scalar T>
struct RubberParams {
  T modulus_amplitude{};       ///< K_A, Pa: the modulus above G_lim at T_A
  T modulus_decay{};           ///< K_B, 1/K
  T modulus_reference_temp{};  ///< T_A, K
  T modulus_limit{};           ///< G_lim, Pa: the high-temperature limit of the modulus
  /// p_g, 1: the bristle stiffness per unit contact length per unit modulus, k_ty = p_g G. For
  /// bristles of width w and height h, p_g = w / h (the paper's "geometric parameter", 001:2).
  T geometry_factor{};

  template <class Self>
  static auto FieldsOf(Self& s) {
    return std::tie(s.modulus_amplitude, s.modulus_decay, s.modulus_reference_temp, s.modulus_limit,
                    s.geometry_factor);
  }
};

/// Shear modulus of the tread rubber, Pa: `G(T) = K_A exp(-K_B (T - T_A)) + G_lim` (001:1). The
/// paper prints `K_A e^(K_B T_A) e^(-K_B T) + G_lim`, the same function.
template <Scalar T>
T CalcShearModulus(const RubberParams<T>& rubber, const T& temp);

/// Bristle (tread) stiffness per unit contact length, N/m^2 (N per m of deflection per m of
/// contact length): `k_ty = p_g G(T)` (001:2). The brush model uses the same value for the
/// longitudinal bristle stiffness k_tx (isotropic bristles).
template <Scalar T>
T CalcBristleStiffness(const RubberParams<T>& rubber, const T& temp);

}  // namespace hotlap::tyre
