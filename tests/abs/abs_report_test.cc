// The HTML report of `hotlap abs` on a hand-made event: written, with the summary rows and the
// histories' series; the controller's chart only with ABS; the scenarios' sections with them.

#include "hotlap/abs/abs_report.h"

#include <gtest/gtest.h>

#include "abs/abs_example.h"
#include "test_util.h"

namespace hotlap::sim {
namespace {

TEST(WriteAbsReport, WritesTheSummaryAndTheHistories) {
  test::TempDir dir;
  const AbsConfig config = testing::MakeExampleAbsConfig();
  AbsEvent event = testing::MakeExampleAbsEvent();
  const AbsRunResult run = testing::MakeExampleAbsRun();
  const AbsMetrics m = testing::MakeExampleAbsMetrics();
  AbsReportInputs in{.config = &config,
                     .event = &event,
                     .run = &run,
                     .metrics = &m,
                     .summary = {{"stopped", "yes, at 1.500 s"}},
                     .csv = "out/abs.csv"};
  const auto path = dir.path() / "abs_report.html";
  WriteAbsReport(in, path);
  const std::string html = test::ReadTextFile(path);
  for (const char* part : {"hotlap abs: example on", "yes, at 1.500 s", "out/abs.csv",
                           "wheel cylinder", "Braking slip", "Controller state", "calliper"}) {
    EXPECT_TRUE(test::Contains(html, part)) << part;
  }
  EXPECT_FALSE(test::Contains(html, "Scenarios"));

  event.control = AbsControl::kDriverOnly;
  std::vector<AbsComparisonRun> comparison(2);
  comparison[0].surface = comparison[1].surface = "wet";
  comparison[0].run = comparison[1].run = run;
  AbsStopSeries series;
  series.stops = {m};
  series.stop_start_s = {0.0};
  series.time = run.history.time;
  series.disc_temp = run.history.disc_temp;
  series.calliper_temp = run.history.calliper_temp;
  in.comparison = &comparison;
  in.series = &series;
  WriteAbsReport(in, path);
  const std::string again = test::ReadTextFile(path);
  EXPECT_TRUE(test::Contains(again, "without ABS"));
  EXPECT_FALSE(test::Contains(again, "Controller state"));
  EXPECT_TRUE(test::Contains(again, "Scenarios: ABS against locked wheels"));
  EXPECT_TRUE(test::Contains(again, "wet locked"));
}

TEST(WriteAbsReport, AMissingFolderIsAnInputError) {
  test::TempDir dir;
  const AbsConfig config = testing::MakeExampleAbsConfig();
  const AbsEvent event = testing::MakeExampleAbsEvent();
  const AbsRunResult run = testing::MakeExampleAbsRun();
  const AbsMetrics m = testing::MakeExampleAbsMetrics();
  const AbsReportInputs in{.config = &config,
                           .event = &event,
                           .run = &run,
                           .metrics = &m,
                           .summary = {},
                           .comparison = nullptr,
                           .series = nullptr,
                           .csv = ""};
  EXPECT_TRUE(test::Contains(
      test::InputErrorOf([&] { WriteAbsReport(in, dir.path() / "no" / "r.html"); }), "r.html"));
}

}  // namespace
}  // namespace hotlap::sim
