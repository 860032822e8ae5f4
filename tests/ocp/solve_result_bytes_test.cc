// SolveResults as bytes and back (ocp/solve_result_bytes.h): every field round-trips, and bytes
// that are not a whole encoding are refused.

#include "hotlap/ocp/solve_result_bytes.h"

#include <string>
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

}  // namespace
}  // namespace hotlap::ocp
