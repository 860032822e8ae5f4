#include "hotlap/common/atomic_file.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap {
namespace {

namespace fs = std::filesystem;
using test::Contains;

// Every file in `dir` whose name is not `keep` (a temporary left behind would be one).
int OtherFiles(const fs::path& dir, const std::string& keep) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += e.path().filename() != keep;
  return n;
}

class AtomicFileTest : public ::testing::Test {
 protected:
  const test::TempDir tmp_;
  const fs::path path_ = tmp_.path() / "result.csv";
};

TEST_F(AtomicFileTest, ReplacesTheFileAndLeavesNoTemporary) {
  test::WriteTextFile(path_, "previous\n");
  WriteFileAtomically(path_, [](std::ostream& out) { out << "new\n"; });
  EXPECT_EQ(test::ReadTextFile(path_), "new\n");
  EXPECT_EQ(OtherFiles(tmp_.path(), "result.csv"), 0);
}

TEST_F(AtomicFileTest, AWriterThatThrowsLeavesThePreviousFile) {
  test::WriteTextFile(path_, "previous\n");
  EXPECT_THROW(WriteFileAtomically(path_,
                                   [](std::ostream& out) {
                                     out << "half a file";
                                     throw std::runtime_error("failed half way");
                                   }),
               std::runtime_error);
  EXPECT_EQ(test::ReadTextFile(path_), "previous\n");
  EXPECT_EQ(OtherFiles(tmp_.path(), "result.csv"), 0);
}

// The disk fills while writing: a file-size limit makes the system refuse the write as a full
// disk would (EFBIG instead of ENOSPC), in a child process so the limit stays there.
TEST_F(AtomicFileTest, AWriteTheSystemRefusesLeavesThePreviousFile) {
  test::WriteTextFile(path_, "previous\n");
  const fs::path message = tmp_.path() / "message.txt";
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{64 * 1024, 64 * 1024};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    int code = 1;
    try {
      WriteFileAtomically(path_, [](std::ostream& out) {
        for (int i = 0; i < 100000; ++i) out << "0123456789\n";  // 1.1 MB
      });
    } catch (const InputError& e) {
      test::WriteTextFile(message, e.what());
      code = 0;
    } catch (...) {
      code = 2;
    }
    ::_exit(code);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  ASSERT_EQ(WEXITSTATUS(status), 0) << "no InputError from a refused write";
  EXPECT_TRUE(Contains(test::ReadTextFile(message), "result.csv': write failed: File too large"))
      << test::ReadTextFile(message);
  EXPECT_EQ(test::ReadTextFile(path_), "previous\n");
  EXPECT_EQ(OtherFiles(tmp_.path(), "result.csv"), 1);  // message.txt only: no temporary
}

}  // namespace
}  // namespace hotlap
