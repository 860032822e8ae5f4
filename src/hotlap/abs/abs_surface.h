#pragma once
/// @file
/// The road under a braking wheel: the FE/ABS paper's friction law (002:1) and surfaces made of
/// segments of such laws along the road (docs/abs.md).
///
///   mu(v_s) = mu_k + (mu_s - mu_k) exp(-d_c |v_s|)        (002:1; Abaqus' exponential decay)
///
/// with v_s the slip speed of the contact, m/s, mu_s the static and mu_k the kinetic friction and
/// d_c the decay coefficient, s/m. The paper's values are 0.90, 0.45 and 0.5 s/m (002 §2.1.3).
///
/// A surface is a list of segments, each a friction law from a distance on: one segment is a
/// uniform road; several make a road whose friction changes along the stop (a mu-jump, a wet
/// patch). That is what "split" friction means for one wheel (docs/abs.md says why).

#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include "hotlap/common/field_cast.h"
#include "hotlap/common/scalar.h"

namespace hotlap::sim {

/// The exponential-decay friction law (002:1).
template <Scalar T>
struct FrictionLaw {
  T static_friction{};   ///< mu_s, 1: at zero slip speed
  T kinetic_friction{};  ///< mu_k, 1: at high slip speed
  T decay{};             ///< d_c, s/m

  /// mu(v_s), 1, for a slip speed v_s in m/s (its sign is ignored).
  T Friction(const T& slip_speed) const {
    using std::abs;
    using std::exp;
    return kinetic_friction + (static_friction - kinetic_friction) * exp(-decay * abs(slip_speed));
  }

  template <class Self>
  static auto FieldsOf(Self& s) {
    return std::tie(s.static_friction, s.kinetic_friction, s.decay);
  }
  /// The same law in another scalar type (derivative parts start at zero).
  template <Scalar U>
  FrictionLaw<U> Cast() const {
    FrictionLaw<U> out;
    CastFields(*this, out);
    return out;
  }
};

/// One stretch of road: a friction law from `start_m` on.
struct SurfaceSegment {
  double start_m = 0.0;     ///< distance from the start of braking, m
  std::string law_name;     ///< the law's name in the configuration file
  FrictionLaw<double> law;  ///< its coefficients
};

/// A road: segments in increasing start_m, the first starting at 0 m.
struct Surface {
  std::string name;
  std::vector<SurfaceSegment> segments;

  /// Index of the segment under `distance_m` (the first one for negative distances).
  size_t SegmentAt(double distance_m) const {
    size_t i = 0;
    while (i + 1 < segments.size() && segments[i + 1].start_m <= distance_m) ++i;
    return i;
  }
  /// Where segment `index` ends, m (+infinity for the last).
  double SegmentEnd(size_t index) const {
    return index + 1 < segments.size() ? segments[index + 1].start_m
                                       : std::numeric_limits<double>::infinity();
  }
};

}  // namespace hotlap::sim
