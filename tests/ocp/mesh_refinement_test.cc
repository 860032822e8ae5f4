// The adaptive mesh's next mesh (ocp/mesh_refinement.h): splits where an interval is over its
// share of the tolerance, as many parts as the h^3 law asks, merges pairs far below it, and keeps
// the lap's ends.

#include "hotlap/ocp/mesh_refinement.h"

#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"

namespace hotlap::ocp {
namespace {

std::vector<double> Uniform(int intervals, double length) {
  std::vector<double> m;
  for (int k = 0; k <= intervals; ++k) m.push_back(length * k / intervals);
  return m;
}

TEST(RefineMeshTest, SplitsOverItsShareAndMergesFarBelow) {
  // Ten 10 m intervals of a 100 m lap, tolerance 1 ms: each interval's share is 0.1 ms.
  const std::vector<double> mesh = Uniform(10, 100.0);
  std::vector<double> e(10, 1e-7);  // far below: 0.1% of the share
  e[3] = 0.35e-3;                   // 3.5 shares: ceil(sqrt(3.5)) = 2 parts
  e[6] = -1.0e-3;                   // 10 shares (the sign does not matter): 4 parts
  MeshRefinementOptions o;
  o.tolerance_s = 1e-3;
  o.max_step_m = 20.0;
  o.max_ratio = 0.0;  // no grading
  const MeshRefinement r = RefineMesh(mesh, e, o);
  EXPECT_EQ(r.split, 2);
  EXPECT_EQ(r.over_at_min_step, 0);
  // Intervals 0-1 and 4-5 and 7-8 merge (two 10 m into 20 m); 2 and 9 stay alone (no partner
  // left that is not split).
  const std::vector<double> expected = {0, 20, 30, 35, 40, 60, 62.5, 65, 67.5, 70, 90, 100};
  ASSERT_EQ(r.mesh_m.size(), expected.size());
  for (size_t k = 0; k < expected.size(); ++k) EXPECT_NEAR(r.mesh_m[k], expected[k], 1e-12) << k;
  EXPECT_EQ(r.merged, 3);
}

// With grading, no interval is more than twice its neighbour: the split interval's neighbours
// are split too, and theirs, until the 2.5 m pieces have grown back to 10 m.
TEST(RefineMeshTest, GradesTheMeshAroundASplit) {
  const std::vector<double> mesh = Uniform(10, 100.0);
  std::vector<double> e(10, 0.05e-3);  // half of each share: nothing to do
  e[5] = 1.0e-3;                       // 10 shares: 4 parts of 2.5 m
  MeshRefinementOptions o;
  o.tolerance_s = 1e-3;
  const MeshRefinement r = RefineMesh(mesh, e, o);
  EXPECT_EQ(r.split, 1);
  EXPECT_EQ(r.graded, 2);  // intervals 4 and 6 into 2 parts (5 m); 3 and 7 stay: 10 <= 2 x 5
  EXPECT_EQ(r.merged, 0);
  for (size_t k = 1; k + 1 < r.mesh_m.size(); ++k) {
    const double before = r.mesh_m[k] - r.mesh_m[k - 1], after = r.mesh_m[k + 1] - r.mesh_m[k];
    EXPECT_LE(std::max(before, after), 2.0 * std::min(before, after) + 1e-9) << k;
  }
  EXPECT_EQ(r.mesh_m.size(), 11u + 3u + 2u);
}

TEST(RefineMeshTest, NoSplitBelowTheShortestInterval) {
  const std::vector<double> mesh = Uniform(20, 20.0);  // 1 m intervals
  std::vector<double> e(20, 0.0);
  e[5] = 1.0;  // far over, but 1 m cannot be split at a 0.75 m minimum
  MeshRefinementOptions o;
  o.tolerance_s = 1e-3;
  o.merge_fraction = 0.0;  // no merging
  const MeshRefinement r = RefineMesh(mesh, e, o);
  EXPECT_EQ(r.split, 0);
  EXPECT_EQ(r.over_at_min_step, 1);
  EXPECT_EQ(r.mesh_m, mesh);
}

TEST(RefineMeshTest, WithinTheToleranceEverywhereNothingChangesButMerges) {
  const std::vector<double> mesh = Uniform(4, 40.0);
  const std::vector<double> e(4, 0.2e-3);  // each at 0.8 of its 0.25 ms share
  MeshRefinementOptions o;
  o.tolerance_s = 1e-3;
  const MeshRefinement r = RefineMesh(mesh, e, o);
  EXPECT_EQ(r.split, 0);
  EXPECT_EQ(r.merged, 0);  // a union would be 8 times 0.2 ms, over its share
  EXPECT_EQ(r.mesh_m, mesh);
}

TEST(RefineMeshTest, RefusesMismatchedSizes) {
  MeshRefinementOptions o;
  EXPECT_THROW(RefineMesh(Uniform(4, 40.0), std::vector<double>(3, 0.0), o), InputError);
  o.tolerance_s = 0.0;
  EXPECT_THROW(RefineMesh(Uniform(4, 40.0), std::vector<double>(4, 0.0), o), InputError);
}

}  // namespace
}  // namespace hotlap::ocp
