#pragma once
/// @file
/// Named IEEE special values the sources share: infinity (an unbounded range, an open variable
/// bound, "no time yet") and a quiet NaN (a missing sample or an undefined figure).

#include <limits>

namespace hotlap {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace hotlap
