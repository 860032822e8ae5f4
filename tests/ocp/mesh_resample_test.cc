// A lap's point and multipliers taken onto a non-uniform mesh (ocp/mesh_resample.h): on uniform
// meshes the same as the node-count resampling of lap_problem.h, and exact on linear data.

#include "hotlap/ocp/mesh_resample.h"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"

namespace hotlap::ocp {
namespace {

LapLayout SmallLayout(int nodes) {
  LapLayout l;
  l.nodes = nodes;
  l.vars_per_node = 3;
  l.rows_per_node = 2;
  l.defects_per_interval = 2;
  l.closure_rows = 1;
  l.rate_blocks = 2;
  return l;
}

SolveResult RandomSolve(const LapLayout& l, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  SolveResult s;
  for (int i = 0; i < l.variables(); ++i) {
    s.x.push_back(u(rng));
    s.z_lower.push_back(u(rng));
    s.z_upper.push_back(u(rng));
  }
  for (int i = 0; i < l.rows(); ++i) s.lambda.push_back(u(rng));
  return s;
}

TEST(ResampleOnMeshTest, UniformMeshesAgreeWithTheNodeCountResampling) {
  const double length = 500.0;
  const LapLayout from = SmallLayout(11), to_uniform = SmallLayout(26);
  const SolveResult s = RandomSolve(from, 7);
  const std::vector<double> from_m = LayoutNodeDistances(from, length);
  const std::vector<double> to_m = LayoutNodeDistances(to_uniform, length);
  const std::vector<double> a = ResampleLapPoint(s.x, from.nodes, to_uniform.nodes);
  const std::vector<double> b = ResampleLapPointOnMesh(s.x, from_m, to_m);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-12) << i;
  const LapMultipliers ma = ResampleLapMultipliers(s, from, to_uniform);
  const LapMultipliers mb = ResampleLapMultipliersOnMesh(s, from, from_m, to_uniform, to_m);
  for (const auto& [x, y] :
       {std::pair{&ma.z_lower, &mb.z_lower}, std::pair{&ma.z_upper, &mb.z_upper},
        std::pair{&ma.lambda, &mb.lambda}}) {
    ASSERT_EQ(x->size(), y->size());
    for (size_t i = 0; i < x->size(); ++i) EXPECT_NEAR((*x)[i], (*y)[i], 1e-12) << i;
  }
}

TEST(ResampleOnMeshTest, LinearInDistanceIsKeptOnAnyMesh) {
  const std::vector<double> from_m = {0, 10, 15, 40, 41, 70, 100};
  const std::vector<double> to_m = {0, 3, 12, 14, 33, 50, 51, 52, 99, 100};
  std::vector<double> x;  // two variables a node: 2 + s and -s / 10
  for (double s : from_m) x.insert(x.end(), {2.0 + s, -0.1 * s});
  const std::vector<double> y = ResampleLapPointOnMesh(x, from_m, to_m);
  ASSERT_EQ(y.size(), 2 * to_m.size());
  for (size_t k = 0; k < to_m.size(); ++k) {
    EXPECT_NEAR(y[2 * k], 2.0 + to_m[k], 1e-12);
    EXPECT_NEAR(y[2 * k + 1], -0.1 * to_m[k], 1e-12);
  }
  EXPECT_THROW(ResampleLapPointOnMesh(std::vector<double>(5, 0.0), from_m, to_m), InputError);
}

// A bound's multiplier is a density times its node's share: a uniform density stays uniform
// and the multipliers' sum (the density times the lap) is kept.
TEST(ResampleOnMeshTest, NodeMultipliersKeepTheirDensity) {
  const std::vector<double> from_m = {0, 10, 20, 25, 30, 60, 100};
  const std::vector<double> to_m = {0, 1, 2, 50, 75, 100};
  LapLayout from = SmallLayout(static_cast<int>(from_m.size()));
  LapLayout to = from.WithMesh(to_m);
  SolveResult s = RandomSolve(from, 3);
  const double density = 0.02;
  for (size_t k = 0; k < from_m.size(); ++k) {
    const double share = 0.5 * ((k > 0 ? from_m[k] - from_m[k - 1] : 0.0) +
                                (k + 1 < from_m.size() ? from_m[k + 1] - from_m[k] : 0.0));
    for (int i = 0; i < from.vars_per_node; ++i)
      s.z_lower[k * from.vars_per_node + i] = density * share;
  }
  const LapMultipliers m = ResampleLapMultipliersOnMesh(s, from, from_m, to, to_m);
  double sum = 0.0;
  for (size_t k = 0; k < to_m.size(); ++k) sum += m.z_lower[k * to.vars_per_node];
  EXPECT_NEAR(sum, density * 100.0, 1e-12);
  EXPECT_NEAR(m.z_lower[3 * to.vars_per_node], density * 36.5, 1e-12);  // share (48 + 25) / 2
}

}  // namespace
}  // namespace hotlap::ocp
