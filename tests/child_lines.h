#pragma once
/// @file
/// A program run as a child process with one of its output streams read line by line as the
/// lines come: for the tests that kill a run at an event it reports (a checkpoint written), so
/// that where the kill lands is decided by what the program did, not by wall time.
///
///   test::ChildLines child("exec hotlap ... 2>/dev/null", STDOUT_FILENO);
///   while (std::optional<std::string> line = child.NextLine()) {
///     if (/* the event */) break;                 // blocks on the pipe: no polling, no sleep
///   }
///   const int status = child.KillAndWait();        // SIGKILL; what it wrote before is kept
///   child.text();                                  // every line it wrote

#include <fcntl.h>
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <optional>
#include <stdexcept>
#include <string>

namespace hotlap::test {

class ChildLines {
 public:
  /// Runs `command` with /bin/sh (start it with `exec` so that the child is the program, not a
  /// shell); its file descriptor `fd` (STDOUT_FILENO or STDERR_FILENO) goes to a pipe read here.
  ChildLines(const std::string& command, int fd) {
    int ends[2];
    if (::pipe2(ends, O_CLOEXEC) != 0) throw std::runtime_error("test: pipe failed");
    pid_ = ::fork();
    if (pid_ < 0) throw std::runtime_error("test: fork failed");
    if (pid_ == 0) {
      ::dup2(ends[1], fd);  // the duplicate has no O_CLOEXEC
      ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::close(ends[1]);
    read_ = ends[0];
  }
  ChildLines(const ChildLines&) = delete;
  ChildLines& operator=(const ChildLines&) = delete;
  ~ChildLines() {
    if (pid_ > 0) KillAndWait();
    if (read_ >= 0) ::close(read_);
  }

  /// The next whole line the child wrote (without its '\n'), waiting for it; nullopt once the
  /// stream has ended (the child closed it, exited or died) with no whole line left.
  std::optional<std::string> NextLine() {
    for (;;) {
      const size_t end = text_.find('\n', next_);
      if (end != std::string::npos) {
        std::string line = text_.substr(next_, end - next_);
        next_ = end + 1;
        return line;
      }
      if (!ReadSome()) return std::nullopt;
    }
  }

  /// SIGKILL to the child, then waits for it and reads what it had written. Returns its
  /// wait status (WIFSIGNALED and WTERMSIG SIGKILL where it was still running).
  int KillAndWait() {
    if (pid_ <= 0) return status_;
    ::kill(pid_, SIGKILL);
    while (::waitpid(pid_, &status_, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
    // What is in the pipe, without waiting: a process the child started may still hold it open.
    if (read_ >= 0) ::fcntl(read_, F_SETFL, ::fcntl(read_, F_GETFL) | O_NONBLOCK);
    while (ReadSome()) {
    }
    return status_;
  }

  /// Everything the child wrote on the stream so far.
  const std::string& text() const { return text_; }

 private:
  // Appends what the pipe has; false at its end.
  bool ReadSome() {
    if (read_ < 0) return false;
    char buffer[4096];
    for (;;) {
      const ssize_t n = ::read(read_, buffer, sizeof buffer);
      if (n > 0) {
        text_.append(buffer, static_cast<size_t>(n));
        return true;
      }
      if (n < 0 && errno == EINTR) continue;
      if (n < 0 && errno == EAGAIN) return false;  // drained (after KillAndWait)
      ::close(read_);
      read_ = -1;
      return false;
    }
  }

  pid_t pid_ = -1;
  int read_ = -1;
  int status_ = 0;
  std::string text_;
  size_t next_ = 0;
};

}  // namespace hotlap::test
