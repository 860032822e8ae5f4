// ReadWholeFile: bytes come back unchanged (CR LF, NUL, no final newline), and a missing file, a
// folder or an empty path fail with InputError naming the file and the reason.

#include "hotlap/common/read_file.h"

#include <string>

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

}  // namespace
}  // namespace hotlap
