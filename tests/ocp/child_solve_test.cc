// Solves in a child process (ocp/child_solve.h): the results' encoding, and a child that answers,
// fails, crashes or is abandoned.

#include "hotlap/ocp/child_solve.h"

#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"

namespace hotlap::ocp {
namespace {

SolveResult Example(double seed) {
  SolveResult r;
  r.status = SolveStatus::kAcceptable;
  r.message = "converged to Ipopt's acceptable (looser) tolerance only";
  r.x = {seed, -1.5, 1e300, 0.0};
  r.z_lower = {0.0, 2.0, 0.0, 0.0};
  r.z_upper = {1e-9, 0.0, 0.0, 3.0};
  r.lambda = {seed * 2.0, -7.0};
  r.objective = 29.66;
  r.iterations = 47;
  r.regularized_iterations = 28;
  r.primal_infeasibility = 1e-9;
  r.dual_infeasibility = 2e-8;
  r.solve_seconds = 28.1;
  return r;
}

void ExpectSame(const SolveResult& a, const SolveResult& b) {
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.message, b.message);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.z_lower, b.z_lower);
  EXPECT_EQ(a.z_upper, b.z_upper);
  EXPECT_EQ(a.lambda, b.lambda);
  EXPECT_EQ(a.objective, b.objective);
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_EQ(a.regularized_iterations, b.regularized_iterations);
  EXPECT_EQ(a.primal_infeasibility, b.primal_infeasibility);
  EXPECT_EQ(a.dual_infeasibility, b.dual_infeasibility);
  EXPECT_EQ(a.solve_seconds, b.solve_seconds);
}

TEST(SolveResultEncodingTest, RoundTripsEveryField) {
  const std::vector<SolveResult> in = {Example(1.0), SolveResult{}, Example(-3.25)};
  const std::vector<SolveResult> out = DecodeSolveResults(EncodeSolveResults(in));
  ASSERT_EQ(out.size(), in.size());
  for (size_t i = 0; i < in.size(); ++i) ExpectSame(out[i], in[i]);
  EXPECT_TRUE(DecodeSolveResults(EncodeSolveResults({})).empty());
}

TEST(SolveResultEncodingTest, RefusesBytesThatAreNotAWholeEncoding) {
  const std::string bytes = EncodeSolveResults({Example(1.0)});
  EXPECT_THROW(DecodeSolveResults(bytes.substr(0, bytes.size() - 1)), InputError);
  EXPECT_THROW(DecodeSolveResults(bytes + "x"), InputError);
  EXPECT_THROW(DecodeSolveResults(""), InputError);
  std::string other = bytes;
  other[0] ^= 1;  // not the magic
  EXPECT_THROW(DecodeSolveResults(other), InputError);
}

TEST(ChildSolveTest, ReturnsWhatTheChildSolved) {
  const pid_t parent = ::getpid();
  ChildSolve child([&] {
    SolveResult r = Example(1.0);
    // Where it ran: another process.
    r.iterations = static_cast<int>(::getpid());
    r.x.assign(100000, 0.5);  // more than a pipe holds at once
    return std::vector<SolveResult>{r, Example(2.0)};
  });
  ASSERT_TRUE(child.started());
  const std::optional<std::vector<SolveResult>> r = child.Join();
  ASSERT_TRUE(r.has_value());
  ASSERT_EQ(r->size(), 2u);
  EXPECT_NE((*r)[0].iterations, static_cast<int>(parent));
  EXPECT_GT((*r)[0].iterations, 0);
  EXPECT_EQ((*r)[0].x, std::vector<double>(100000, 0.5));
  ExpectSame((*r)[1], Example(2.0));
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
