// A folder's fingerprint (common/folder_fingerprint.h): every file below it by relative path and
// the hash of its bytes, so that a change to any file, a file added or one moved tells it apart.

#include "hotlap/common/folder_fingerprint.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "hotlap/common/fnv1a.h"
#include "test_util.h"

namespace hotlap {
namespace {

namespace fs = std::filesystem;

TEST(FolderFingerprintTest, NamesEveryFileByPathAndBytes) {
  test::TempDir dir;
  test::WriteTextFile(dir.path() / "car.yaml", "name: a\n");
  test::WriteTextFile(dir.path() / "tyres/t.yaml", "x: 1\n");
  const std::string key = FolderFingerprint(dir.path());
  EXPECT_EQ(key, fmt::format(" car.yaml {:016x}; tyres/t.yaml {:016x};", Fnv1a64("name: a\n"),
                             Fnv1a64("x: 1\n")));
  // Another byte, another file, the same file moved: another key.
  test::WriteTextFile(dir.path() / "tyres/t.yaml", "x: 2\n");
  const std::string changed = FolderFingerprint(dir.path());
  EXPECT_NE(changed, key);
  fs::create_directories(dir.path() / "brakes");
  fs::rename(dir.path() / "tyres/t.yaml", dir.path() / "brakes/t.yaml");
  EXPECT_NE(FolderFingerprint(dir.path()), changed);
  EXPECT_EQ(FolderFingerprint(dir.path() / "none"), "");
  EXPECT_EQ(FileFingerprint(dir.path() / "car.yaml"),
            fmt::format(" car.yaml {:016x};", Fnv1a64("name: a\n")));
  EXPECT_EQ(FileFingerprint(dir.path() / "gone.yaml"), " gone.yaml unreadable;");
}

}  // namespace
}  // namespace hotlap
