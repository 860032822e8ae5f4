// SampleSource: a hotlap CSV read a line at a time and the same log read whole (one lap asked)
// give the same samples; a MoTeC export is read whole; standard input is named "stdin" and takes
// no lap or channel map; a file that cannot be opened says so.

#include "hotlap/observe/sample_source.h"

#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap::observe {
namespace {

int CountSamples(SampleSource& source) {
  int n = 0;
  while (source.Next()) ++n;
  return n;
}

TEST(SampleSource, LineByLineAndWholeLogAgree) {
  const std::string path = test::SourcePath("data/telemetry/darlington_example.csv").string();
  SampleSource by_line(path, {}, {});
  EXPECT_EQ(by_line.name(), path);
  SampleSource whole(path, {.channel_map = test::SourcePath("data/motec_channels.yaml")}, {});
  for (int i = 0; i < 50; ++i) {
    const auto a = by_line.Next(), b = whole.Next();
    ASSERT_TRUE(a && b);
    EXPECT_EQ(a->time, b->time);
    EXPECT_EQ(by_line.line(), whole.line());
  }
  EXPECT_EQ(CountSamples(by_line), CountSamples(whole));
}

TEST(SampleSource, AMotecExportIsReadWhole) {
  SampleSource source(test::SourcePath("tests/data/motec/darlington_i2.csv").string(), {}, {});
  EXPECT_GT(CountSamples(source), 100);
}

TEST(SampleSource, StandardInputTakesNoLapAndAMissingFileIsNamed) {
  EXPECT_EQ(SampleSource("-", {}, {}).name(), "stdin");
  EXPECT_TRUE(test::Contains(test::InputErrorOf([] { SampleSource("-", {.lap = 1}, {}); }),
                             "--lap and --channel-map need a log file"));
  EXPECT_EQ(test::InputErrorOf([] { SampleSource("/nonexistent/log.csv", {}, {}); }),
            "cannot read '/nonexistent/log.csv'");
}

}  // namespace
}  // namespace hotlap::observe
