#include "hotlap/track/track_summary.h"

#include <cmath>

#include <gtest/gtest.h>

#include "hotlap/common/units.h"

namespace hotlap::track {
namespace {

RibbonPiece Piece(double length, double k0, double k1, double bank0, double bank1) {
  RibbonPiece p;
  p.length_m = length;
  p.curvature = {k0, (k1 - k0) / length, k1, (k1 - k0) / length};
  p.bank = {bank0, 0, bank1, 0};
  p.grade = CubicHermite::Constant(0);
  p.width_left = p.width_right = CubicHermite::Constant(5);
  return p;
}

TEST(TrackSummaryTest, OvalTurnsWithClothoidEntries) {
  // straight 100, clothoid 50 into R 100 (banked 10 deg), arc, clothoid out, and the same again.
  const double r = 100, c = 50, arc = (kPi - c / r) * r, b = DegToRad(10);
  std::vector<RibbonPiece> pieces;
  for (int k = 0; k < 2; ++k) {
    pieces.push_back(Piece(100, 0, 0, 0, 0));
    pieces.push_back(Piece(c, 0, 1 / r, 0, b));
    pieces.push_back(Piece(arc, 1 / r, 1 / r, b, b));
    pieces.push_back(Piece(c, 1 / r, 0, b, 0));
  }
  const Track t = Track::FromPieces("oval", pieces, {});
  const TrackSummary s = Summarize(t);
  EXPECT_NEAR(s.length_m, 200 + 4 * c + 2 * arc, 1e-9);
  EXPECT_EQ(s.winding, 1);
  EXPECT_NEAR(s.min_radius_m, r, 1e-9);
  EXPECT_NEAR(s.bank_max_rad, b, 1e-12);
  EXPECT_NEAR(s.bank_min_rad, 0.0, 1e-15);
  EXPECT_NEAR(s.width_min_m, 10.0, 1e-12);
  ASSERT_EQ(s.turns.size(), 2u);
  const double half = 100 + 2 * c + arc;
  EXPECT_NEAR(s.turns[0].entry_m, 100.0, 1e-6);  // exactly where the clothoid starts
  EXPECT_NEAR(s.turns[0].exit_m, half, 1e-6);
  EXPECT_NEAR(s.turns[1].entry_m, half + 100.0, 1e-6);
  EXPECT_EQ(s.turns[0].direction, 1);
  EXPECT_NEAR(s.turns[0].max_bank_rad, b, 1e-12);
  EXPECT_GT(s.turns[0].apex_m, 100 + c - 0.5);
}

TEST(TrackSummaryTest, CircleIsOneTurnAndAStraightHasNone) {
  const Track circle =
      Track::FromPieces("circle", {Piece(2 * kPi * 30, -1 / 30.0, -1 / 30.0, 0, 0)}, {});
  const TrackSummary s = Summarize(circle);
  ASSERT_EQ(s.turns.size(), 1u);
  EXPECT_EQ(s.turns[0].direction, -1);
  EXPECT_NEAR(s.turns[0].min_radius_m, 30.0, 1e-9);
  // A huge circle is never tighter than the turn threshold.
  const Track wide =
      Track::FromPieces("wide", {Piece(2 * kPi * 5000, 1 / 5000.0, 1 / 5000.0, 0, 0)}, {});
  EXPECT_TRUE(Summarize(wide).turns.empty());
}

}  // namespace
}  // namespace hotlap::track
