#pragma once
/// @file
/// Thermal conductivity and kinematic viscosity of air at 1 atm against temperature
/// (Cengel & Cimbala, Table A-9; spec section 2), used by the forced-convection coefficient
/// (000:15) at the film temperature. Linear interpolation, clamped outside the table.

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "hotlap/common/interpolation.h"
#include "hotlap/common/scalar.h"

namespace hotlap::tyre {

namespace internal {
inline constexpr std::array<double, 18> kAirTableTempK = {
    273.15, 283.15, 293.15, 303.15, 313.15, 323.15, 333.15, 343.15, 353.15,
    363.15, 373.15, 393.15, 413.15, 433.15, 453.15, 473.15, 523.15, 573.15};
inline constexpr std::array<double, 18> kAirConductivity = {
    .02364, .02439, .02514, .02588, .02662, .02735, .02808, .02881, .02953,
    .03024, .03095, .03235, .03374, .03511, .03646, .03779, .04104, .04418};
inline constexpr std::array<double, 18> kAirKinematicViscosity = {
    1.338e-5, 1.426e-5, 1.516e-5, 1.608e-5, 1.702e-5, 1.798e-5, 1.896e-5, 1.995e-5, 2.097e-5,
    2.201e-5, 2.306e-5, 2.522e-5, 2.745e-5, 2.975e-5, 3.212e-5, 3.455e-5, 4.091e-5, 4.765e-5};
}  // namespace internal

/// Thermal conductivity of air, W/(m K), at temperature `temp` (K).
template <Scalar T>
T AirConductivity(const T& temp) {
  return InterpolateClamped<T>(internal::kAirTableTempK, internal::kAirConductivity, temp);
}

/// Kinematic viscosity of air, m^2/s, at temperature `temp` (K).
template <Scalar T>
T AirKinematicViscosity(const T& temp) {
  return InterpolateClamped<T>(internal::kAirTableTempK, internal::kAirKinematicViscosity, temp);
}

namespace internal {
/// Degree of the per-interval polynomials of AirConvectionFactor.
inline constexpr int kConvectionFactorDegree = 10;
using ConvectionFactorPolynomial = std::array<double, kConvectionFactorDegree + 1>;

/// For every table interval, the coefficients of k(T) nu(T)^-0.805 as a polynomial in T - T_mid
/// (T_mid the interval's midpoint). With nu = nu_m (1 + r), r = (dnu/dT) (T - T_mid) / nu_m, the
/// power is nu_m^-0.805 times the binomial series sum_n C(-0.805, n) r^n, here to n = 9; |r| <=
/// 0.092 on this table, so the remainder is below 1e-11 relative. Multiplying by the linear k(T)
/// gives degree 10. Computed once.
inline const std::array<ConvectionFactorPolynomial, 17>& ConvectionFactorPolynomials() {
  static const std::array<ConvectionFactorPolynomial, 17> table = [] {
    constexpr double kExponent = -0.805;
    std::array<ConvectionFactorPolynomial, 17> out{};
    for (size_t i = 0; i + 1 < kAirTableTempK.size(); ++i) {
      const double width = kAirTableTempK[i + 1] - kAirTableTempK[i];
      const double nu_slope = (kAirKinematicViscosity[i + 1] - kAirKinematicViscosity[i]) / width;
      const double k_slope = (kAirConductivity[i + 1] - kAirConductivity[i]) / width;
      const double nu_mid = 0.5 * (kAirKinematicViscosity[i] + kAirKinematicViscosity[i + 1]);
      const double k_mid = 0.5 * (kAirConductivity[i] + kAirConductivity[i + 1]);
      const double rho = nu_slope / nu_mid;  // r = rho (T - T_mid)
      // Series coefficients in (T - T_mid): b_n = C(a, n) rho^n, n = 0..degree-1.
      std::array<double, kConvectionFactorDegree> b{};
      b[0] = 1.0;
      for (int n = 1; n < kConvectionFactorDegree; ++n) {
        b[n] = b[n - 1] * (kExponent - n + 1) / n * rho;
      }
      const double scale = std::pow(nu_mid, kExponent);
      ConvectionFactorPolynomial& c = out[i];
      for (int n = 0; n <= kConvectionFactorDegree; ++n) {
        const double from_k = n < kConvectionFactorDegree ? k_mid * b[n] : 0.0;
        const double from_slope = n > 0 ? k_slope * b[n - 1] : 0.0;
        c[n] = scale * (from_k + from_slope);
      }
    }
    return out;
  }();
  return table;
}
}  // namespace internal

/// k(T) nu(T)^-0.805, W/(m K) (m^2/s)^-0.805: the air-property factor of the forced-convection
/// coefficient (000:15), with k and nu interpolated linearly in the table as above and clamped
/// outside it.
///
/// The power is not taken through exp and log at every call (the costliest part of a replay):
/// each table interval has a precomputed polynomial (internal::ConvectionFactorPolynomials),
/// equal to the direct form within 1e-10 relative (checked against std::pow by a test), and
/// evaluated by Estrin's scheme to keep the dependency chain short.
template <Scalar T>
T AirConvectionFactor(const T& temp) {
  using internal::kAirTableTempK;
  const auto& table = internal::ConvectionFactorPolynomials();
  const double tv = ValueOf(temp);
  // Outside the table the properties are clamped: the polynomial's value at the end knot.
  const auto value_at = [](const internal::ConvectionFactorPolynomial& c, double d) {
    double v = c.back();
    for (int n = internal::kConvectionFactorDegree - 1; n >= 0; --n) v = c[n] + d * v;
    return v;
  };
  if (tv <= kAirTableTempK.front()) {
    return T(value_at(table.front(), -0.5 * (kAirTableTempK[1] - kAirTableTempK[0])));
  }
  if (tv >= kAirTableTempK.back()) {
    return T(value_at(table.back(), 0.5 * (kAirTableTempK[17] - kAirTableTempK[16])));
  }
  const size_t i =
      std::upper_bound(kAirTableTempK.begin(), kAirTableTempK.end(), tv) - kAirTableTempK.begin();
  const internal::ConvectionFactorPolynomial& c = table[i - 1];
  const T d = temp - 0.5 * (kAirTableTempK[i - 1] + kAirTableTempK[i]);
  // Estrin's scheme for degree 10.
  const T d2 = d * d;
  const T d4 = d2 * d2;
  const T p01 = c[0] + c[1] * d;
  const T p23 = c[2] + c[3] * d;
  const T p45 = c[4] + c[5] * d;
  const T p67 = c[6] + c[7] * d;
  const T p89 = c[8] + c[9] * d;
  const T q0 = p01 + p23 * d2;
  const T q1 = p45 + p67 * d2;
  const T q2 = p89 + c[10] * d2;
  return q0 + q1 * d4 + q2 * (d4 * d4);
}

}  // namespace hotlap::tyre
