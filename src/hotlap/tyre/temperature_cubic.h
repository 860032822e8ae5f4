#pragma once
/// @file
/// The grip cubic g(T) and the wear-rate cubic w(T) of (000:5-6).
///
/// Each is fixed by four conditions: value 1 and zero slope at its optimal temperature, and given
/// values at one temperature below and one above. The 4x4 system (000:6) is solved in the shifted
/// variable x = T - T_opt so that it stays well conditioned. At load time the cubic is rejected if
/// it is not positive on its declared valid range, or if T_opt is not where it should be (the
/// maximum of a grip cubic, the minimum of a wear cubic). Evaluation clamps T to the valid range.

#include <string>

#include "hotlap/common/scalar.h"

namespace hotlap::tyre {

/// Whether the optimal temperature is the cubic's maximum (grip) or its minimum (wear rate).
enum class CubicKind { kGripMaximum, kWearMinimum };

/// The four conditions and the valid range, temperatures in kelvin.
struct TemperatureCubicSpec {
  CubicKind kind = CubicKind::kGripMaximum;
  double optimal_temp = 0.0;    ///< K; value 1, slope 0 here.
  double low_temp = 0.0;        ///< K; below optimal_temp.
  double low_value = 0.0;       ///< value at low_temp.
  double high_temp = 0.0;       ///< K; above optimal_temp.
  double high_value = 0.0;      ///< value at high_temp.
  double valid_min_temp = 0.0;  ///< K; the cubic is evaluated with T clamped to the valid range.
  double valid_max_temp = 0.0;  ///< K
};

/// g(T) = a x^3 + b x^2 + c x + d with x = T - T_opt (kelvin differences).
class TemperatureCubic {
 public:
  /// Solves (000:6) and checks the cubic. Throws InputError, with `what` (for example
  /// "data/.../compound.yaml: grip_cubic") at the start of the message, if the temperatures are
  /// not distinct and ordered low < optimal < high inside the valid range, if the cubic is not
  /// positive on the valid range, or if T_opt is not its maximum (grip) or minimum (wear) there.
  static TemperatureCubic Create(const TemperatureCubicSpec& spec, const std::string& what);

  /// Value at temperature `temp` (K), with `temp` clamped to the valid range. Dimensionless.
  template <Scalar T>
  T Evaluate(const T& temp) const;

  /// Slope dg/dT in 1/K (zero outside the valid range, where the cubic is clamped).
  double Slope(double temp) const;

  const TemperatureCubicSpec& spec() const { return spec_; }
  /// Coefficients in the shifted variable x = T - T_opt: {a, b, c, d}.
  double a() const { return a_; }
  double b() const { return b_; }
  double c() const { return c_; }
  double d() const { return d_; }

 private:
  TemperatureCubic(const TemperatureCubicSpec& spec, double a, double b, double c, double d)
      : spec_(spec), a_(a), b_(b), c_(c), d_(d) {}
  TemperatureCubicSpec spec_;
  double a_, b_, c_, d_;
};

template <Scalar T>
T TemperatureCubic::Evaluate(const T& temp) const {
  const double value = ValueOf(temp);
  if (value <= spec_.valid_min_temp) return T(Evaluate(spec_.valid_min_temp));
  if (value >= spec_.valid_max_temp) return T(Evaluate(spec_.valid_max_temp));
  const T x = temp - spec_.optimal_temp;
  return ((a_ * x + b_) * x + c_) * x + d_;  // Horner form of (000:5).
}

template <>
inline double TemperatureCubic::Evaluate(const double& temp) const {
  const double t = temp < spec_.valid_min_temp   ? spec_.valid_min_temp
                   : temp > spec_.valid_max_temp ? spec_.valid_max_temp
                                                 : temp;
  const double x = t - spec_.optimal_temp;
  return ((a_ * x + b_) * x + c_) * x + d_;
}

}  // namespace hotlap::tyre
