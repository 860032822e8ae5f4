// WriteFitReport on a small hand-made fit: the page and the channels CSV are written, the CSV
// holds the measured, modelled and residual columns, and a folder it cannot create is an
// InputError.

#include "hotlap/ident/fit_run_report.h"

#include <gtest/gtest.h>

#include "hotlap/common/csv.h"
#include "ident/fit_run_example.h"
#include "test_util.h"

namespace hotlap::ident {
namespace {

TEST(WriteFitReport, WritesThePageAndTheChannels) {
  test::TempDir dir;
  const auto written = WriteFitReport(testing::MakeExampleFitRun(), dir.path() / "report");
  ASSERT_EQ(written.size(), 2u);
  EXPECT_EQ(written[0], dir.path() / "report" / "index.html");
  EXPECT_EQ(written[1], dir.path() / "report" / "channels.csv");

  const std::string html = test::ReadTextFile(written[0]);
  for (const char* part : {"hotlap fit tyre: run1.csv", "Fitted parameters", "rr: thermal",
                           "correlation of the estimates", "rr tread temperature", "measured",
                           "rr: short log", "m = 2 parameters"}) {
    EXPECT_TRUE(test::Contains(html, part)) << part;
  }

  const CsvTable csv = ReadCsv(written[1]);
  EXPECT_EQ(csv.columns,
            (std::vector<std::string>{"time_s", "tread_temp_rr_C", "measured_tread_temp_rr_C",
                                      "residual_tread_temp_rr_C"}));
  EXPECT_EQ(csv.Column("residual_tread_temp_rr_C"), (std::vector<double>{0.5, 0.0, -0.5}));
  EXPECT_EQ(csv.metadata.front(), (std::pair<std::string, std::string>{"track", "darlington"}));
}

TEST(WriteFitReport, AFolderItCannotCreateIsAnInputError) {
  test::TempDir dir;
  EXPECT_TRUE(test::Contains(test::InputErrorOf([&] {
                               WriteFitReport(testing::MakeExampleFitRun(), dir.path() / "a" / "b");
                             }),
                             "cannot create it"));
}

}  // namespace
}  // namespace hotlap::ident
