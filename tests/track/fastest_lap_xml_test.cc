#include "hotlap/track/fastest_lap_xml.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/common/xml_file.h"
#include "hotlap/track/tum_csv.h"
#include "test_util.h"

namespace hotlap::track {
namespace {

using test::Contains;

const std::filesystem::path kCircuit = test::SourcePath("data/tracks/catalunya-fl.xml");

// One comma-separated array of the file, e.g. Array({"data", "yaw"}).
std::vector<double> Array(const std::vector<std::string>& path) {
  const XmlFile xml = XmlFile::Load(kCircuit);
  pugi::xml_node e = xml.root();
  for (const std::string& name : path) e = e.child(name.c_str());
  std::vector<double> out;
  std::stringstream in(e.child_value());
  std::string cell;
  while (std::getline(in, cell, ',')) out.push_back(std::stod(cell));
  return out;
}

TEST(FastestLapXmlTest, LengthMatchesTheHeaderAndTheLoopCloses) {
  const Track t = LoadFastestLapCircuit(kCircuit);
  EXPECT_EQ(t.name(), "catalunya-fl");
  EXPECT_NEAR(t.length_m(), 4634.15, 0.005 * 4634.15);  // acceptance: within 0.5 %
  EXPECT_NEAR(t.length_m(), 4634.1501076379418, 1e-9);  // in fact exactly the header
  EXPECT_EQ(t.winding(), -1);                           // clockwise, as the circuit is run
  // Curvature linear between the file's points integrates to its own yaw: the heading closes
  // before any correction, and the position to about 2 cm.
  EXPECT_LT(std::abs(t.closure_error().heading_rad), 1e-12);
  EXPECT_LT(t.closure_error().position_m(), 0.05);
  const TrackPoint start = t.At(0.0), end = t.At(t.length_m() - 1e-9);
  EXPECT_NEAR(end.x_m, start.x_m, 1e-6);
  EXPECT_NEAR(end.y_m, start.y_m, 1e-6);
}

TEST(FastestLapXmlTest, HeadingsCurvaturesAndWidthsAreTheFilesMirrored) {
  const Track t = LoadFastestLapCircuit(kCircuit);
  const std::vector<double> s = Array({"data", "arclength"});
  const std::vector<double> yaw = Array({"data", "yaw"});
  const std::vector<double> kappa = Array({"data", "yaw_dot"});
  const std::vector<double> nl = Array({"data", "nl"});
  const std::vector<double> nr = Array({"data", "nr"});
  ASSERT_EQ(s.size(), 500u);
  for (size_t i = 0; i < s.size(); i += 7) {
    const TrackPoint p = t.At(s[i]);
    // y mirrored: heading and curvature change sign. The closure correction of the 1.6 cm gap
    // (about 3e-8 1/m) moves the heading by up to 1e-4 rad.
    EXPECT_NEAR(p.heading_rad, -yaw[i], 2e-4) << i;
    EXPECT_NEAR(p.curvature_per_m, -kappa[i], 1e-7) << i;
    EXPECT_NEAR(p.width_left_m, nl[i], 1e-9) << i;
    EXPECT_NEAR(p.width_right_m, nr[i], 1e-9) << i;
  }
}

TEST(FastestLapXmlTest, LeftEdgeIsTheFilesLeftBoundary) {
  // The mirror keeps fastest-lap's left boundary on hotlap's left (y left of x).
  const Track t = LoadFastestLapCircuit(kCircuit);
  const std::vector<double> s = Array({"data", "arclength"});
  const std::vector<double> lx = Array({"data", "left_boundary", "x"});
  const std::vector<double> ly = Array({"data", "left_boundary", "y"});
  const std::vector<double> cx = Array({"data", "centerline", "x"});
  const std::vector<double> cy = Array({"data", "centerline", "y"});
  double worst = 0.0;
  for (size_t i = 0; i < s.size(); ++i) {
    const TrackPoint p = t.At(s[i]);
    const Eigen::Vector3d left = PointAtOffset(p, p.width_left_m);
    // Compare the edge relative to the centre line: fastest-lap's own centre line is a coarser
    // (trapezoidal) integral of the same headings, so whole positions drift by up to 0.5 m.
    const double dx = (left.x() - p.x_m) - (lx[i] - cx[i]);
    const double dy = (left.y() - p.y_m) - (-ly[i] + cy[i]);
    worst = std::max(worst, std::hypot(dx, dy));
    EXPECT_NEAR(p.x_m, cx[i], 1.0) << i;
    EXPECT_NEAR(p.y_m, -cy[i], 1.0) << i;
  }
  EXPECT_LT(worst, 1e-3);  // the file's boundaries agree with its own yaw and nl to 0.6 mm
}

TEST(FastestLapXmlTest, SameCircuitAsTumsCentreLine) {
  // Independent data of the same circuit: the same shape after moving the centroid (the two
  // files put their origin at different points of the main straight).
  const Track fl = LoadFastestLapCircuit(kCircuit);
  const Track tum = LoadTumTrack(test::SourcePath("data/tracks/catalunya.csv"));
  const std::vector<TrackPoint> a = fl.Sample(2000), b = tum.Sample(4000);
  Eigen::Vector2d ca = Eigen::Vector2d::Zero(), cb = Eigen::Vector2d::Zero();
  for (size_t i = 0; i + 1 < a.size(); ++i) ca += Eigen::Vector2d(a[i].x_m, a[i].y_m) / 2000;
  for (size_t i = 0; i + 1 < b.size(); ++i) cb += Eigen::Vector2d(b[i].x_m, b[i].y_m) / 4000;
  double sum = 0.0, worst = 0.0;
  for (size_t i = 0; i < a.size(); i += 4) {
    const Eigen::Vector2d p = Eigen::Vector2d(a[i].x_m, a[i].y_m) - ca + cb;
    double nearest = 1e9;
    for (const TrackPoint& q : b)
      nearest = std::min(nearest, (p - Eigen::Vector2d(q.x_m, q.y_m)).norm());
    sum += nearest;
    worst = std::max(worst, nearest);
  }
  EXPECT_LT(sum / (a.size() / 4), 5.0);  // a mirrored shape would be off by hundreds of metres
  EXPECT_LT(worst, 15.0);
  EXPECT_NEAR(fl.length_m(), tum.length_m(), 0.01 * tum.length_m());
}

class FastestLapErrorTest : public ::testing::Test {
 protected:
  void ExpectError(const std::string& from, const std::string& to,
                   const std::vector<std::string>& needles) {
    const auto path =
        dir_.Write("bad.xml", test::ReplaceOnce(test::ReadTextFile(kCircuit), from, to));
    try {
      LoadFastestLapCircuit(path);
      ADD_FAILURE() << "no error for " << to;
    } catch (const InputError& e) {
      EXPECT_TRUE(Contains(e.what(), path.string())) << e.what();
      for (const std::string& n : needles) EXPECT_TRUE(Contains(e.what(), n));
    }
  }
  test::TempDir dir_;
};

TEST_F(FastestLapErrorTest, WrongFormat) {
  ExpectError("format=\"discrete\"", "format=\"continuous\"",
              {":1:", "format=\"continuous\" is not supported"});
}

TEST_F(FastestLapErrorTest, MissingElement) {
  std::string text = test::ReplaceOnce(test::ReadTextFile(kCircuit), "<yaw_dot ", "<curvature ");
  text = test::ReplaceOnce(text, "</yaw_dot>", "</curvature>");
  const auto path = dir_.Write("bad.xml", text);
  try {
    LoadFastestLapCircuit(path);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), path.string() + ":")) << e.what();
    EXPECT_TRUE(Contains(e.what(), "<data>: missing element <yaw_dot>")) << e.what();
  }
}

TEST_F(FastestLapErrorTest, WrongCount) {
  ExpectError("<nl units=\"rad\">6.186697911970791, ", "<nl units=\"rad\">",
              {"<nl>", "499 values", "number_of_points=\"500\""});
}

TEST_F(FastestLapErrorTest, NotANumber) {
  ExpectError("<nr units=\"rad\">6.3048762775537188", "<nr units=\"rad\">six",
              {"<nr> value 1", "'six' is not a finite number"});
}

TEST_F(FastestLapErrorTest, NegativeWidth) {
  ExpectError("<nr units=\"rad\">6.3048762775537188", "<nr units=\"rad\">-1",
              {"<nr>", "value 1 (-1) must be > 0 m"});
}

// Malformed XML (pugixml's errors): the file and the line, and what is wrong there.
TEST_F(FastestLapErrorTest, MalformedXml) {
  ExpectError("</header>", "</headr>",
              {":8: XML: start-end tags mismatch: </headr> does not close the element"});
  ExpectError("<data number_of_points=\"500\">", "<data number_of_points=500>",
              {":25: XML: error parsing element attribute at '500>'"});
  ExpectError("</circuit>", "", {":55: XML: start-end tags mismatch: an element is not closed"});
}

TEST_F(FastestLapErrorTest, WrongElementNamesItsLine) {
  ExpectError("<yaw units=\"rad\">2.1417907364643334", "<yaw units=\"rad\">x",
              {":47: <yaw> value 1: 'x' is not a finite number"});
}

// What fuzz/fastest_lap_xml_fuzz found (tests/data/fuzz_regressions/fastest_lap_xml): each file
// is refused with an InputError naming it (curvature that closes into no loop escaped as the
// track builder's NumericalError).
TEST(FastestLapXmlTest, FuzzRegressionsAreInputErrors) {
  for (const auto& file : test::FuzzRegressions("fastest_lap_xml")) {
    EXPECT_TRUE(Contains(test::InputErrorOf([&] { LoadFastestLapCircuit(file); }), file.string()))
        << file;
  }
}

}  // namespace
}  // namespace hotlap::track
