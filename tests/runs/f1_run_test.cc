// The F1 car's run: overrides and disc limits refused with what the planar model lacks, the
// warning on a banked track (none on a flat one), and the run's Ipopt settings carried over.

#include "hotlap/runs/f1_run.h"

#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/track/track_io.h"
#include "test_util.h"

namespace hotlap::runs {
namespace {

TEST(F1Run, OverridesAndDiscLimitsAreRefused) {
  ocp::OptimalRunOptions run;
  EXPECT_NO_THROW(CheckF1Run("f1-2014", false, run));
  EXPECT_TRUE(test::Contains(test::InputErrorOf([&] { CheckF1Run("f1-2014", true, run); }),
                             "--set does not apply to the car 'f1-2014'"));
  run.compare_disc_limit_C = 500.0;
  EXPECT_EQ(test::InputErrorOf([&] { CheckF1Run("f1-2014", false, run); }),
            "the limebeer-2014-f1 car has no brake temperatures: no disc limit");
}

TEST(F1Run, ABankedTrackIsWarnedOfAndAFlatOneIsNot) {
  const std::string banked = PlanarTrackWarning(track::LoadTrack("darlington"));
  EXPECT_TRUE(test::Contains(banked, "the limebeer-2014-f1 model is planar")) << banked;
  EXPECT_EQ(PlanarTrackWarning(track::LoadTrack("catalunya-fl")), "");
}

TEST(F1Run, TheRunsIpoptSettingsAreCarried) {
  ocp::OptimalRunOptions run;
  run.max_iterations = 77;
  run.ipopt_output = true;
  run.ipopt_options = {{"mumps_pivot_order", "5"}};
  const ocp::IpoptOptions ipopt = F1RunIpoptOptions(run);
  EXPECT_EQ(ipopt.max_iterations, 77);
  EXPECT_EQ(ipopt.print_level, 5);
  ASSERT_FALSE(ipopt.extra.empty());
  EXPECT_EQ(ipopt.extra.back().first, "mumps_pivot_order");
}

}  // namespace
}  // namespace hotlap::runs
