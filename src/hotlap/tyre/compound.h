#pragma once
/// @file
/// A tyre compound: how grip and wear rate depend on tread temperature (the cubics of 000:5-6),
/// how grip falls with wear (000 Fig. 7A, spec section 4), and the wear law's reference power.

#include <span>
#include <string>
#include <vector>

#include "hotlap/common/interpolation.h"
#include "hotlap/common/scalar.h"
#include "hotlap/tyre/temperature_cubic.h"

namespace hotlap::tyre {

/// Grip factor against tread depth lost, linear between points, constant beyond the ends.
struct GripWearTable {
  std::vector<double> wear_mm;  ///< strictly increasing, from 0
  std::vector<double> factor;   ///< in (0, 1], non-increasing

  /// h(wear), dimensionless; `wear` in mm. Below the first row the first segment carries on: a
  /// new tyre (wear 0) sits on no kink, so a solver's iterates either side of it see one slope.
  template <Scalar T>
  T Evaluate(const T& wear) const {
    if (ValueOf(wear) < wear_mm.front() && wear_mm.size() > 1) {
      const double slope = (factor[1] - factor[0]) / (wear_mm[1] - wear_mm[0]);
      return factor[0] + slope * (wear - wear_mm[0]);
    }
    return InterpolateClamped<T>(std::span<const double>(wear_mm), std::span<const double>(factor),
                                 wear);
  }
};

struct TyreCompound {
  std::string name;
  TemperatureCubic grip;        ///< g(T_t), maximum 1 at its optimum (000:5)
  TemperatureCubic wear_rate;   ///< w(T_t), minimum 1 at its optimum (000:23)
  GripWearTable grip_vs_wear;   ///< h(wear) (spec section 4)
  double wear_reference_power;  ///< Q_ref of (000:23), W

  /// The force correction g(T_t) h(wear) of spec section 4 (000:35-36 as corrected).
  template <Scalar T>
  T GripFactor(const T& tread_temp, const T& wear_mm) const {
    return grip.Evaluate(tread_temp) * grip_vs_wear.Evaluate(wear_mm);
  }
};

}  // namespace hotlap::tyre
