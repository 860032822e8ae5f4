#pragma once
/// @file
/// Pieces the Magic Formula and UniTire rig fits (mf_fit.h, unitire_fit.h) share; not API.

#include <span>
#include <utility>
#include <vector>

#include "hotlap/common/scalar.h"
#include "hotlap/ident/unitire_fit.h"
#include "hotlap/tyre/tyre_force.h"

namespace hotlap::ident::internal {

/// The operating point of a rig sample in the scalar type T.
template <Scalar T>
tyre::TyreOperatingPoint<T> RigOperatingPoint(const RigSample& s) {
  tyre::TyreOperatingPoint<T> op;
  op.fz = T(s.fz);
  op.slip_ratio = T(s.slip_ratio);
  op.slip_angle = T(s.slip_angle);
  op.camber = T(s.camber);
  op.speed = T(s.speed);
  op.tread_temp = T(s.tread_temp);
  return op;
}

/// InputError naming the sample for a value that is not finite, a load that is not positive or
/// a tread temperature that is not positive (kelvin).
void CheckRigSamples(std::span<const RigSample> samples);

/// Least squares y = c0 + c1 x; c1 = 0 with fewer than two distinct x. Returns (c0, c1).
std::pair<double, double> LineFit(const std::vector<double>& x, const std::vector<double>& y);

/// Slope dy/dx at x = 0 of one measured curve: the least-squares slope through the origin of the
/// points at the smallest non-zero |x| (points within a millionth of a level belong to it),
/// extrapolated linearly to x = 0 with the next level's slope and kept between 1 and 1.5 times
/// the first (a saturating curve's secant slope falls about linearly with slip at first). With
/// one level, its slope; NaN with none. The rig fits' starting stiffnesses.
double ZeroSlipSlope(std::span<const double> x, std::span<const double> y);

/// Whether GroupValues' tolerance is in the values' unit or a fraction of each value.
enum class GroupTolerance {
  kAbsolute,  ///< a value joins the group when it is within `tolerance` of the previous one
  kRelative,  ///< ... within `tolerance` times its own magnitude (loads: 0.02 is 2 %)
};

/// Groups of values: sorted, a new group starts wherever a value lies more than the tolerance
/// above the previous one. The rig fits group loads (2 %) and temperatures (kelvin) this way.
struct ValueGroups {
  std::vector<int> index;    ///< group of each value, in the input order
  std::vector<double> mean;  ///< mean of each group, ascending
};

/// Relative tolerance within which rig loads are one load (GroupTolerance::kRelative).
inline constexpr double kLoadGroupTolerance = 0.02;

/// Groups `values` (see ValueGroups).
ValueGroups GroupValues(const std::vector<double>& values, double tolerance, GroupTolerance kind);

}  // namespace hotlap::ident::internal
