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

TEST(BrakeSlipSummaryTest, WindowRunsFromTheSecondCycleStartToTheEnd) {
  // Cycles begin at 0.015 s, 0.035 s and 0.075 s; the window starts at 0.035 s, i.e. with row 4
  // (t = 0.04): rows 4..10, 6 intervals of which two start above the target (rows 6, 7).
  const std::vector<double> starts = {0.015, 0.035, 0.075};
  const BrakeSlipSummary s = SummarizeBrakeSlip(
      History({0.0, 0.1, 0.2, 0.3, 0.04, 0.1, 0.15, 0.16, 0.1, 0.05, 0.12}), starts);
  EXPECT_DOUBLE_EQ(s.max_slip, 0.3);  // in the first cycle: not counted after it
  EXPECT_EQ(s.cycles, 3);
  EXPECT_NEAR(s.cycles_per_s, 3.0 / (0.10 - 0.015), 1e-9);
  EXPECT_DOUBLE_EQ(s.first_cycle_end_s, 0.035);
  EXPECT_DOUBLE_EQ(s.max_slip_after_first_cycle, 0.16);
  EXPECT_NEAR(s.fraction_time_below_0_135_after_first_cycle, 4.0 / 6.0, 1e-12);
}

TEST(BrakeSlipSummaryTest, FewerThanTwoCyclesLeaveTheWindowUndefined) {
  const std::vector<HistoryRow> h = History({0.0, 0.1, 0.2, 0.13});
  BrakeSlipSummary s = SummarizeBrakeSlip(h, {});
  EXPECT_DOUBLE_EQ(s.max_slip, 0.2);
  EXPECT_EQ(s.cycles, 0);
  EXPECT_EQ(s.cycles_per_s, 0.0);
  EXPECT_TRUE(std::isnan(s.first_cycle_end_s));
  const std::vector<double> one = {0.01};
  s = SummarizeBrakeSlip(h, one);
  EXPECT_EQ(s.cycles, 1);
  EXPECT_NEAR(s.cycles_per_s, 1.0 / 0.02, 1e-9);
  EXPECT_TRUE(std::isnan(s.max_slip_after_first_cycle));
  EXPECT_TRUE(std::isnan(s.fraction_time_below_0_135_after_first_cycle));
  s = SummarizeBrakeSlip({}, one);  // an empty history: nothing
  EXPECT_EQ(s.max_slip, 0.0);
  EXPECT_TRUE(std::isnan(s.first_cycle_end_s));
}

}  // namespace
}  // namespace hotlap::fe
