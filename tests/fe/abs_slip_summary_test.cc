// The FE braking step's slip summary (002 Fig. 10 terms) on hand-made histories.

#include "hotlap/fe/abs_slip_summary.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace hotlap::fe {
namespace {

// Rows every 10 ms with the given slips.
std::vector<HistoryRow> History(const std::vector<double>& slips) {
  std::vector<HistoryRow> h(slips.size());
  for (size_t k = 0; k < slips.size(); ++k) {
    h[k].time_s = 0.01 * static_cast<double>(k);
    h[k].slip = slips[k];
  }
  return h;
}

TEST(BrakeSlipSummaryTest, FirstCycleEndsWhenTheSlipFallsBackBelowAThirdOfTheTarget) {
  // Up past 0.135, back down to 0.04 at row 4 (t = 0.04 s), then 6 intervals of which 2 start
  // above the target (0.15 at rows 6 and 7): 4 of 6 intervals below.
  const BrakeSlipSummary s =
      SummarizeBrakeSlip(History({0.0, 0.1, 0.2, 0.1, 0.04, 0.1, 0.15, 0.15, 0.1, 0.05, 0.12}));
  EXPECT_DOUBLE_EQ(s.max_slip, 0.2);
  EXPECT_NEAR(s.first_cycle_end_s, 0.04, 1e-15);
  EXPECT_DOUBLE_EQ(s.max_slip_after_first_cycle, 0.15);
  EXPECT_NEAR(s.fraction_time_below_0_135_after_first_cycle, 4.0 / 6.0, 1e-12);
}

TEST(BrakeSlipSummaryTest, NoCycleWithoutExceedingTheTargetAndFallingBack) {
  // Never above the target: no cycle, even though the slip dips below 0.045.
  BrakeSlipSummary s = SummarizeBrakeSlip(History({0.0, 0.1, 0.02, 0.13}));
  EXPECT_DOUBLE_EQ(s.max_slip, 0.13);
  EXPECT_TRUE(std::isnan(s.first_cycle_end_s));
  EXPECT_TRUE(std::isnan(s.fraction_time_below_0_135_after_first_cycle));
  // Above the target and never back below 0.045 (a locking wheel): no cycle either.
  s = SummarizeBrakeSlip(History({0.0, 0.2, 0.5, 0.9}));
  EXPECT_DOUBLE_EQ(s.max_slip, 0.9);
  EXPECT_TRUE(std::isnan(s.max_slip_after_first_cycle));
  // An empty history: nothing.
  s = SummarizeBrakeSlip({});
  EXPECT_EQ(s.max_slip, 0.0);
  EXPECT_TRUE(std::isnan(s.first_cycle_end_s));
}

}  // namespace
}  // namespace hotlap::fe
