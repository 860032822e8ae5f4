// ResampleLine (track/racing_line.h): a line given at one spacing read at another. The line's
// curvature is its offset's second derivative, so the resampled offsets must be smooth, not only
// close: linear interpolation between 3 m rows read at 2 m put curvature spikes of +60% every
// 6 m into the QSS lap on the optimal line (docs/lap-simulation.md).

#include "hotlap/track/racing_line.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/track/track_io.h"

namespace hotlap::track {
namespace {

// An offset with two waves a lap, as a racing line swings out and in at both ends.
double Wave(double s, double length) { return 6.0 * std::sin(4.0 * kPi * s / length); }
double WaveSecondDerivative(double s, double length) {
  const double k = 4.0 * kPi / length;
  return -6.0 * k * k * std::sin(k * s);
}

struct Rows {
  std::vector<double> s, n;
};

Rows WaveRows(double length, double step, bool closing_row) {
  Rows r;
  const int intervals = static_cast<int>(std::round(length / step));
  for (int k = 0; k < intervals + (closing_row ? 1 : 0); ++k) {
    r.s.push_back(length * k / intervals);
    r.n.push_back(Wave(r.s.back(), length));
  }
  return r;
}

TEST(ResampleLineTest, SecondDifferencesFollowTheLineNotTheRows) {
  const Track track = LoadTrack("darlington");  // 2198 m
  const double length = track.length_m();
  const Rows rows = WaveRows(length, 3.0, true);  // as the optimal lap's nodes, closing node too
  const RacingLine line = ResampleLine(rows.s, rows.n, track, 2.0);
  ASSERT_EQ(line.s_m.size(), 1099u);
  const size_t m = line.s_m.size();
  const double h = length / static_cast<double>(m);
  const double peak = 6.0 * std::pow(4.0 * kPi / length, 2);  // |n''| at its largest
  double worst = 0.0;
  for (size_t k = 0; k < m; ++k) {
    // Values at the 2 m points: the wave to well within a millimetre.
    EXPECT_NEAR(line.offset_m[k], Wave(line.s_m[k], length), 1e-4) << k;
    const double second =
        (line.offset_m[(k + 1) % m] - 2.0 * line.offset_m[k] + line.offset_m[(k + m - 1) % m]) /
        (h * h);
    worst = std::max(worst, std::abs(second - WaveSecondDerivative(line.s_m[k], length)));
  }
  // The curvature the line's points imply is the wave's to 1% of its peak. Linear interpolation
  // of the same rows misses by 41% of the peak (the curvature piled onto the rows).
  EXPECT_LT(worst, 0.01 * peak);
}

TEST(ResampleLineTest, PassesThroughTheRowsAndWrapsFromAnyFirstDistance) {
  const Track track = LoadTrack("darlington");
  const double length = track.length_m();
  // Rows every 21.98 m from 10.99 m: the line must pass through them and wrap to the start.
  Rows rows;
  for (int k = 0; k < 100; ++k) {
    rows.s.push_back(10.99 + 21.98 * k);
    rows.n.push_back(Wave(rows.s.back(), length));
  }
  const RacingLine line = ResampleLine(rows.s, rows.n, track, 10.99);  // every other point a row
  ASSERT_EQ(line.s_m.size(), 200u);
  for (int k = 1; k < 200; k += 2) {
    EXPECT_NEAR(line.offset_m[k], rows.n[(k - 1) / 2], 1e-9) << k;
  }
  // Between the rows (and across the start line, at k = 0) the spline stays near the wave.
  for (int k = 0; k < 200; k += 2) EXPECT_NEAR(line.offset_m[k], Wave(line.s_m[k], length), 0.01);
}

TEST(ResampleLineTest, TooFewDistinctPointsIsBadInput) {
  const Track track = LoadTrack("darlington");
  const double length = track.length_m();
  // Two points and the first again one lap on: not a line.
  const std::vector<double> s = {0.0, 700.0, length}, n = {1.0, -1.0, 1.0};
  EXPECT_THROW(ResampleLine(s, n, track, 2.0), InputError);
}

}  // namespace
}  // namespace hotlap::track
