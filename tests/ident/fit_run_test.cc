// The short texts of an estimate that the fit's terminal table and report share.

#include "hotlap/ident/fit_run.h"

#include <cmath>
#include <limits>

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

}  // namespace
}  // namespace hotlap::ident
