// The FE tyre's ABS stop as an ensemble (abs/fe_abs_ensemble.h) on the very coarse, mass-scaled
// tyre of the other FE tests: the ensemble's figures at the full step and at half of it agree
// within each figure's equivalence margin (|difference of the means| + 2 combined standard
// errors, each standard error floored so that a mesh whose members do not diverge is not
// flaky), and the members do differ (the perturbation acts). It fails when a figure moves with
// the step beyond its margin (docs/fe-tyre.md, "ABS stop").

#include "hotlap/abs/fe_abs_ensemble.h"

#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "fe/coarse_fe_config.h"
#include "hotlap/fe/fe_config.h"
#include "test_util.h"

namespace hotlap::sim {
namespace {

// A figure, the margin its ensembles must agree within, and the floor on its standard error.
struct Margin {
  const char* key;
  double margin;
  double se_floor;
};
// The acceptance's margins for the slip (4 percentage points, 0.02); the others of the size a
// step change must not move them by on this tyre.
constexpr Margin kMargins[] = {
    {"fraction_below_0_135", 0.04, 0.005}, {"slip_p99", 0.02, 0.002},  {"slip_mean", 0.005, 0.0005},
    {"first_release_s", 0.010, 0.001},     {"cycles_per_s", 3.0, 0.3}, {"distance_m", 0.03, 0.003},
    {"mean_deceleration_mps2", 0.2, 0.02}};

FeAbsEnsembleResult RunEnsemble(const std::filesystem::path& file, double step_scale) {
  fe::FeConfig config = fe::LoadFeConfig(file);
  config.solver.time_step_scale = step_scale;
  const AbsConfig abs = LoadAbsConfig(config.abs_config);
  fe::TyreRun run(config);
  run.mutable_solver().set_threads(1);
  fe::StepHooks hooks;
  hooks.history_interval_s = config.history_interval_s;
  run.Inflate(hooks);
  run.Footprint(hooks);
  run.Roll(hooks);
  FeAbsEnsembleOptions o;
  o.members = 4;
  o.threads = 2;
  o.duration_s = 0.35;
  o.history_interval_s = config.history_interval_s;
  return RunFeAbsEnsemble(run, abs, o);
}

TEST(FeAbsEnsembleTest, FiguresAgreeAtTheFullAndHalfStepWithinTheirMargins) {
  const test::TempDir tmp;
  const auto file = test::WriteCoarseFeConfig(tmp.path() / "coarse.yaml");
  const FeAbsEnsembleResult full = RunEnsemble(file, 1.0);
  const FeAbsEnsembleResult half = RunEnsemble(file, 0.5);
  ASSERT_EQ(full.members.size(), 4u);
  // The members differ (by far less than any figure's margin): the perturbation acts.
  const EnsembleStat& distance = FindEnsembleStat(full, "distance_m");
  EXPECT_GT(distance.max - distance.min, 0.0);
  EXPECT_LT(distance.max - distance.min, 0.01);
  for (const Margin& m : kMargins) {
    const EnsembleStat& a = FindEnsembleStat(full, m.key);
    const EnsembleStat& b = FindEnsembleStat(half, m.key);
    // Every member has every figure: at least two control cycles in each stop.
    EXPECT_EQ(a.n, 4) << m.key;
    EXPECT_EQ(b.n, 4) << m.key;
    const double bound = EquivalenceBound(a, b, m.se_floor);
    EXPECT_LT(bound, m.margin) << m.key << " moved with the step: full " << a.mean << " +- " << a.standard_error
                               << ", half " << b.mean << " +- " << b.standard_error;
    std::printf("%s: full %.5g +- %.2g, half %.5g +- %.2g, bound %.3g of %.3g\n", m.key, a.mean,
                a.standard_error, b.mean, b.standard_error, bound, m.margin);
  }
  // The band follows the members: the mean lies between the smallest and largest slip.
  ASSERT_FALSE(full.time_s.empty());
  for (size_t k = 0; k < full.time_s.size(); k += 50) {
    EXPECT_LE(full.slip.min[k], full.slip.mean[k]);
    EXPECT_LE(full.slip.mean[k], full.slip.max[k]);
  }
}

}  // namespace
}  // namespace hotlap::sim
