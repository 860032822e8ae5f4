// The paper's friction law (002:1) and surfaces made of segments along the road.

#include "hotlap/abs/abs_surface.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "test_util.h"

namespace {

using hotlap::sim::FrictionLaw;
using hotlap::sim::Surface;

TEST(FrictionLawTest, ThePapersLawRunsFromStaticToKineticFriction) {
  const FrictionLaw<double> paper{0.90, 0.45, 0.5};  // 002 §2.1.3
  EXPECT_DOUBLE_EQ(paper.Friction(0.0), 0.90);
  EXPECT_NEAR(paper.Friction(1e3), 0.45, 1e-12);
  // mu = 0.45 + 0.45 exp(-0.5 * 2) at 2 m/s of slip speed; the sign of v_s does not matter.
  EXPECT_DOUBLE_EQ(paper.Friction(2.0), 0.45 + 0.45 * std::exp(-1.0));
  EXPECT_DOUBLE_EQ(paper.Friction(-2.0), paper.Friction(2.0));
}

TEST(FrictionLawTest, DifferentiatesInTheSlipSpeedAndTheCoefficients) {
  using J = hotlap::Jet2;
  FrictionLaw<J> law = FrictionLaw<double>{0.9, 0.45, 0.5}.Cast<J>();
  law.decay.v[1] = 1.0;
  const J mu = law.Friction(J(1.5, 0));
  const double e = std::exp(-0.75);
  EXPECT_NEAR(mu.v[0], -0.45 * 0.5 * e, 1e-14);  // d mu / d v_s
  EXPECT_NEAR(mu.v[1], -0.45 * 1.5 * e, 1e-14);  // d mu / d d_c
}

TEST(SurfaceTest, FindsTheSegmentUnderTheWheelAndWhereItEnds) {
  Surface s{"split", {{0.0, "dry", {1.1, 0.7, 0.5}}, {3.0, "wet", {0.8, 0.45, 0.8}}}};
  EXPECT_EQ(s.SegmentAt(-1.0), 0u);
  EXPECT_EQ(s.SegmentAt(2.999), 0u);
  EXPECT_EQ(s.SegmentAt(3.0), 1u);
  EXPECT_EQ(s.SegmentAt(50.0), 1u);
  EXPECT_DOUBLE_EQ(s.SegmentEnd(0), 3.0);
  EXPECT_EQ(s.SegmentEnd(1), std::numeric_limits<double>::infinity());
}

}  // namespace
