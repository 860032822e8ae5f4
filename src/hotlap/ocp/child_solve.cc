#include "hotlap/ocp/child_solve.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>

#include "hotlap/common/error.h"
#include "hotlap/ocp/solve_result_bytes.h"

namespace hotlap::ocp {

namespace {

bool WriteAll(int fd, const std::string& bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

}  // namespace

ChildSolve::ChildSolve(const std::function<std::vector<SolveResult>()>& solve) {
  int fds[2];
  if (::pipe(fds) != 0) return;
  std::fflush(nullptr);  // nothing buffered twice
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return;
  }
  if (pid == 0) {
    // The child: solve, send, and leave without running the parent's exit handlers.
    ::close(fds[0]);
    int code = 0;
    try {
      code = WriteAll(fds[1], EncodeSolveResults(solve())) ? 0 : 2;
    } catch (...) {
      code = 1;
    }
    std::fflush(nullptr);
    ::close(fds[1]);
    ::_exit(code);
  }
  ::close(fds[1]);
  pid_ = pid;
  read_fd_ = fds[0];
}

ChildSolve::~ChildSolve() {
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
  }
  if (read_fd_ >= 0) ::close(read_fd_);
}

std::optional<std::vector<SolveResult>> ChildSolve::Join() {
  if (pid_ <= 0) return std::nullopt;
  std::string bytes;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(read_fd_, buffer, sizeof(buffer));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    bytes.append(buffer, static_cast<size_t>(n));
  }
  ::close(read_fd_);
  read_fd_ = -1;
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return std::nullopt;
  try {
    return DecodeSolveResults(bytes);
  } catch (const InputError&) {
    return std::nullopt;
  }
}

}  // namespace hotlap::ocp
