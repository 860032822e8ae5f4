// ReadWholeFile: bytes come back unchanged (CR LF, NUL, no final newline), and a missing file, a
// folder or an empty path fail with InputError naming the file and the reason.

#include "hotlap/common/read_file.h"

#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap {
namespace {

using test::Contains;

TEST(ReadWholeFile, ReturnsTheBytesUnchanged) {
  test::TempDir dir;
  const std::string bytes = std::string("a,b\r\n1,2\r\n") + '\0' + "\xEF\xBB\xBF" + "tail";
  EXPECT_EQ(ReadWholeFile(dir.Write("f.csv", bytes)), bytes);
  EXPECT_EQ(ReadWholeFile(dir.Write("empty.txt", "")), "");
}

TEST(ReadWholeFile, ErrorsNameTheFileAndTheReason) {
  test::TempDir dir;
  const auto expect = [](const std::filesystem::path& path, const std::string& reason) {
    try {
      ReadWholeFile(path);
      ADD_FAILURE() << "no error for " << path;
    } catch (const InputError& e) {
      EXPECT_TRUE(Contains(e.what(), "cannot read '" + path.string() + "': " + reason));
    }
  };
  expect(dir.path() / "missing.csv", "No such file or directory");
  expect(dir.path(), "it is a folder, not a file");
}

TEST(TextLinesTest, DropsTheByteOrderMarkAndCarriageReturnsAndNumbersEveryLine) {
  const std::vector<std::string_view> lines = TextLines(
      "\xEF\xBB\xBF"
      "a,b\r\n\r\n  c \nlast");
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "a,b");
  EXPECT_EQ(lines[1], "");      // blank lines keep their place: line 2
  EXPECT_EQ(lines[2], "  c ");  // nothing else trimmed
  EXPECT_EQ(lines[3], "last");  // no final line end
  EXPECT_EQ(TextLines("x\n").size(), 1u);
  EXPECT_TRUE(TextLines("").empty());
  EXPECT_EQ(TextLines("a\rb\n")[0], "a\rb");  // a lone CR inside a line stays
}

}  // namespace
}  // namespace hotlap
