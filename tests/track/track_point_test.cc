#include "hotlap/track/track_point.h"

#include <cmath>

#include <gtest/gtest.h>

#include "hotlap/common/units.h"

namespace hotlap::track {
namespace {

TrackPoint Banked(double heading_deg, double bank_deg, double curvature) {
  TrackPoint p;
  p.x_m = 10.0;
  p.y_m = -4.0;
  p.heading_rad = DegToRad(heading_deg);
  p.bank_rad = DegToRad(bank_deg);
  p.curvature_per_m = curvature;
  return p;
}

TEST(TrackPointTest, PositiveBankPutsTheLeftEdgeDown) {
  // An anticlockwise oval's turn: turning left, banked 25 deg, heading north.
  const TrackPoint p = Banked(90, 25, 1.0 / 183);
  const Eigen::Vector3d left = PointAtOffset(p, 9.0), right = PointAtOffset(p, -9.0);
  EXPECT_LT(left.z(), 0.0);   // inside edge down
  EXPECT_GT(right.z(), 0.0);  // outside edge up
  EXPECT_NEAR(right.z() - left.z(), 18.0 * std::sin(DegToRad(25)), 1e-12);
  EXPECT_LT(left.x(), p.x_m);  // heading north, left is west (-x)
  // The road normal leans toward the inside of the turn (the left).
  const Eigen::Vector3d n = NormalUnit(p);
  EXPECT_LT(n.x(), 0.0);
  EXPECT_NEAR(n.z(), std::cos(DegToRad(25)), 1e-12);
}

TEST(TrackPointTest, FrameIsRightHandedAndOrthonormal) {
  TrackPoint p = Banked(37, -12, 0.0);
  p.grade_rad = DegToRad(4);
  const Eigen::Vector3d t = TangentUnit(p), l = LateralUnit(p), n = NormalUnit(p);
  EXPECT_NEAR(t.norm(), 1.0, 1e-15);
  EXPECT_NEAR(l.norm(), 1.0, 1e-15);
  EXPECT_NEAR(t.dot(l), 0.0, 1e-15);
  EXPECT_NEAR(t.cross(l).dot(n), 1.0, 1e-15);
  EXPECT_GT(t.z(), 0.0);  // uphill
}

TEST(TrackPointTest, GeodesicAndNormalCurvature) {
  // Spec section 10: kappa_g = kappa_h cos(theta), kappa_n = kappa_h sin(theta).
  const TrackPoint p = Banked(0, 25, 1.0 / 183);
  EXPECT_NEAR(GeodesicCurvature(p), std::cos(DegToRad(25)) / 183, 1e-15);
  EXPECT_NEAR(NormalCurvature(p), std::sin(DegToRad(25)) / 183, 1e-15);
  // The centre line's curvature vector (horizontal, toward the left) split on the ribbon frame.
  const Eigen::Vector3d curvature_vector =
      p.curvature_per_m * Eigen::Vector3d(-std::sin(p.heading_rad), std::cos(p.heading_rad), 0);
  EXPECT_NEAR(curvature_vector.dot(LateralUnit(p)), GeodesicCurvature(p), 1e-15);
  EXPECT_NEAR(curvature_vector.dot(NormalUnit(p)), NormalCurvature(p), 1e-15);
}

}  // namespace
}  // namespace hotlap::track
