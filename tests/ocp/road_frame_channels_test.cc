// A lap solution's time along its mesh (ocp/road_frame_channels.h): dt/ds integrated as the
// transcription's defects integrate a state, the trapezoid's or Hermite-Simpson's.

#include "hotlap/ocp/road_frame_channels.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace hotlap::ocp {
namespace {

struct TinyNode {
  int u, v, r, n, w;
};

// `count` nodes `ds` apart, each with its own five variables, w = dt/ds(s) filled in.
struct TinyLap {
  std::vector<TinyNode> nodes;
  std::vector<double> x;
  TinyLap(int count, double ds, double (*w)(double)) {
    for (int k = 0; k < count; ++k) {
      const int b = 5 * k;
      nodes.push_back({b, b + 1, b + 2, b + 3, b + 4});
      x.insert(x.end(), {50.0, 0.0, 0.1, 1.0, w(k * ds)});
    }
  }
};

// dt/ds quadratic in s, and its integral: Simpson's rule is exact to an interval's end and
// Hermite's cubic to its midpoint.
double Quadratic(double s) { return 0.02 + 1e-4 * s + 3e-6 * s * s; }
double QuadraticTime(double s) { return 0.02 * s + 0.5e-4 * s * s + 1e-6 * s * s * s; }

TEST(RoadFrameChannelsTest, HermiteSimpsonTimeIsExactForAQuadraticRate) {
  const double ds = 7.0;
  const TinyLap lap(9, ds, Quadratic);  // four intervals and their midpoints
  RoadFrameChannels out;
  const double end = AppendRoadFrameChannels(lap.nodes, lap.x, ds, out, true);
  ASSERT_EQ(out.time.size(), 9u);
  for (int k = 0; k < 9; ++k) {
    EXPECT_NEAR(out.time[k], QuadraticTime(k * ds), 1e-12) << k;
    EXPECT_DOUBLE_EQ(out.distance[k], k * ds);
  }
  EXPECT_DOUBLE_EQ(end, out.time.back());
  // The trapezoid on the same nodes is not exact for it (its error is ds^2 / 12 of w'' per metre).
  RoadFrameChannels trapezoid;
  AppendRoadFrameChannels(lap.nodes, lap.x, ds, trapezoid);
  const double error = trapezoid.time.back() - QuadraticTime(8 * ds);
  EXPECT_NEAR(error, 8 * ds * ds * ds / 12.0 * 6e-6, 1e-12);
  EXPECT_GT(std::abs(error), 1e-4);
}

double Linear(double s) { return 0.02 + 1e-4 * s; }

TEST(RoadFrameChannelsTest, TrapezoidTimeIsExactForALinearRate) {
  const double ds = 3.0;
  const TinyLap lap(6, ds, Linear);
  RoadFrameChannels out;
  const double end = AppendRoadFrameChannels(lap.nodes, lap.x, ds, out);
  ASSERT_EQ(out.time.size(), 6u);
  for (int k = 0; k < 6; ++k)
    EXPECT_NEAR(out.time[k], 0.02 * k * ds + 0.5e-4 * k * k * ds * ds, 1e-14);
  EXPECT_DOUBLE_EQ(end, out.time.back());
  EXPECT_EQ(out.u, std::vector<double>(6, 50.0));
}

}  // namespace
}  // namespace hotlap::ocp
