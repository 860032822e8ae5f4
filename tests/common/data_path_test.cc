#include "hotlap/common/data_path.h"

#include <filesystem>

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

}  // namespace
}  // namespace hotlap
