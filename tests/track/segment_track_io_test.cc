#include "hotlap/track/segment_track_io.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/track/track_summary.h"
#include "test_util.h"

namespace hotlap::track {
namespace {

using test::Contains;

const std::filesystem::path kDarlington = test::SourcePath("data/tracks/darlington.yaml");

// Public facts (/work/shared/data/README.md, docs/tracks.md).
TEST(SegmentTrackIoTest, DarlingtonClosesAndHasThePublicFigures) {
  const SegmentTrack d = LoadSegmentTrack(kDarlington);
  const Track& t = d.track;
  EXPECT_EQ(t.name(), "darlington");
  EXPECT_NEAR(t.length_m(), 2198.0, 1e-8);  // 1.366 mi
  EXPECT_EQ(t.winding(), 1);                // anticlockwise
  // Acceptance: closes to within 0.01 m and 1e-6 rad (in fact to rounding).
  EXPECT_LT(t.closure_error().position_m(), 0.01);
  EXPECT_LT(std::abs(t.closure_error().heading_rad), 1e-6);
  EXPECT_LT(t.closure_error().position_m(), 1e-9);
  EXPECT_LT(std::abs(t.closure_error().heading_rad), 1e-12);
  // Straights solved near the public "about 375 m", equal by the loop's symmetry.
  ASSERT_EQ(d.unknowns.size(), 4u);
  EXPECT_EQ(d.unknowns[0].name, "front_stretch_m");
  EXPECT_NEAR(d.unknowns[0].value, 375.0, 5.0);
  EXPECT_NEAR(d.unknowns[1].value, d.unknowns[0].value, 1e-6);
  // Turn 1 and turn 3 entries near 200 m and 1300 m (start/finish mid front stretch).
  ASSERT_EQ(d.spans.size(), 8u);
  EXPECT_NEAR(d.spans[1].start_m, 200.0, 15.0);
  EXPECT_NEAR(d.spans[5].start_m, 1300.0, 15.0);
  // Each end turns more than a semicircle's length, the egg's turns 3-4 are tighter.
  EXPECT_GT(d.spans[1].length_m + d.spans[2].length_m + d.spans[3].length_m, kPi * 183.0);
  EXPECT_GT(d.spans[5].length_m + d.spans[6].length_m + d.spans[7].length_m, kPi * 160.0);
  // The straights are not parallel: turns 1-2 turn through more than 180 deg.
  const double turn_12 = d.unknowns[2].value + 150.0 / 183.0;
  EXPECT_GT(turn_12, kPi + DegToRad(1));
}

TEST(SegmentTrackIoTest, DarlingtonCurvatureAndBankingMatchTheSegments) {
  const SegmentTrack d = LoadSegmentTrack(kDarlington);
  const Track& t = d.track;
  const double banks_deg[] = {3, 25, 2, 23};  // front, turns 1-2, back, turns 3-4: public
  for (int k = 0; k < 4; ++k) {
    const SegmentSpan& g = d.spans[2 * k];
    for (double u = 0.01; u < 1.0; u += 0.07) {
      const TrackPoint p = t.At(g.start_m + u * g.length_m);
      EXPECT_NEAR(RadToDeg(p.bank_rad), banks_deg[k], 1e-12) << k;
      EXPECT_NEAR(p.curvature_per_m, k % 2 == 0 ? 0.0 : (k == 1 ? 1 / 183.0 : 1 / 160.0), 1e-15);
    }
  }
  // In the clothoids the curvature ramps linearly and the bank follows the smoothstep.
  const SegmentSpan& entry = d.spans[1];
  for (double u = 0.0; u <= 1.0; u += 0.1) {
    const TrackPoint p = t.At(entry.start_m + u * entry.length_m);
    EXPECT_NEAR(p.curvature_per_m, u / 183.0, 1e-14) << u;
    EXPECT_NEAR(RadToDeg(p.bank_rad), 3 + 22 * (3 * u * u - 2 * u * u * u), 1e-10) << u;
  }
  // Widths: 18 m, narrowing to 15 m in turns 3-4 (assumed, labelled in the file).
  EXPECT_NEAR(t.At(0).width_left_m + t.At(0).width_right_m, 18.0, 1e-12);
  const SegmentSpan& t34 = d.spans[6];
  EXPECT_NEAR(t.At(t34.start_m + 10).width_left_m, 7.5, 1e-12);
}

TEST(SegmentTrackIoTest, DarlingtonSummary) {
  const Track t = LoadSegmentTrack(kDarlington).track;
  const TrackSummary s = Summarize(t);
  EXPECT_NEAR(s.min_radius_m, 160.0, 1e-9);
  EXPECT_NEAR(RadToDeg(s.bank_min_rad), 2.0, 1e-9);
  EXPECT_NEAR(RadToDeg(s.bank_max_rad), 25.0, 1e-9);
  ASSERT_EQ(s.turns.size(), 2u);
  EXPECT_NEAR(s.turns[0].entry_m, 187.285, 0.01);  // the clothoid's start, refined
  EXPECT_NEAR(s.turns[1].entry_m, 1297.070, 0.01);
  EXPECT_NEAR(s.turns[0].min_radius_m, 183.0, 1e-9);
  EXPECT_NEAR(s.turns[1].min_radius_m, 160.0, 1e-9);
  EXPECT_NEAR(RadToDeg(s.turns[1].max_bank_rad), 23.0, 1e-9);
}

// A small valid file to break in the error tests below.
const char* kSmall = R"(name: small
model: segments
width_left_m: 6     # assumed
width_right_m: 6
segments:
  - {type: straight, length_m: 100, bank_deg: 2}
  - {type: clothoid, length_m: 50}
  - {type: arc, radius_m: 80, angle_deg: 144.1901378, turn: left, bank_deg: 10}
  - {type: clothoid, length_m: 50}
  - {type: straight, length_m: 100, bank_deg: 2}
  - {type: clothoid, length_m: 50}
  - {type: arc, radius_m: 80, angle_deg: 144.1901378, turn: left, bank_deg: 10}
  - {type: clothoid, length_m: 50}
)";

class SegmentFileErrorTest : public ::testing::Test {
 protected:
  // Loads kSmall with `from` replaced by `to`; expects an InputError containing every needle.
  void ExpectError(const std::string& from, const std::string& to,
                   const std::vector<std::string>& needles) {
    const auto path = dir_.Write("t.yaml", test::ReplaceOnce(kSmall, from, to));
    try {
      LoadSegmentTrack(path);
      ADD_FAILURE() << "no error for " << to;
    } catch (const InputError& e) {
      EXPECT_TRUE(Contains(e.what(), path.string())) << e.what();
      for (const std::string& n : needles) EXPECT_TRUE(Contains(e.what(), n));
    }
  }
  test::TempDir dir_;
};

TEST_F(SegmentFileErrorTest, TheSmallFileLoads) {
  const SegmentTrack t = LoadSegmentTrack(dir_.Write("t.yaml", kSmall));
  // 144.19 deg arcs (180 deg less the clothoids' 2 x 50 m / 80 m) close to within the rounding
  // of the angle.
  EXPECT_LT(t.track.closure_error().position_m(), 0.01);
}

TEST_F(SegmentFileErrorTest, UnknownKey) {
  ExpectError("bank_deg: 2}", "bank_deg: 2, camber: 1}", {"unknown field 'segments[0].camber'"});
}

TEST_F(SegmentFileErrorTest, WrongUnitInKey) {
  ExpectError("length_m: 100", "length_ft: 328",
              {"missing field 'segments[0].length_m'", "'length_ft'"});
}

TEST_F(SegmentFileErrorTest, MissingTopLevelKey) {
  ExpectError("width_right_m: 6\n", "", {"missing field 'width_right_m'"});
}

TEST_F(SegmentFileErrorTest, NegativeLength) {
  ExpectError("length_m: 100", "length_m: -100",
              {"field 'segments[0].length_m'", "-100", "must be > 0 m"});
}

TEST_F(SegmentFileErrorTest, BankOutOfRange) {
  ExpectError("bank_deg: 10", "bank_deg: 60",
              {"field 'segments[2].bank_deg'", "60", "in [-45, 45] deg"});
}

TEST_F(SegmentFileErrorTest, LoopThatDoesNotClose) {
  ExpectError(
      "length_m: 100", "length_m: 110",
      {"field 'segments'", "the loop does not close", "the end is 10 m from the start", "solve"});
}

TEST_F(SegmentFileErrorTest, ClothoidTakesNoBank) {
  ExpectError("{type: clothoid, length_m: 50}", "{type: clothoid, length_m: 50, bank_deg: 5}",
              {"field 'segments[1].bank_deg'", "a clothoid takes only length_m"});
}

TEST_F(SegmentFileErrorTest, TwoClothoidsInARow) {
  ExpectError("{type: straight, length_m: 100, bank_deg: 2}", "{type: clothoid, length_m: 100}",
              {"field 'segments[0]'", "segments[7] is also a clothoid", "wraps around"});
}

TEST_F(SegmentFileErrorTest, ArcNeedsAngleOrLength) {
  ExpectError("angle_deg: 144.1901378, ", "",
              {"segments[2].angle_deg", "angle_deg or its length_m"});
  ExpectError("angle_deg: 144.1901378, ", "angle_deg: 144.1901378, length_m: 200, ",
              {"segments[2].angle_deg", "not both"});
}

TEST_F(SegmentFileErrorTest, RadiusInsideTheTrack) {
  ExpectError("radius_m: 80", "radius_m: 5", {"segments[2].radius_m", "inside half-width 6 m"});
}

TEST_F(SegmentFileErrorTest, UndeclaredUnknown) {
  ExpectError("length_m: 100", "length_m: front_m",
              {"segments[0].length_m", "'front_m' is neither a number", "declared: (none)"});
}

TEST_F(SegmentFileErrorTest, UnknownWithTheWrongUnit) {
  ExpectError("segments:\n  - {type: straight, length_m: 100",
              "solve:\n  a_deg: 10\nsegments:\n  - {type: straight, length_m: a_deg",
              {"segments[0].length_m", "wrong unit", "_m"});
}

TEST_F(SegmentFileErrorTest, UnknownNameWithoutUnit) {
  ExpectError("segments:\n", "solve:\n  front: 100\nsegments:\n",
              {"field 'solve.front'", "ends in its unit"});
}

TEST_F(SegmentFileErrorTest, UnusedUnknown) {
  ExpectError("segments:\n", "solve:\n  spare_m: 100\nsegments:\n",
              {"field 'solve.spare_m'", "not used"});
}

TEST_F(SegmentFileErrorTest, SolvedFileLoadsAndReportsItsUnknowns) {
  // The first straight and the first arc's radius and angle: the loop closes exactly.
  std::string text = test::ReplaceOnce(kSmall, "segments:\n",
                                       "solve:\n  a_m: 90\n  r_m: 85\n  t_deg: 140\nsegments:\n");
  text = test::ReplaceOnce(text, "length_m: 100", "length_m: a_m");
  text = test::ReplaceOnce(text, "radius_m: 80, angle_deg: 144.1901378",
                           "radius_m: r_m, angle_deg: t_deg");
  const SegmentTrack t = LoadSegmentTrack(dir_.Write("s2.yaml", text));
  EXPECT_LT(t.track.closure_error().position_m(), 1e-9);
  ASSERT_EQ(t.unknowns.size(), 3u);
  EXPECT_EQ(t.unknowns[1].name, "r_m");
  EXPECT_NEAR(t.unknowns[0].value, 100.0, 1e-6);
  EXPECT_NEAR(t.unknowns[1].value, 80.0, 1e-6);
  EXPECT_NEAR(RadToDeg(t.unknowns[2].value), 144.1901378, 1e-6);
}

// What fuzz/track_yaml_fuzz found (tests/data/fuzz_regressions/track_yaml): a file whose loop
// solve stepped through a geometry the track builder refuses (a NumericalError out of the loader,
// which ended the program) is refused with an InputError naming it.
TEST(SegmentTrackFuzzTest, FuzzRegressionsAreInputErrors) {
  for (const auto& file : test::FuzzRegressions("track_yaml")) {
    EXPECT_TRUE(Contains(test::InputErrorOf([&] { LoadSegmentTrack(file); }), file.string()))
        << file;
  }
}

}  // namespace
}  // namespace hotlap::track
