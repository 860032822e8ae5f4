#include "hotlap/common/data_path.h"

#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap {
namespace {

using test::Contains;
using test::InputErrorOf;

TEST(DataPathTest, TyreNamesResolveToDataTyresAndCarsTyres) {
  EXPECT_EQ(ResolveTyreFile("brush_example"), DataDir() / "tyres" / "brush_example.yaml");
  EXPECT_EQ(ResolveTyreFile("gen7/left"), DataDir() / "cars" / "gen7" / "tyres" / "left.tir");
  const std::filesystem::path path = test::SourcePath("data/tyres/unitire_example.yaml");
  EXPECT_EQ(ResolveTyreFile(path.string()), path);  // a path is taken as it is
}

TEST(DataPathTest, UnknownTyreListsTheBuiltIns) {
  const std::string message = InputErrorOf([] { ResolveTyreFile("gen7/middle"); });
  EXPECT_TRUE(Contains(message, "no tyre 'gen7/middle'")) << message;
  EXPECT_TRUE(Contains(message, "'brush_example'")) << message;
  EXPECT_TRUE(Contains(message, "'gen7/left'")) << message;
  EXPECT_TRUE(Contains(message, "'gen7/right'")) << message;
  // A car's thermal parameter files are not force models: not offered, not taken.
  EXPECT_FALSE(Contains(message, "gen7/fl")) << message;
  EXPECT_TRUE(Contains(InputErrorOf([] { ResolveTyreFile("gen7/fl"); }), "no tyre 'gen7/fl'"));
}

// Where the data folder is missing (an install whose data is not where the library looks), the
// message for a name says so and how to point at it (a bare "(built-in: (none))" before).
TEST(DataPathTest, AMissingDataFolderIsNamed) {
  const test::TempDir dir;
  const std::string missing = (dir.path() / "no_such_data").string();
  ASSERT_EQ(setenv("HOTLAP_DATA_DIR", missing.c_str(), 1), 0);
  const std::string car = InputErrorOf([] { ResolveCarFile("gen7"); });
  const std::string track = InputErrorOf([] { ResolveTrackFile("darlington"); });
  const std::string tyre = InputErrorOf([] { ResolveTyreFile("gen7/left"); });
  unsetenv("HOTLAP_DATA_DIR");
  for (const std::string& m : {car, track, tyre}) {
    EXPECT_TRUE(Contains(m, "there is no data folder at '" + missing + "'")) << m;
    EXPECT_TRUE(Contains(m, "set HOTLAP_DATA_DIR")) << m;
  }
  // With the data where it is, no such note.
  EXPECT_FALSE(Contains(InputErrorOf([] { ResolveCarFile("gen8"); }), "no data folder"));
}

}  // namespace
}  // namespace hotlap
