#pragma once
/// @file
/// The median of a sample (robust centre; with the median absolute deviation, a robust spread).

#include <algorithm>
#include <limits>
#include <vector>

namespace hotlap {

/// The median of `v`: the middle value, or the mean of the two middle ones for an even count;
/// NaN when `v` is empty. Takes `v` by value (it is partially reordered).
inline double Median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  double m = *mid;
  if (v.size() % 2 == 0) m = 0.5 * (m + *std::max_element(v.begin(), mid));
  return m;
}

}  // namespace hotlap
