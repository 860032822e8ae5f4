// OptionName: the command line's spelling of an option (`--caution-speed-kph`, the unit's case
// kept) and Python's (the name as it is).

#include "hotlap/runs/option_name.h"

#include <gtest/gtest.h>

namespace hotlap::runs {
namespace {

TEST(OptionName, CommandLineSpellingHasDashesAndKeepsTheUnitsCase) {
  EXPECT_EQ(OptionName(NameStyle::kCommandLine, "caution_speed_kph"), "--caution-speed-kph");
  EXPECT_EQ(OptionName(NameStyle::kCommandLine, "ambient_temp_C"), "--ambient-temp-C");
  EXPECT_EQ(OptionName(NameStyle::kCommandLine, "laps"), "--laps");
}

TEST(OptionName, PythonSpellingIsTheKeywordItself) {
  EXPECT_EQ(OptionName(NameStyle::kPython, "caution_speed_kph"), "caution_speed_kph");
  EXPECT_EQ(OptionName(NameStyle::kPython, "laps"), "laps");
}

}  // namespace
}  // namespace hotlap::runs
