// Reading measured channels for the fits: dead, stuck, sparse and implausible data; trapezoid
// weights; the small parsers of the fit options.

#include "hotlap/ident/fit_log.h"

#include <cmath>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap::ident {
namespace {

// A 100-row log with time and one tread-temperature column made by `cell(k)` ("" = empty).
Telemetry Log(const test::TempDir& dir, const std::function<std::string(int)>& cell) {
  std::string text = "time_s,tread_temp_fl_C\n";
  for (int k = 0; k < 100; ++k) text += std::to_string(0.02 * k) + "," + cell(k) + "\n";
  return Telemetry::Read(dir.Write("log.csv", text));
}

LoggedChannel Read(const Telemetry& log) {
  return ReadLoggedChannel(log, "tread_temp", Corner::kFrontLeft, 223.15, 573.15, 0.01);
}

TEST(FitLogTest, GoodChannelIsUsableWithItsGaps) {
  const test::TempDir dir;
  const LoggedChannel ch =
      Read(Log(dir, [](int k) { return k % 10 == 3 ? std::string() : std::to_string(60 + k); }));
  EXPECT_TRUE(ch.usable);
  EXPECT_EQ(ch.column, "tread_temp_fl_C");
  EXPECT_EQ(ch.empty_cells, 10);
  EXPECT_EQ(ch.Count(), 90);
  EXPECT_TRUE(std::isnan(ch.values[3]));
  EXPECT_DOUBLE_EQ(ch.values[4], 64 + 273.15);
  EXPECT_EQ(DescribeChannelProblems(ch), "");
}

TEST(FitLogTest, DeadStuckSparseAndMissingChannelsAreExcluded) {
  const test::TempDir dir;
  const LoggedChannel constant = Read(Log(dir, [](int) { return std::string("61.5"); }));
  EXPECT_FALSE(constant.usable);
  EXPECT_TRUE(test::Contains(DescribeChannelProblems(constant),
                             "tread_temp_fl_C: excluded from the fit: constant at 334.65"));
  EXPECT_TRUE(std::isnan(constant.values[0]));  // nothing of it is fitted
  const LoggedChannel stuck =
      Read(Log(dir, [](int k) { return k < 60 ? std::string("70") : std::to_string(70 + k); }));
  EXPECT_FALSE(stuck.usable);
  EXPECT_TRUE(test::Contains(stuck.problem, "stuck: 60 of its 100 values"));
  const LoggedChannel sparse =
      Read(Log(dir, [](int k) { return k < 5 ? std::to_string(60 + k) : std::string(); }));
  EXPECT_FALSE(sparse.usable);
  EXPECT_TRUE(test::Contains(sparse.problem, "only 5 usable values of 100"));
  const Telemetry log = Log(dir, [](int k) { return std::to_string(60 + k); });
  const LoggedChannel missing =
      ReadLoggedChannel(log, "carcass_temp", Corner::kFrontLeft, 0, 1e4, 0.01);
  EXPECT_FALSE(missing.usable);
  EXPECT_EQ(missing.problem, "the log has no such column");
}

TEST(FitLogTest, ImplausibleValuesAreDroppedAndCounted) {
  const test::TempDir dir;
  const LoggedChannel ch = Read(Log(dir, [](int k) {
    return k % 20 == 0 ? std::string("-273.15") : std::to_string(60 + 0.5 * k);  // error code
  }));
  EXPECT_TRUE(ch.usable);
  EXPECT_EQ(ch.implausible, 5);
  EXPECT_TRUE(std::isnan(ch.values[20]));
  EXPECT_TRUE(test::Contains(DescribeChannelProblems(ch), "5 implausible values dropped"));
}

TEST(FitLogTest, TrapezoidWeightsHaveMeanOneAndCapGaps) {
  const std::vector<double> uniform = {0.0, 0.1, 0.2, 0.3, 0.4};
  const std::vector<double> w = TrapezoidWeights(uniform);
  EXPECT_NEAR(w[0], 0.625, 1e-12);  // half weight at the ends, scaled to mean 1
  EXPECT_NEAR(w[2], 1.25, 1e-12);
  // A 10 s gap counts as two median intervals, not 10 s.
  const std::vector<double> gap = {0.0, 0.1, 0.2, 10.2, 10.3, 10.4};
  const std::vector<double> g = TrapezoidWeights(gap);
  EXPECT_NEAR(g[2] / g[1], 1.5, 1e-12);
  double sum = 0.0;
  for (double x : g) sum += x;
  EXPECT_NEAR(sum, 6.0, 1e-12);
}

TEST(FitLogTest, RobustFirstValueAndSmoothing) {
  const std::vector<double> t = {0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 2.0};
  const double nan = std::nan("");
  EXPECT_DOUBLE_EQ(RobustFirstValue(t, std::vector<double>{nan, 90.0, 10.0, 11.0, 12.0, 13.0, 14}),
                   12.0);  // median of 90, 10, 11, 12, 13: the spike does not matter
  EXPECT_TRUE(std::isnan(RobustFirstValue(t, std::vector<double>(7, nan))));
  const std::vector<double> s = SmoothedForGuess(std::vector<double>{1, 2, nan, 4, 50, 6, 7});
  EXPECT_DOUBLE_EQ(s[2], 3.0);  // filled
  EXPECT_DOUBLE_EQ(s[4], 6.0);  // spike removed by the running median
}

TEST(FitLogTest, ParsesCornerOptions) {
  EXPECT_EQ(ParseCornerList("all", "--corners").size(), 4u);
  EXPECT_EQ(ParseCornerList("rr, fl", "--corners"),
            (std::vector<Corner>{Corner::kFrontLeft, Corner::kRearRight}));
  EXPECT_THROW(ParseCornerList("fl,xx", "--corners"), InputError);
  const auto v = ParseCornerValues("fl=0.02, rr=0.033", "--wear-per-lap-mm");
  EXPECT_DOUBLE_EQ(v.at(Corner::kRearRight), 0.033);
  EXPECT_EQ(v.size(), 2u);
  EXPECT_THROW(ParseCornerValues("fl:0.02", "--wear-per-lap-mm"), InputError);
  EXPECT_THROW(ParseCornerValues("fl=abc", "--wear-per-lap-mm"), InputError);
}

}  // namespace
}  // namespace hotlap::ident
