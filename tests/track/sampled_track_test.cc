#include "hotlap/track/sampled_track.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/units.h"

namespace hotlap::track {
namespace {

// Curvature samples of a stadium (straights and half circles) with a deliberate error in the
// curvature, so that the loop does not close until corrected.
CurvatureSamples Stadium(double kappa_error) {
  CurvatureSamples c;
  const double straight = 200, radius = 50, h = 2.0;
  c.length_m = 2 * straight + 2 * kPi * radius;
  for (double s = 0; s < c.length_m - 1e-9; s += h) {
    const double u = std::fmod(s, straight + kPi * radius);
    c.s_m.push_back(s);
    c.curvature_per_m.push_back((u < straight ? 0.0 : 1 / radius) + kappa_error);
    c.width_left_m.push_back(6.0);
    c.width_right_m.push_back(s < 100 ? 6.0 : 7.0);
  }
  c.start = {0, 0, 0, 0};
  return c;
}

TEST(SampledTrackTest, ClosureCorrectionClosesAndReportsTheGapBefore) {
  const CurvatureSamples c = Stadium(2e-5);
  const Track t = TrackFromCurvature("stadium", c);
  // The gap before correction: the trapezoidal integral of the samples, less one turn.
  double turn = 0.0;
  for (size_t i = 0; i < c.s_m.size(); ++i) {
    const size_t j = (i + 1) % c.s_m.size();
    const double h = (j == 0 ? c.length_m : c.s_m[j]) - c.s_m[i];
    turn += h * (c.curvature_per_m[i] + c.curvature_per_m[j]) / 2;
  }
  EXPECT_NEAR(t.closure_error().heading_rad, turn - 2 * kPi, 1e-12);
  EXPECT_GT(std::abs(t.closure_error().heading_rad), 1e-3);
  EXPECT_GT(t.closure_error().position_m(), 1.0);
  EXPECT_LT(t.spread_closure().position_m(), 1e-7);
  EXPECT_LT(std::abs(t.spread_closure().heading_rad), 1e-10);
  // The corrected curvature is within the error of the samples' (smooth correction).
  for (double s = 10; s < 190; s += 10) EXPECT_NEAR(t.At(s).curvature_per_m, 0.0, 1e-4) << s;
}

TEST(SampledTrackTest, WidthsDoNotOvershootASteppedSample) {
  const Track t = TrackFromCurvature("stadium", Stadium(0.0));
  for (double s = 0; s < t.length_m(); s += 0.25) {
    EXPECT_GE(t.At(s).width_right_m, 6.0 - 1e-12) << s;
    EXPECT_LE(t.At(s).width_right_m, 7.0 + 1e-12) << s;
  }
}

TEST(SampledTrackTest, CentreLineOfAnEllipseFollowsTheEllipse) {
  // An ellipse 300 m x 150 m as 400 points: curvature between 1/600 and 1/37.5 m^-1.
  CentreLinePoints p;
  const int n = 400;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * kPi * i / n;
    p.x_m.push_back(300 * std::cos(a));
    p.y_m.push_back(150 * std::sin(a));
    p.width_left_m.push_back(5);
    p.width_right_m.push_back(5);
  }
  const Track t = TrackFromCentreLine("ellipse", p);
  // Ramanujan's perimeter of the ellipse.
  const double a = 300, b = 150;
  const double perimeter = kPi * (3 * (a + b) - std::sqrt((3 * a + b) * (a + 3 * b)));
  EXPECT_NEAR(t.length_m(), perimeter, 1e-3 * perimeter);
  EXPECT_EQ(t.winding(), 1);
  for (double s = 0; s < t.length_m(); s += 13) {
    const TrackPoint q = t.At(s);
    // On the ellipse, and the curvature of the ellipse at that point (smoothing costs a little
    // at the tight ends).
    const double angle = std::atan2(q.y_m / b, q.x_m / a);
    const double ex = a * std::cos(angle), ey = b * std::sin(angle);
    EXPECT_NEAR(std::hypot(q.x_m - ex, q.y_m - ey), 0.0, 0.2) << s;
    const double k = a * b /
                     std::pow(a * a * std::sin(angle) * std::sin(angle) +
                                  b * b * std::cos(angle) * std::cos(angle),
                              1.5);
    EXPECT_NEAR(q.curvature_per_m, k, 0.02 * k + 1e-5) << s;
  }
}

}  // namespace
}  // namespace hotlap::track
