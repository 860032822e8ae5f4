#pragma once
/// @file
/// Thinning a long series for display without losing what the eye looks for: peaks, troughs and
/// the ends. A 30-lap log at 100 Hz has 90 000 samples per channel; a chart a thousand pixels
/// wide shows no more than two values per pixel column, so the report keeps, for each of about
/// max_points / 2 consecutive buckets of samples, the smallest and the largest value (in their
/// original order), plus the first and the last sample. Every local extreme that stands out by
/// more than one bucket survives; a plot of the kept points covers exactly the same range.

#include <cstddef>
#include <span>
#include <vector>

namespace hotlap::report {

/// Indices, strictly increasing, of at most `max_points` of the `values` to keep: all of them
/// when there are no more than `max_points`; otherwise the first, the last, and the index of the
/// minimum and of the maximum of each of about (max_points - 2) / 2 equal-count buckets of the
/// samples in between. Non-finite values are gaps: a bucket that holds part of a gap also keeps its
/// first non-finite sample (so a gap stays a gap), and there are as many fewer buckets as needed
/// to stay within `max_points`. Throws std::invalid_argument if max_points < 5.
std::vector<size_t> MinMaxDecimationIndices(std::span<const double> values, size_t max_points);

/// values[i] for each of `indices`.
std::vector<double> PickIndices(std::span<const double> values, std::span<const size_t> indices);

}  // namespace hotlap::report
