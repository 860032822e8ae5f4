#include "hotlap/track/tum_csv.h"

#include <cmath>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "test_util.h"

namespace hotlap::track {
namespace {

using test::Contains;

double PolylineLength(const CentreLinePoints& p) {
  double length = 0.0;
  const size_t n = p.x_m.size();
  for (size_t i = 0; i < n; ++i) {
    const size_t j = (i + 1) % n;
    length += std::hypot(p.x_m[j] - p.x_m[i], p.y_m[j] - p.y_m[i]);
  }
  return length;
}

class TumImportTest : public ::testing::TestWithParam<const char*> {};

// Acceptance: the right length within 0.5 % and a closed ribbon; also close to the points.
TEST_P(TumImportTest, LengthWithinHalfAPercentAndCloses) {
  const auto path = test::SourcePath(std::string("data/tracks/") + GetParam() + ".csv");
  const CentreLinePoints points = ReadTumCentreLine(path);
  const Track t = LoadTumTrack(path);
  EXPECT_EQ(t.name(), GetParam());
  const double polyline = PolylineLength(points);
  EXPECT_NEAR(t.length_m(), polyline, 0.005 * polyline);
  // The uncorrected closure is small; after correction the ribbon meets itself.
  EXPECT_LT(t.closure_error().position_m(), 2.0);
  EXPECT_LT(std::abs(t.closure_error().heading_rad), 1e-9);  // heading turns whole turns
  EXPECT_LT(t.spread_closure().position_m(), 1e-7);
  const TrackPoint start = t.At(0.0), end = t.At(t.length_m() - 1e-9);
  EXPECT_NEAR(end.x_m, start.x_m, 1e-6);
  EXPECT_NEAR(end.y_m, start.y_m, 1e-6);
  EXPECT_NEAR(end.heading_rad - 2 * kPi * t.winding(), start.heading_rad, 1e-9);
  EXPECT_NEAR(end.curvature_per_m, start.curvature_per_m, 1e-9);
  EXPECT_NEAR(end.width_left_m, start.width_left_m, 1e-6);
  // Within 2 m of every point (smoothing at 40 m wavelength), bank and grade zero.
  const std::vector<TrackPoint> ribbon = t.Sample(static_cast<int>(t.length_m() / 0.5));
  for (size_t i = 0; i < points.x_m.size(); i += 3) {
    double nearest = 1e9;
    for (const TrackPoint& p : ribbon) {
      nearest = std::min(nearest, std::hypot(p.x_m - points.x_m[i], p.y_m - points.y_m[i]));
    }
    EXPECT_LT(nearest, 2.0) << "point " << i;
  }
  for (const TrackPoint& p : ribbon) {
    EXPECT_EQ(p.bank_rad, 0.0);
    EXPECT_EQ(p.grade_rad, 0.0);
  }
}

TEST_P(TumImportTest, CurvatureIsContinuous) {
  const Track t = LoadTumTrack(test::SourcePath(std::string("data/tracks/") + GetParam() + ".csv"));
  // C1 curvature: over a 1 cm step neither curvature nor its rate jumps.
  double prev_k = t.At(0).curvature_per_m, prev_rate = t.At(0).curvature_rate_per_m2;
  double max_dk = 0.0, max_drate = 0.0;
  for (double s = 0.01; s < t.length_m(); s += 0.01) {
    const TrackPoint p = t.At(s);
    max_dk = std::max(max_dk, std::abs(p.curvature_per_m - prev_k));
    max_drate = std::max(max_drate, std::abs(p.curvature_rate_per_m2 - prev_rate));
    prev_k = p.curvature_per_m;
    prev_rate = p.curvature_rate_per_m2;
  }
  EXPECT_LT(max_dk, 2e-4);
  EXPECT_LT(max_drate, 1e-4);
}

INSTANTIATE_TEST_SUITE_P(Shipped, TumImportTest, ::testing::Values("catalunya", "ims"));

TEST(TumCsvTest, ImsIsAnAnticlockwiseOvalAndCatalunyaClockwise) {
  const Track ims = LoadTumTrack(test::SourcePath("data/tracks/ims.csv"));
  EXPECT_EQ(ims.winding(), 1);
  const Track cat = LoadTumTrack(test::SourcePath("data/tracks/catalunya.csv"));
  EXPECT_EQ(cat.winding(), -1);
  // TUM's widths are kept: Catalunya's first row has w_tr_right 5.894, w_tr_left 5.830.
  EXPECT_NEAR(cat.At(0).width_right_m, 5.894, 1e-12);
  EXPECT_NEAR(cat.At(0).width_left_m, 5.830, 1e-12);
}

// A circle of radius 100 m as TUM points, with the edits the error tests apply.
std::string CircleCsv(int n = 120) {
  std::ostringstream out;
  out << "# x_m,y_m,w_tr_right_m,w_tr_left_m\n";
  for (int i = 0; i < n; ++i) {
    const double a = 2 * kPi * i / n;
    out << 100 * std::cos(a) << "," << 100 * std::sin(a) << ",5,5\n";
  }
  return out.str();
}

TEST(TumCsvTest, CircleImportsAsACircle) {
  test::TempDir dir;
  const Track t = LoadTumTrack(dir.Write("circle.csv", CircleCsv()));
  // Smoothing shrinks a 5 m polyline of a 100 m circle very slightly.
  EXPECT_NEAR(t.length_m(), 2 * kPi * 100, 0.5);
  for (double s = 0; s < t.length_m(); s += 10) {
    EXPECT_NEAR(t.At(s).curvature_per_m, 0.01, 2e-5) << s;
    EXPECT_NEAR(std::hypot(t.At(s).x_m, t.At(s).y_m), 100.0, 0.1) << s;
  }
}

class TumCsvErrorTest : public ::testing::Test {
 protected:
  void ExpectError(const std::string& text, const std::vector<std::string>& needles) {
    const auto path = dir_.Write("bad.csv", text);
    try {
      LoadTumTrack(path);
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_TRUE(Contains(e.what(), path.string())) << e.what();
      for (const std::string& n : needles) EXPECT_TRUE(Contains(e.what(), n));
    }
  }
  test::TempDir dir_;
};

TEST_F(TumCsvErrorTest, WrongHeader) {
  ExpectError(test::ReplaceOnce(CircleCsv(), "w_tr_left_m", "w_left_m"),
              {"bad.csv:1:", "expected the TUM header"});
}

TEST_F(TumCsvErrorTest, NotANumber) {
  ExpectError(test::ReplaceOnce(CircleCsv(), ",5,5\n", ",nan,5\n"),
              {"bad.csv:2:", "column 'w_tr_right_m' (column 3)", "'nan' is not a number"});
}

TEST_F(TumCsvErrorTest, RaggedRow) {
  ExpectError(test::ReplaceOnce(CircleCsv(), ",5,5\n", ",5\n"), {"bad.csv:2:", "3 cells"});
}

TEST_F(TumCsvErrorTest, NonPositiveWidth) {
  ExpectError(test::ReplaceOnce(CircleCsv(), ",5,5\n", ",5,0\n"),
              {"bad.csv:2:", "'w_tr_left_m'", "must be > 0 m"});
}

TEST_F(TumCsvErrorTest, RepeatedPoint) {
  std::string text = CircleCsv();
  const size_t second = text.find('\n', text.find('\n') + 1) + 1;
  const std::string first_row = text.substr(text.find('\n') + 1, second - text.find('\n') - 1);
  text.insert(second, first_row);
  ExpectError(text, {"bad.csv:3:", "repeats the one on line 2"});
}

TEST_F(TumCsvErrorTest, OpenLoop) {
  // Only the first half of the circle: the last point is 200 m from the first.
  std::string text = CircleCsv();
  std::istringstream in(text);
  std::string line, half;
  for (int i = 0; i <= 60 && std::getline(in, line); ++i) half += line + "\n";
  ExpectError(half, {"not a closed loop", "median spacing"});
}

TEST_F(TumCsvErrorTest, PointFarOffTheLine) {
  // The tenth point thousands of km out (its x prefixed with -30000) on a line sampled every 5 m.
  std::string text = CircleCsv();
  size_t at = 0;
  for (int i = 0; i < 10; ++i) at = text.find('\n', at) + 1;
  text.insert(at, "-30000");
  ExpectError(text, {"bad.csv:11:", "more than 20 times the median spacing"});
}

TEST_F(TumCsvErrorTest, TooFewPoints) { ExpectError(CircleCsv(10), {"10 points", "at least 20"}); }

// What fuzz/tum_csv_fuzz found (tests/data/fuzz_regressions/tum_csv): each file is refused with
// an InputError naming it (a point 2500 km out made a track of a million pieces, out of memory).
TEST(TumCsvTest, FuzzRegressionsAreInputErrors) {
  for (const auto& file : test::FuzzRegressions("tum_csv")) {
    EXPECT_TRUE(Contains(test::InputErrorOf([&] { LoadTumTrack(file); }), file.string())) << file;
  }
}

}  // namespace
}  // namespace hotlap::track
