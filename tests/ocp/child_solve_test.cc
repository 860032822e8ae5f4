// Solves in a child process (ocp/child_solve.h): a child that answers, fails, crashes or is
// abandoned.

#include "hotlap/ocp/child_solve.h"

#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/ocp/solve_result_bytes.h"

namespace hotlap::ocp {
namespace {

// The second result the child sends: a few fields set.
SolveResult Second() {
  SolveResult r;
  r.status = SolveStatus::kIterationLimit;
  r.message = "the second";
  r.lambda = {2.0, -7.0};
  r.solve_seconds = 3.5;
  return r;
}

TEST(ChildSolveTest, ReturnsWhatTheChildSolved) {
  const pid_t parent = ::getpid();
  ChildSolve child([&] {
    SolveResult r;
    // Where it ran: another process.
    r.iterations = static_cast<int>(::getpid());
    r.x.assign(100000, 0.5);  // more than a pipe holds at once
    return std::vector<SolveResult>{r, Second()};
  });
  ASSERT_TRUE(child.started());
  const std::optional<std::vector<SolveResult>> r = child.Join();
  ASSERT_TRUE(r.has_value());
  ASSERT_EQ(r->size(), 2u);
  EXPECT_NE((*r)[0].iterations, static_cast<int>(parent));
  EXPECT_GT((*r)[0].iterations, 0);
  EXPECT_EQ((*r)[0].x, std::vector<double>(100000, 0.5));
  // Every field as sent (the encoding compares them all).
  EXPECT_EQ(EncodeSolveResults({(*r)[1]}), EncodeSolveResults({Second()}));
  EXPECT_FALSE(child.Join().has_value());  // once only
}

TEST(ChildSolveTest, AFailingOrCrashingChildGivesNoAnswer) {
  ChildSolve throws([]() -> std::vector<SolveResult> { throw std::runtime_error("no"); });
  EXPECT_FALSE(throws.Join().has_value());
  ChildSolve crashes([]() -> std::vector<SolveResult> { std::abort(); });
  EXPECT_FALSE(crashes.Join().has_value());
}

TEST(ChildSolveTest, AnAbandonedChildIsStopped) {
  const auto start = std::chrono::steady_clock::now();
  {
    ChildSolve slow([] {
      std::this_thread::sleep_for(std::chrono::seconds(60));
      return std::vector<SolveResult>{};
    });
    ASSERT_TRUE(slow.started());
  }  // destroyed without Join: killed, not waited for a minute
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(20));
}

}  // namespace
}  // namespace hotlap::ocp
