#include "hotlap/track/track.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"

namespace hotlap::track {
namespace {

RibbonPiece Piece(double length, CubicHermite kappa, CubicHermite bank = CubicHermite::Constant(0),
                  double width = 5.0) {
  RibbonPiece p;
  p.length_m = length;
  p.curvature = kappa;
  p.bank = bank;
  p.grade = CubicHermite::Constant(0.0);
  p.width_left = p.width_right = CubicHermite::Constant(width);
  return p;
}

// A circle of radius R in one piece (the track subdivides it).
Track Circle(double radius) {
  return Track::FromPieces("circle", {Piece(2 * kPi * radius, CubicHermite::Constant(1 / radius))},
                           TrackStart{});
}

// A stadium: straight, half circle, straight, half circle; closes exactly.
Track Stadium(double straight, double radius) {
  const CubicHermite k = CubicHermite::Constant(1 / radius);
  const CubicHermite zero = CubicHermite::Constant(0.0);
  return Track::FromPieces("stadium",
                           {Piece(straight, zero), Piece(kPi * radius, k), Piece(straight, zero),
                            Piece(kPi * radius, k)},
                           TrackStart{});
}

TEST(TrackTest, CircleIsACircle) {
  const double r = 100.0;
  const Track t = Circle(r);
  EXPECT_NEAR(t.length_m(), 2 * kPi * r, 1e-9);
  EXPECT_EQ(t.winding(), 1);
  EXPECT_LT(t.closure_error().position_m(), 1e-9);
  EXPECT_LT(std::abs(t.closure_error().heading_rad), 1e-12);
  // Start at the origin heading +x, turning left: the centre is at (0, r).
  for (double s = 0; s < t.length_m(); s += 7.3) {
    const TrackPoint p = t.At(s);
    EXPECT_NEAR(std::hypot(p.x_m, p.y_m - r), r, 1e-9) << s;  // between knots too
    EXPECT_NEAR(p.heading_rad, s / r, 1e-12) << s;
    EXPECT_NEAR(p.curvature_per_m, 1 / r, 1e-15);
    EXPECT_EQ(p.curvature_rate_per_m2, 0.0);
  }
}

TEST(TrackTest, PositionAgreesWithHeadingBetweenKnots) {
  // A circle of radius 20 m whose curvature wiggles inside each quarter (cubic pieces with equal
  // end values, so the turn is still exactly one): the quintic centre line's slope is
  // (cos heading, sin heading), less the spread of the small gap, to within 1e-7.
  const double r = 20.0, quarter = kPi * r / 2;
  const CubicHermite k{1 / r, 2e-3, 1 / r, 2e-3};
  const Track t = Track::FromPieces(
      "wiggle", {Piece(quarter, k), Piece(quarter, k), Piece(quarter, k), Piece(quarter, k)}, {});
  const double L = t.length_m();
  const ClosureError& e = t.spread_closure();
  EXPECT_LT(std::abs(e.heading_rad), 1e-12);
  const double h = 1e-4;
  for (double s = 1.0; s < L - 1.0; s += 0.37) {
    const TrackPoint a = t.At(s - h), b = t.At(s + h), p = t.At(s);
    EXPECT_NEAR((b.x_m - a.x_m) / (2 * h), std::cos(p.heading_rad) - e.dx_m / L, 1e-7) << s;
    EXPECT_NEAR((b.y_m - a.y_m) / (2 * h), std::sin(p.heading_rad) - e.dy_m / L, 1e-7) << s;
    EXPECT_NEAR((b.heading_rad - a.heading_rad) / (2 * h), p.curvature_per_m, 1e-8) << s;
  }
}

TEST(TrackTest, WrapsDistance) {
  const Track t = Stadium(300, 100);
  const double L = t.length_m();
  EXPECT_NEAR(L, 600 + 200 * kPi, 1e-9);
  for (double s : {0.0, 12.5, 350.0, 900.0}) {
    const TrackPoint p = t.At(s), q = t.At(s + L), r = t.At(s - 3 * L);
    EXPECT_NEAR(q.s_m, p.s_m, 1e-9);
    EXPECT_NEAR(q.x_m, p.x_m, 1e-8);
    EXPECT_NEAR(r.y_m, p.y_m, 1e-8);
    EXPECT_NEAR(q.heading_rad, p.heading_rad, 1e-12);
  }
  EXPECT_EQ(t.Wrap(L), 0.0);
  EXPECT_NEAR(t.Wrap(-1.0), L - 1.0, 1e-9);
  // The end meets the start: position and heading (one turn later).
  const TrackPoint end = t.At(L - 1e-9), start = t.At(0.0);
  EXPECT_NEAR(end.x_m, start.x_m, 1e-8);
  EXPECT_NEAR(end.y_m, start.y_m, 1e-8);
  EXPECT_NEAR(end.heading_rad, start.heading_rad + 2 * kPi, 1e-8);
}

TEST(TrackTest, SampleClosesThePlot) {
  const Track t = Stadium(300, 100);
  const std::vector<TrackPoint> s = t.Sample(100);
  ASSERT_EQ(s.size(), 101u);
  EXPECT_EQ(s.front().s_m, 0.0);
  EXPECT_EQ(s.back().s_m, t.length_m());
  EXPECT_EQ(s.back().x_m, s.front().x_m);
  EXPECT_NEAR(s.back().heading_rad, s.front().heading_rad + 2 * kPi, 1e-12);
  EXPECT_NEAR(s[50].s_m, t.length_m() / 2, 1e-9);
}

TEST(TrackTest, ChannelsAreTheGivenCubics) {
  // Bank along a smoothstep from 0 to 0.2 rad over 100 m: value and slope at every point.
  const CubicHermite bank{0.0, 0.0, 0.2, 0.0};
  const Track t =
      Track::FromPieces("banked",
                        {Piece(100, CubicHermite::Constant(0.01), bank),
                         Piece(2 * kPi * 100 - 100, CubicHermite::Constant(0.01), {0.2, 0, 0, 0})},
                        {});
  for (double s = 0; s <= 100; s += 2.5) {
    const double u = s / 100;
    EXPECT_NEAR(t.At(s).bank_rad, 0.2 * (3 * u * u - 2 * u * u * u), 1e-14) << s;
    EXPECT_NEAR(t.At(s).bank_rate_per_m, 0.2 * (6 * u - 6 * u * u) / 100, 1e-14) << s;
  }
}

TEST(TrackTest, ReportsAndSpreadsASmallGap) {
  // A circle whose curvature is 1e-7 too large: it overshoots by a few centimetres.
  const double r = 100.0;
  const Track t = Track::FromPieces(
      "gap", {Piece(2 * kPi * r, CubicHermite::Constant(1 / r + 1e-7))}, TrackStart{});
  EXPECT_GT(t.closure_error().position_m(), 1e-4);
  EXPECT_NEAR(t.closure_error().heading_rad, 1e-7 * 2 * kPi * r, 1e-12);
  const TrackPoint end = t.At(t.length_m() - 1e-12), start = t.At(0);
  EXPECT_NEAR(end.x_m, start.x_m, 1e-9);
  EXPECT_NEAR(end.y_m, start.y_m, 1e-9);
  EXPECT_NEAR(end.heading_rad - 2 * kPi, start.heading_rad, 1e-10);
  // A loader-supplied gap (before its own correction) is what closure_error() reports.
  ClosureError before;
  before.dx_m = 3.0;
  const Track u = Track::FromPieces("given", {Piece(2 * kPi * r, CubicHermite::Constant(1 / r))},
                                    TrackStart{}, before);
  EXPECT_EQ(u.closure_error().position_m(), 3.0);
  EXPECT_LT(u.spread_closure().position_m(), 1e-9);
}

TEST(TrackTest, RejectsBadPieces) {
  EXPECT_THROW(Track::FromPieces("x", {}, {}), NumericalError);
  EXPECT_THROW(Track::FromPieces("x", {Piece(-1, CubicHermite::Constant(0))}, {}), NumericalError);
  EXPECT_THROW(Track::FromPieces("x", {Piece(10, CubicHermite::Constant(0), {}, -1)}, {}),
               NumericalError);
  // Half a circle does not turn through a whole number of turns.
  EXPECT_THROW(Track::FromPieces("x", {Piece(kPi * 10, CubicHermite::Constant(0.1))}, {}),
               NumericalError);
}

TEST(TrackTest, ClockwiseLoop) {
  const double r = 50.0;
  const Track t = Track::FromPieces("cw", {Piece(2 * kPi * r, CubicHermite::Constant(-1 / r))},
                                    {1.0, 2.0, 0.0, 0.5});
  EXPECT_EQ(t.winding(), -1);
  EXPECT_NEAR(t.At(0).x_m, 1.0, 1e-12);
  EXPECT_NEAR(t.At(0).heading_rad, 0.5, 1e-12);
  EXPECT_NEAR(t.At(kPi * r).heading_rad, 0.5 - kPi, 1e-9);
}

}  // namespace
}  // namespace hotlap::track
