#pragma once
/// @file
/// Thermal conductivity and kinematic viscosity of air at 1 atm against temperature
/// (Cengel & Cimbala, Table A-9; spec section 2), used by the forced-convection coefficient
/// (000:15) at the film temperature. Linear interpolation, clamped outside the table.

#include <array>
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

}  // namespace hotlap::tyre
