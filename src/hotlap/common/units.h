#pragma once
/// @file
/// Physical constants and unit conversions. Inside the code everything is SI with temperatures in
/// kelvin; files and reports convert at the edge.

namespace hotlap {

/// Stefan-Boltzmann constant, W/(m^2 K^4) (spec section 0).
inline constexpr double kStefanBoltzmann = 5.670374e-8;
/// Standard gravity, m/s^2.
inline constexpr double kGravity = 9.80665;
/// 0 degC in kelvin.
inline constexpr double kZeroCelsius = 273.15;
inline constexpr double kPi = 3.14159265358979323846;
/// One pound per square inch in pascals (crew chiefs' pressures).
inline constexpr double kPsi = 6894.757293168;

constexpr double CelsiusToKelvin(double c) { return c + kZeroCelsius; }
constexpr double KelvinToCelsius(double k) { return k - kZeroCelsius; }
constexpr double DegToRad(double deg) { return deg * kPi / 180.0; }
constexpr double RadToDeg(double rad) { return rad * 180.0 / kPi; }
constexpr double KilopascalsToPascals(double kpa) { return 1e3 * kpa; }
constexpr double PascalsToKilopascals(double pa) { return pa / 1000.0; }

}  // namespace hotlap
