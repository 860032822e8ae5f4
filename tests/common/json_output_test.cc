// JSON summaries: rounding to significant digits, null for a missing value, and the file written
// pretty-printed with a final newline, or an InputError naming the path.

#include "hotlap/common/json_output.h"

#include <cmath>
#include <limits>
#include <optional>

#include <gtest/gtest.h>

#include "test_util.h"

namespace hotlap {
namespace {

TEST(RoundSignificant, KeepsTheGivenDigits) {
  EXPECT_EQ(RoundSignificant(1.23456789012345), 1.23456789);
  EXPECT_EQ(RoundSignificant(-98765.4321, 4), -98770.0);
  EXPECT_EQ(RoundSignificant(0.000123456, 2), 0.00012);
  EXPECT_EQ(RoundSignificant(0.0), 0.0);
  EXPECT_TRUE(std::isinf(RoundSignificant(std::numeric_limits<double>::infinity())));
  EXPECT_TRUE(std::isnan(RoundSignificant(std::nan(""))));
}

TEST(JsonOrNull, RoundsAValueAndIsNullWithout) {
  EXPECT_EQ(JsonOrNull(2.0 / 3.0, 3), nlohmann::json(0.667));
  EXPECT_TRUE(JsonOrNull(std::nullopt).is_null());
}

TEST(WriteJsonFile, WritesTwoSpaceIndentedJsonWithAFinalNewline) {
  test::TempDir dir;
  const auto path = dir.path() / "s.json";
  WriteJsonFile(path, {{"b", 1}, {"a", {1.5, nullptr}}});
  EXPECT_EQ(test::ReadTextFile(path), "{\n  \"a\": [\n    1.5,\n    null\n  ],\n  \"b\": 1\n}\n");
}

TEST(WriteJsonFile, AMissingFolderIsAnInputErrorNamingThePath) {
  test::TempDir dir;
  const auto path = dir.path() / "no" / "s.json";
  EXPECT_TRUE(test::Contains(test::InputErrorOf([&] {
                               WriteJsonFile(path, {{"a", 1}});
                             }),
                             path.string()));
}

}  // namespace
}  // namespace hotlap
