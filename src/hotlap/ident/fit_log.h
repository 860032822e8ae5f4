#pragma once
/// @file
/// What the fits read from a telemetry log (docs/fitting.md, "Bad data"): each measured channel
/// with its gaps and implausible values marked missing, a whole channel excluded (with the reason)
/// when it is absent, nearly empty, or stuck at one value; trapezoid weights so that sums over
/// samples approximate integrals over time; and the small parsers of the fit commands' options.

#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hotlap/common/corner.h"
#include "hotlap/logs/telemetry.h"
#include "hotlap/sim/replay.h"
#include "hotlap/sim/sampled_inputs.h"

namespace hotlap::ident {

/// One measured channel of one corner as a fit uses it.
struct LoggedChannel {
  std::string quantity;  ///< e.g. "tread_temp"
  Corner corner = Corner::kFrontLeft;
  std::string column;          ///< as written in the file; empty if the file has none
  std::vector<double> values;  ///< SI; NaN where empty, implausible, or the channel is excluded
  int empty_cells = 0;
  int implausible = 0;  ///< values outside the plausible range, dropped
  bool usable = false;
  std::string problem;  ///< why the channel is excluded; empty when usable

  /// Number of non-NaN values.
  int Count() const;
};

/// Reads `quantity` of `corner` and checks it. A value outside [min_si, max_si] (a sensor
/// reporting an error code, a disconnected thermocouple) is dropped. The channel is excluded
/// when the file has no such column, when fewer than max(10, 5% of the rows) values remain, or
/// when it is stuck: one value makes up half of its samples, or all of them lie within
/// `flat_tolerance_si` of each other (a dead sensor or a constant written in its place).
LoggedChannel ReadLoggedChannel(const Telemetry& log, std::string_view quantity, Corner corner,
                                double min_si, double max_si, double flat_tolerance_si);

/// The sentence a command prints for an excluded channel or dropped values; empty if none.
std::string DescribeChannelProblems(const LoggedChannel& channel);

/// Trapezoid weights of samples at `time`, scaled to mean 1: each sample stands for half of each
/// interval beside it, and no interval counts for more than twice the median interval (so the
/// samples at the edges of a logging gap are not over-weighted).
std::vector<double> TrapezoidWeights(std::span<const double> time);

/// A robust starting value: the median of the first (up to) five values within 1 s of the first
/// one; NaN if the channel has no value.
double RobustFirstValue(std::span<const double> time, std::span<const double> values);

/// The channel with its gaps filled linearly (held at the ends) and isolated spikes removed by a
/// running median of five: good enough for an equation-error starting guess, not for fitting.
std::vector<double> SmoothedForGuess(std::span<const double> values);

/// A corner's inputs as CornerSamples, and its brake's (sim/replay.h).
using sim::BrakeSamplesOf;
using sim::CornerSamplesOf;

/// Parses a comma-separated corner list ("fl,rr"); "all" or "" gives all four. InputError naming
/// `option` for an unknown name.
std::vector<Corner> ParseCornerList(std::string_view text, std::string_view option);

/// Parses "fl=0.03,rr=0.04" into per-corner values. InputError naming `option` otherwise.
std::map<Corner, double> ParseCornerValues(std::string_view text, std::string_view option);

/// The integer value of a `# key: value` metadata line of the log, if there is one.
std::optional<int> MetadataInt(const Telemetry& log, std::string_view key);

}  // namespace hotlap::ident
