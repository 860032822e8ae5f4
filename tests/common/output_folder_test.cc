// CheckOutputFolder: a file in an existing folder passes; a missing folder or a path that is a
// folder is an InputError naming the option and the path.

#include "hotlap/common/output_folder.h"

#include <gtest/gtest.h>

#include "test_util.h"

namespace hotlap {
namespace {

TEST(CheckOutputFolder, PassesForAFileInAnExistingFolder) {
  test::TempDir dir;
  EXPECT_NO_THROW(CheckOutputFolder(dir.path() / "out.json", "--json"));
  EXPECT_NO_THROW(CheckOutputFolder("out.json", "--json"));  // the working folder
}

TEST(CheckOutputFolder, AMissingFolderOrAFolderIsAnInputError) {
  test::TempDir dir;
  const auto missing = dir.path() / "no" / "out.json";
  const std::string m = test::InputErrorOf([&] { CheckOutputFolder(missing, "--json"); });
  EXPECT_TRUE(test::Contains(m, "--json '" + missing.string() + "': folder '"));
  EXPECT_TRUE(test::Contains(m, "does not exist"));
  EXPECT_EQ(test::InputErrorOf([&] { CheckOutputFolder(dir.path(), "--out"); }),
            "--out '" + dir.path().string() + "' is a folder, not a file");
}

}  // namespace
}  // namespace hotlap
