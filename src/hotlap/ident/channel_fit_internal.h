#pragma once
/// @file
/// Pieces of FitChannels (channel_fit.h) kept in their own file; not API.

#include <span>

#include "hotlap/ident/channel_fit.h"

namespace hotlap::ident::internal {

/// The two-sided 95% quantile of the standard normal distribution (the intervals' z).
inline constexpr double kZ95 = 1.959963984540054;

/// The sensor-lag diagnostic of ChannelStats::apparent_lag: fills apparent_lag and its standard
/// error of every channel of `result` from the predictions at the solution (with their Jacobian,
/// model units), the parameters' scales and the noise levels in result->channels.
void EstimateApparentLags(const Predictions& at_best, std::span<const double> scale,
                          std::span<const MeasuredChannel> channels, std::span<const double> time,
                          FitResult* result);

}  // namespace hotlap::ident::internal
