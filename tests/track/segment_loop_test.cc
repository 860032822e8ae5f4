#include "hotlap/track/segment_loop.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "test_util.h"

namespace hotlap::track {
namespace {

using test::Contains;

Segment Straight(LoopValue length, double bank_deg = 0) {
  Segment s;
  s.type = SegmentType::kStraight;
  s.length = length;
  s.bank_rad = DegToRad(bank_deg);
  s.width_left_m = s.width_right_m = 6.0;
  return s;
}

Segment Arc(LoopValue radius, LoopValue angle, double bank_deg = 0, int turn = 1) {
  Segment s;
  s.type = SegmentType::kArc;
  s.radius = radius;
  s.angle = angle;
  s.arc_by_angle = true;
  s.turn_sign = turn;
  s.bank_rad = DegToRad(bank_deg);
  s.width_left_m = s.width_right_m = 6.0;
  return s;
}

Segment Clothoid(LoopValue length) {
  Segment s;
  s.type = SegmentType::kClothoid;
  s.length = length;
  return s;
}

LoopValue Fixed(double v) { return {v, -1}; }
LoopValue Unknown(int k) { return {0.0, k}; }

// A symmetric oval with clothoids: straight, clothoid, arc, clothoid, straight, clothoid, arc,
// clothoid. Closed by symmetry when both arcs turn pi - clothoid/R.
SegmentLoop Oval() {
  SegmentLoop loop;
  loop.name = "oval";
  loop.path = "oval.yaml";
  const double r = 200, c = 100, arc = kPi - c / r;
  loop.segments = {Straight(Fixed(500), 4),       Clothoid(Fixed(c)),
                   Arc(Fixed(r), Fixed(arc), 20), Clothoid(Fixed(c)),
                   Straight(Fixed(500), 4),       Clothoid(Fixed(c)),
                   Arc(Fixed(r), Fixed(arc), 20), Clothoid(Fixed(c))};
  return loop;
}

TEST(SegmentLoopTest, SymmetricOvalClosesWithoutUnknowns) {
  const SegmentTrack t = SolveSegmentLoop(Oval());
  EXPECT_LT(t.track.closure_error().position_m(), 1e-9);
  EXPECT_NEAR(t.track.length_m(), 1000 + 4 * 100 + 2 * (200 * kPi - 100), 1e-9);
  EXPECT_EQ(t.track.winding(), 1);
  ASSERT_EQ(t.spans.size(), 8u);
  EXPECT_EQ(t.spans[0].start_m, 0.0);
  EXPECT_NEAR(t.spans[2].start_m, 600.0, 1e-9);
}

TEST(SegmentLoopTest, CurvatureIsExactlyTheSegments) {
  const SegmentTrack t = SolveSegmentLoop(Oval());
  for (const SegmentSpan& g : t.spans) {
    for (double u = 0.0; u <= 1.0; u += 0.125) {
      const TrackPoint p = t.track.At(g.start_m + u * g.length_m);
      const double kappa =
          g.curvature_start_per_m + u * (g.curvature_end_per_m - g.curvature_start_per_m);
      EXPECT_NEAR(p.curvature_per_m, kappa, 1e-14) << g.index << " " << u;
      if (g.type == SegmentType::kClothoid && u > 0.0 && u < 1.0) {  // linear ramp
        EXPECT_NEAR(p.curvature_rate_per_m2,
                    (g.curvature_end_per_m - g.curvature_start_per_m) / g.length_m, 1e-15);
        // Bank along the smoothstep between the neighbours' banks.
        const double smooth = 3 * u * u - 2 * u * u * u;
        EXPECT_NEAR(p.bank_rad, g.bank_start_rad + smooth * (g.bank_end_rad - g.bank_start_rad),
                    1e-13);
      } else if (u > 0.0 && u < 1.0) {
        EXPECT_EQ(p.bank_rad, g.bank_start_rad);
      }
    }
  }
}

TEST(SegmentLoopTest, BankAndCurvatureAreContinuous) {
  const SegmentTrack t = SolveSegmentLoop(Oval());
  const double L = t.track.length_m();
  double max_bank_jump = 0.0, max_kappa_jump = 0.0, max_bank_rate = 0.0;
  const double h = 0.01;
  for (double s = 0.0; s < L; s += h) {
    const TrackPoint a = t.track.At(s), b = t.track.At(s + h);
    max_bank_jump = std::max(max_bank_jump, std::abs(b.bank_rad - a.bank_rad));
    max_kappa_jump = std::max(max_kappa_jump, std::abs(b.curvature_per_m - a.curvature_per_m));
    max_bank_rate = std::max(max_bank_rate, std::abs(b.bank_rate_per_m - a.bank_rate_per_m));
  }
  // Steepest smoothstep slope: 1.5 * 16 deg / 100 m; per 1 cm step that is 7e-5 rad.
  EXPECT_LT(max_bank_jump, 1.5 * DegToRad(16) / 100 * h * 1.01);
  EXPECT_LT(max_kappa_jump, (1.0 / 200) / 100 * h * 1.01);
  EXPECT_LT(max_bank_rate, 1e-5);  // bank is C1: its rate never jumps
}

TEST(SegmentLoopTest, SolvesUnknownsSoTheLoopClosesAndHasItsLength) {
  // An egg: ends of different radius, so the straights cannot be parallel.
  SegmentLoop loop;
  loop.path = "egg.yaml";
  loop.name = "egg";
  loop.unknowns = {{"a_m", UnknownKind::kLength, 400, 400},
                   {"b_m", UnknownKind::kLength, 400, 400},
                   {"t1_deg", UnknownKind::kAngle, 2.5, 2.5},
                   {"t2_deg", UnknownKind::kAngle, 2.5, 2.5}};
  loop.target_length_m = 2000.0;
  loop.segments = {Straight(Unknown(0)),        Clothoid(Fixed(80)),  Arc(Fixed(150), Unknown(2)),
                   Clothoid(Fixed(80)),         Straight(Unknown(1)), Clothoid(Fixed(120)),
                   Arc(Fixed(120), Unknown(3)), Clothoid(Fixed(120))};
  const SegmentTrack t = SolveSegmentLoop(loop);
  EXPECT_LT(t.track.closure_error().position_m(), 1e-8);
  EXPECT_LT(std::abs(t.track.closure_error().heading_rad), 1e-11);
  EXPECT_NEAR(t.track.length_m(), 2000.0, 1e-8);
  // Turning adds to one turn: the arcs, and each clothoid turns by length / (2 R).
  const double turn = t.unknowns[2].value + t.unknowns[3].value + 80 / 150.0 + 120 / 120.0;
  EXPECT_NEAR(turn, 2 * kPi, 1e-10);
  EXPECT_GT(t.newton_iterations, 0);
  EXPECT_NE(t.unknowns[2].value, t.unknowns[3].value);
}

TEST(SegmentLoopTest, StartFinishInsideTheFirstSegment) {
  SegmentLoop loop = Oval();
  loop.start_finish_fraction = 0.5;
  const SegmentTrack t = SolveSegmentLoop(loop);
  EXPECT_NEAR(t.spans[0].start_m, t.track.length_m() - 250.0, 1e-9);
  EXPECT_NEAR(t.spans[1].start_m, 250.0, 1e-9);
  const TrackPoint p = t.track.At(0.0);
  EXPECT_EQ(p.x_m, 0.0);
  EXPECT_EQ(p.heading_rad, 0.0);
  EXPECT_EQ(p.curvature_per_m, 0.0);
  EXPECT_NEAR(p.bank_rad, DegToRad(4), 1e-15);
}

TEST(SegmentLoopTest, AnOpenLoopWithoutUnknownsIsAnError) {
  SegmentLoop loop = Oval();
  loop.segments[0].length = Fixed(501.0);
  try {
    SolveSegmentLoop(loop);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), "oval.yaml: field 'segments': the loop does not close"));
    EXPECT_TRUE(Contains(e.what(), "the end is 1 m from the start"));
    EXPECT_TRUE(Contains(e.what(), "allowed: 0.01 m, 1e-06 rad"));
  }
}

TEST(SegmentLoopTest, UnknownsThatCannotMoveTheEndEverywhereAreAnError) {
  // Both straights unknown plus an arc: the parallel straights only move the end along x.
  SegmentLoop loop = Oval();
  loop.unknowns = {{"a_m", UnknownKind::kLength, 500, 500},
                   {"b_m", UnknownKind::kLength, 500, 500},
                   {"r_m", UnknownKind::kLength, 200, 200}};
  loop.segments[0].length = Unknown(0);
  loop.segments[4].length = Unknown(1);
  loop.segments[2].radius = Unknown(2);
  loop.segments[6].radius = Fixed(201.0);  // so it does not already close
  try {
    SolveSegmentLoop(loop);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), "oval.yaml: field 'solve': the unknowns cannot close the loop"))
        << e.what();
  }
}

TEST(SegmentLoopTest, WrongNumberOfUnknownsIsAnError) {
  SegmentLoop loop = Oval();
  loop.unknowns = {{"a_m", UnknownKind::kLength, 500, 500}};
  loop.segments[0].length = Unknown(0);
  try {
    SolveSegmentLoop(loop);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), "1 unknown(s) for 3 closure equations")) << e.what();
  }
}

TEST(SegmentLoopTest, ASolutionThatNeedsANegativeLengthIsAnError) {
  // The back straight would have to be negative to meet a target length this short.
  SegmentLoop loop = Oval();
  loop.unknowns = {{"a_m", UnknownKind::kLength, 500, 500},
                   {"b_m", UnknownKind::kLength, 500, 500},
                   {"t1_deg", UnknownKind::kAngle, 2.6, 2.6},
                   {"t2_deg", UnknownKind::kAngle, 2.6, 2.6}};
  loop.target_length_m = 1000.0;
  loop.segments[0].length = Unknown(0);
  loop.segments[4].length = Unknown(1);
  loop.segments[2].angle = Unknown(2);
  loop.segments[6].angle = Unknown(3);
  try {
    SolveSegmentLoop(loop);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), "cannot close with these unknowns")) << e.what();
    EXPECT_TRUE(Contains(e.what(), "a_m = ")) << e.what();
  }
}

}  // namespace
}  // namespace hotlap::track
