#include "hotlap/report/decimate.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace hotlap::report {

std::vector<size_t> MinMaxDecimationIndices(std::span<const double> values, size_t max_points) {
  if (max_points < 5) {
    throw std::invalid_argument("MinMaxDecimationIndices: max_points " +
                                std::to_string(max_points) + " < 5");
  }
  const size_t n = values.size();
  std::vector<size_t> kept;
  if (n <= max_points) {
    kept.resize(n);
    std::iota(kept.begin(), kept.end(), size_t{0});
    return kept;
  }
  // Buckets hold 2 kept points, or 3 where they hold part of a gap (non-finite values): as many
  // buckets as the budget allows, found by counting the gap buckets for a trial count.
  std::vector<size_t> gaps_before(n + 1, 0);  // non-finite values among the first i samples
  for (size_t i = 0; i < n; ++i) gaps_before[i + 1] = gaps_before[i] + !std::isfinite(values[i]);
  const size_t inner = n - 2;  // samples 1 .. n-2 are shared out among the buckets
  const auto bucket_begin = [&](size_t b, size_t buckets) { return 1 + b * inner / buckets; };
  const auto gap_buckets = [&](size_t buckets) {
    size_t count = 0;
    for (size_t b = 0; b < buckets; ++b) {
      count += gaps_before[bucket_begin(b + 1, buckets)] > gaps_before[bucket_begin(b, buckets)];
    }
    return count;
  };
  size_t buckets = (max_points - 2) / 2;
  while (buckets > 1 && 2 * buckets + gap_buckets(buckets) > max_points - 2) {
    buckets =
        std::max<size_t>(1, std::min(buckets - 1, (max_points - 2 - gap_buckets(buckets)) / 2));
  }
  kept.push_back(0);
  for (size_t b = 0; b < buckets; ++b) {
    const size_t begin = bucket_begin(b, buckets), end = bucket_begin(b + 1, buckets);
    size_t lo = end, hi = end, gap = end;  // `end` means "none in this bucket"
    for (size_t i = begin; i < end; ++i) {
      const double v = values[i];
      if (!std::isfinite(v)) {
        if (gap == end) gap = i;
        continue;
      }
      if (lo == end || v < values[lo]) lo = i;
      if (hi == end || v > values[hi]) hi = i;
    }
    size_t picks[3] = {lo, hi, gap};
    std::sort(picks, picks + 3);
    for (size_t k = 0; k < 3; ++k) {
      if (picks[k] != end && (k == 0 || picks[k] != picks[k - 1])) kept.push_back(picks[k]);
    }
  }
  kept.push_back(n - 1);
  return kept;
}

std::vector<double> PickIndices(std::span<const double> values, std::span<const size_t> indices) {
  std::vector<double> picked;
  picked.reserve(indices.size());
  for (size_t i : indices) {
    if (i >= values.size()) {
      throw std::out_of_range("PickIndices: index " + std::to_string(i) + " of " +
                              std::to_string(values.size()) + " values");
    }
    picked.push_back(values[i]);
  }
  return picked;
}

}  // namespace hotlap::report
