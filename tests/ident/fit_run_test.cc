// The short texts of an estimate that the fit's terminal table and report share.

#include "hotlap/ident/fit_run.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace hotlap::ident {
namespace {

TEST(FitRunText, ShortNumberHasFourDigitsAndNamesTheNonFinite) {
  EXPECT_EQ(ShortNumber(0.123456), "0.1235");
  EXPECT_EQ(ShortNumber(1234567.0), "1.235e+06");
  EXPECT_EQ(ShortNumber(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(ShortNumber(-std::numeric_limits<double>::infinity()), "-inf");
  EXPECT_EQ(ShortNumber(std::nan("")), "n/a");
}

TEST(FitRunText, IntervalsAreInDisplayUnitsAndJointOnlyForModelParameters) {
  const FitParameter model{.key = "t", .label = "T", .display_offset = -273.15};
  FitParameter nuisance = model;
  nuisance.role = ParameterRole::kNuisance;
  ParameterEstimate e{.value = 300.0, .ci_low = 299.0, .ci_high = 301.0};
  e.joint_low = 298.0;
  e.joint_high = 302.0;
  EXPECT_EQ(IntervalText(model, e), "[25.85, 27.85]");
  EXPECT_EQ(JointIntervalText(model, e), "[24.85, 28.85]");
  EXPECT_EQ(JointIntervalText(nuisance, e), "");
}

TEST(FitRunText, VerdictPutsUndeterminedBeforeAtBound) {
  ParameterEstimate e;
  EXPECT_EQ(VerdictText(e), "no");
  e.well_determined = true;
  EXPECT_EQ(VerdictText(e), "yes");
  e.at_bound = true;
  EXPECT_EQ(VerdictText(e), "at bound");
  e.undetermined = true;
  EXPECT_EQ(VerdictText(e), "undetermined");
}

TEST(FitRunText, TheTableNamesTheLogTheCornersAndTheTimeAndTheWarningsTheirCorner) {
  FitRun run;
  run.command = "fit brake";
  run.telemetry = "log.csv";
  run.car_name = "gen7";
  run.time = {1.0, 2.0, 3.5};
  run.elapsed_s = 0.25;
  CornerFitOutcome rr;
  rr.corner = Corner::kRearRight;
  rr.rms = {{"rms_disc_C", 1.23456}};
  rr.warnings = {"no calliper channel"};
  run.result.corners.push_back(rr);
  EXPECT_EQ(FitRunText(run),
            "hotlap fit brake: log.csv (3 samples, 2.50 s of log) with car 'gen7'\n"
            "rr:  rms_disc_C 1.235\n"
            "fitted in 0.25 s\n");
  const std::vector<std::string> warnings = FitRunWarnings(run);
  ASSERT_FALSE(warnings.empty());
  EXPECT_EQ(warnings.front().rfind("rr: ", 0), 0u) << warnings.front();
}

}  // namespace
}  // namespace hotlap::ident
