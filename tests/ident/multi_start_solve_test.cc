// The rig fits' multi-start solve on a one-parameter problem with two minima: residuals x^2 - 1
// and 0.3 (x - 1) have their global minimum at x = 1 (cost 0) and a local one near x = -1. The
// starts decide which is found; the lowest cost is kept, iterations add up, bounds hold.

#include "hotlap/ident/multi_start_solve.h"

#include <vector>

#include <gtest/gtest.h>

namespace hotlap::ident::internal {
namespace {

struct TwoMinima {
  template <typename T>
  bool operator()(T const* const* x, T* r) const {
    r[0] = x[0][0] * x[0][0] - T(1.0);
    r[1] = T(0.3) * (x[0][0] - T(1.0));
    return true;
  }
};

MultiStartResult Solve(std::vector<double> starts, ParameterBounds bounds = {-3.0, 3.0}) {
  MultiStartOptions options;
  options.start_values = std::move(starts);
  options.start_indices = {0};
  const std::vector<double> x0 = {0.5};
  const std::vector<ParameterBounds> b = {bounds};
  return SolveMultiStart(
      x0, b,
      [](ceres::Problem& problem, double* x) {
        AddDynamicAutoDiffResidual(problem, new TwoMinima, 1, 2, x);
      },
      options);
}

TEST(MultiStartSolve, OneStartFindsTheNearestMinimum) {
  const MultiStartResult local = Solve({-1.2});
  ASSERT_EQ(local.x.size(), 1u);
  EXPECT_LT(local.x[0], -0.9);
  EXPECT_GT(local.final_cost, 0.1);
  EXPECT_TRUE(local.converged);
  EXPECT_GT(local.iterations, 0);
  EXPECT_FALSE(local.brief_report.empty());
}

TEST(MultiStartSolve, KeepsTheLowestCostAndSumsIterations) {
  const MultiStartResult a = Solve({-1.2});
  const MultiStartResult b = Solve({0.9});
  const MultiStartResult both = Solve({-1.2, 0.9});
  EXPECT_NEAR(b.x[0], 1.0, 1e-8);
  EXPECT_EQ(both.x, b.x);
  EXPECT_EQ(both.final_cost, b.final_cost);
  EXPECT_EQ(both.iterations, a.iterations + b.iterations);
  // The global minimum first: the later, worse start does not replace it.
  EXPECT_EQ(Solve({0.9, -1.2}).x, b.x);
}

TEST(MultiStartSolve, BoundsHoldAndStartsAreMovedInside) {
  EXPECT_NEAR(Solve({0.9}, {-3.0, 0.5}).x[0], 0.5, 1e-9);
  EXPECT_DOUBLE_EQ(StartInsideBounds(7.0, {0.0, 2.0}), 2.0 - 2e-6);
  EXPECT_DOUBLE_EQ(StartInsideBounds(-1.0, {0.0, 2.0}), 2e-6);
  EXPECT_EQ(StartInsideBounds(1.25, {0.0, 2.0}), 1.25);
}

}  // namespace
}  // namespace hotlap::ident::internal
