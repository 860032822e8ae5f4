#pragma once
/// @file
/// Solves in a child process, for using a second core: Ipopt with MUMPS is not thread-safe, so
/// two solves at once need two processes. The child (fork) inherits the parent's memory (car,
/// track, warm-up), solves, and sends its SolveResults back through a pipe; the parent works on
/// meanwhile and collects them with Join().
///
///   ocp::ChildSolve child([&] { return std::vector<ocp::SolveResult>{...solve...}; });
///   ... the parent's own solve ...
///   std::optional<std::vector<ocp::SolveResult>> r = child.Join();  // nullopt: solve here
///
/// POSIX only. Output the child prints (progress lines) goes to the same terminal.

#include <functional>
#include <optional>
#include <vector>

#include "hotlap/ocp/ipopt_solve.h"

namespace hotlap::ocp {

/// A solve running in a child process.
class ChildSolve {
 public:
  /// Forks a child that runs `solve` and sends its results back. If the fork or the pipe fails
  /// there is no child, and Join() returns nullopt at once.
  explicit ChildSolve(const std::function<std::vector<SolveResult>()>& solve);
  /// Kills a child that was not joined (e.g. the parent's own solve threw).
  ~ChildSolve();
  ChildSolve(const ChildSolve&) = delete;
  ChildSolve& operator=(const ChildSolve&) = delete;

  /// Waits for the child and returns its results; nullopt if there was no child or it failed
  /// (threw, crashed, or sent no whole answer). Once only.
  std::optional<std::vector<SolveResult>> Join();

  bool started() const { return pid_ > 0; }

 private:
  int pid_ = -1;
  int read_fd_ = -1;
};

}  // namespace hotlap::ocp
