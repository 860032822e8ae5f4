// The FE tyre's ABS stop as a library call (sim::FeAbsStop), on a very coarse, mass-scaled copy
// of the shipped tyre: a stop checkpointed part way, restored into a new TyreRun and continued
// equals the stop run straight through bit for bit (histories, controller, end checkpoint); the
// checkpoint key sees the configuration files; a checkpoint of another configuration is refused.

#include "hotlap/abs/fe_abs_stop.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fe/coarse_fe_config.h"
#include "hotlap/common/error.h"
#include "hotlap/fe/fe_config.h"
#include "test_util.h"

namespace hotlap::sim {
namespace {

namespace fs = std::filesystem;

class FeAbsStopTest : public ::testing::Test {
 protected:
  // The shipped file with a coarse mesh, mass scaling and short steps (fe/coarse_fe_config.h).
  fs::path CoarseConfig(const std::string& name, const std::string& pressure = "220") {
    return test::WriteCoarseFeConfig(dir_ / name, pressure);
  }
  static fe::StepHooks Hooks(const fe::FeConfig& c) {
    fe::StepHooks hooks;
    hooks.history_interval_s = c.history_interval_s;
    return hooks;
  }
  static void RunUpToRoll(fe::TyreRun& run) {
    const fe::StepHooks hooks = Hooks(run.config());
    run.Inflate(hooks);
    run.Footprint(hooks);
    run.Roll(hooks);
  }
  static std::string Bytes(const fs::path& p) { return test::ReadTextFile(p); }

  const test::TempDir tmp_;
  const fs::path dir_ = tmp_.path();
};

TEST_F(FeAbsStopTest, RestartFromACheckpointEqualsTheStraightRunBitForBit) {
  fe::FeConfig config = fe::LoadFeConfig(CoarseConfig("coarse.yaml"));
  const AbsConfig abs = LoadAbsConfig(config.abs_config);
  const auto options = [&](double duration, double every, const fs::path& file,
                           const fe::CheckpointKey& key) {
    FeAbsStopOptions o;
    o.duration_s = duration;
    o.hooks = Hooks(config);
    o.checkpoint_every_s = every;
    o.checkpoint_file = file;
    o.checkpoint_key = key;
    o.summary = "{\"earlier\": 1}";
    return o;
  };
  // Straight through, 25 ms, a checkpoint at its end.
  fe::TyreRun straight(config);
  straight.mutable_solver().set_threads(1);
  RunUpToRoll(straight);
  const fe::CheckpointKey key = MakeFeCheckpointKey(straight);
  FeAbsStop stop(straight, abs);
  const FeAbsStopResult a = stop.Run(options(0.025, 1.0, dir_ / "a.bin", key));
  ASSERT_GT(a.brake.history.size(), 20u);
  EXPECT_GT(a.brake.max_brake_torque_Nm, 0.0);

  // Stopped at 12 ms (checkpoints at 5 and 10 ms and at the end), continued in a new run.
  fe::TyreRun first(config);
  first.mutable_solver().set_threads(1);
  RunUpToRoll(first);
  FeAbsStop(first, abs).Run(options(0.012, 0.005, dir_ / "b.bin", key));
  fe::TyreRun second(config);  // not stepped: the checkpoint brings every step's state
  second.mutable_solver().set_threads(1);
  FeAbsStop resumed(second, abs);
  const FeAbsCheckpointInfo info = resumed.Restore(dir_ / "b.bin", key);
  EXPECT_EQ(info.summary, "{\"earlier\": 1}");
  EXPECT_EQ(info.threads, 1u);
  EXPECT_EQ(info.kernel, second.solver().element_kernel());
  EXPECT_NEAR(second.solver().time() - second.brake_start_s(), 0.012, 1e-4);
  const FeAbsStopResult c = resumed.Run(options(0.025, 1.0, dir_ / "c.bin", key));

  EXPECT_TRUE(Bytes(dir_ / "a.bin") == Bytes(dir_ / "c.bin"));
  ASSERT_EQ(c.brake.history.size(), a.brake.history.size());
  for (size_t k = 0; k < a.brake.history.size(); ++k) {
    EXPECT_EQ(c.brake.history[k].rim_vx_mps, a.brake.history[k].rim_vx_mps) << k;
    EXPECT_EQ(c.brake.history[k].brake_torque_Nm, a.brake.history[k].brake_torque_Nm) << k;
    EXPECT_EQ(c.brake.history[k].energies.BalanceError(),
              a.brake.history[k].energies.BalanceError())
        << k;
  }
  EXPECT_EQ(c.cycle_starts_s, a.cycle_starts_s);
  EXPECT_EQ(c.brake.final_speed_mps, a.brake.final_speed_mps);
  EXPECT_EQ(c.brake.distance_m, a.brake.distance_m);
  EXPECT_EQ(c.cycles.cycles, a.cycles.cycles);
}

TEST_F(FeAbsStopTest, CheckpointOfAnotherConfigurationIsRefused) {
  const fe::FeConfig config = fe::LoadFeConfig(CoarseConfig("coarse.yaml"));
  const fe::FeConfig other = fe::LoadFeConfig(CoarseConfig("other.yaml", "200"));
  const AbsConfig abs = LoadAbsConfig(config.abs_config);
  fe::TyreRun run(config), run_other(other);
  const fe::CheckpointKey key = MakeFeCheckpointKey(run);
  EXPECT_EQ(key.nodes, run.tyre().mesh.nodes.size());
  EXPECT_EQ(key.mesh_hash, MakeFeCheckpointKey(run_other).mesh_hash);
  EXPECT_NE(key.config_hash, MakeFeCheckpointKey(run_other).config_hash);
  RunUpToRoll(run);
  FeAbsStopOptions o;
  o.duration_s = 0.001;
  o.hooks = Hooks(config);
  o.checkpoint_every_s = 1.0;
  o.checkpoint_file = dir_ / "a.bin";
  o.checkpoint_key = key;
  FeAbsStop(run, abs).Run(o);
  FeAbsStop stop(run_other, abs);
  try {
    stop.Restore(dir_ / "a.bin", MakeFeCheckpointKey(run_other));
    ADD_FAILURE() << "a checkpoint of another configuration was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("written for another configuration"), std::string::npos)
        << e.what();
  }
}

// The stop's slip history, brake-step time from the first row, interpolated at time t.
double SlipAt(const std::vector<fe::HistoryRow>& h, double t) {
  const double t0 = h.front().time_s;
  for (size_t k = 1; k < h.size(); ++k) {
    const double a = h[k - 1].time_s - t0, b = h[k].time_s - t0;
    if (t <= b) return h[k - 1].slip + (h[k].slip - h[k - 1].slip) * (t - a) / (b - a);
  }
  return h.back().slip;
}

// Issue 27: the ABS stop must not move with the time step. The coarse tyre braked for
// kDuration at the stable step and at half of it (SolverOptions::time_step_scale, the road's
// penalty springs unchanged): the slip histories agree within kSlipRms (RMS over the stop, on a
// 1 ms grid) and the control cycles are as many and begin within 10 ms. Measured (2026-11-26,
// docs/validation/fe-tyre.md "ABS stop"): RMS 0.0026 with 7 cycles at the same ticks; the bound is
// about twice that. On finer meshes the event after the third cycle moves with any perturbation,
// round-off included, so this coarse mesh, whose slip stays small, is the one that can be held
// to a tight bound over several cycles.
TEST_F(FeAbsStopTest, HalvingTheStepKeepsTheSlipHistoryAndTheCycles) {
  constexpr double kDuration = 0.5, kSlipRms = 0.005, kCycleShift = 0.010;
  const auto run = [&](double scale) {
    fe::FeConfig config = fe::LoadFeConfig(CoarseConfig("coarse.yaml"));
    config.solver.time_step_scale = scale;
    const AbsConfig abs = LoadAbsConfig(config.abs_config);
    fe::TyreRun tyre(config);
    tyre.mutable_solver().set_threads(1);
    RunUpToRoll(tyre);
    FeAbsStopOptions o;
    o.duration_s = kDuration;
    o.hooks = Hooks(config);
    FeAbsStopResult r = FeAbsStop(tyre, abs).Run(o);
    for (double& c : r.cycle_starts_s) c -= r.brake.history.front().time_s;
    return std::pair{r, tyre.solver().time_step()};
  };
  const auto [full, dt_full] = run(1.0);
  const auto [half, dt_half] = run(0.5);
  EXPECT_NEAR(dt_half, 0.5 * dt_full, 1e-12 * dt_full);
  double sum = 0.0, peak = 0.0;
  int n = 0;
  for (double t = 0.0; t <= kDuration; t += 1e-3, ++n) {
    const double d = SlipAt(full.brake.history, t) - SlipAt(half.brake.history, t);
    sum += d * d;
    peak = std::max(peak, std::abs(SlipAt(full.brake.history, t)));
  }
  const double rms = std::sqrt(sum / n);
  EXPECT_GT(peak, 0.005);  // the brake acted: there is a slip to compare
  EXPECT_LT(rms, kSlipRms) << "largest slip " << peak;
  ASSERT_EQ(full.cycle_starts_s.size(), half.cycle_starts_s.size());
  for (size_t k = 0; k < full.cycle_starts_s.size(); ++k) {
    EXPECT_NEAR(full.cycle_starts_s[k], half.cycle_starts_s[k], kCycleShift) << k;
  }
  std::printf("slip RMS difference %.4g (largest slip %.4g), cycles %zu\n", rms, peak,
              full.cycle_starts_s.size());
}

}  // namespace
}  // namespace hotlap::sim
